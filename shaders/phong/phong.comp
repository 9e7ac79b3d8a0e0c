#version 460
// Phong tessellation on the compute path: phong.tesc's and phong.tese's bodies
// (phong_build.glsl, phong_evaluate.glsl) run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#define TB_SURFACE_BUILD
#define TB_SURFACE_EVALUATE
#include "phong_surface.glsl"

// What phong.tesc hands phong.tese.
struct TbPhongSurface {
  vec3 p[3];
  vec3 n[3];
  vec3 edge_n[6];
  uvec3 perm;
};

#define TB_BUILD_FUNCTION TbPhongSurface tbBuildPhong()
#define TB_BUILD_PROLOGUE                                \
  vec3 tb_phong_p[3], tb_phong_n[3], tb_phong_edge_n[6]; \
  uvec3 tb_phong_perm;
#define TB_BUILD_EPILOGUE \
  return TbPhongSurface(tb_phong_p, tb_phong_n, tb_phong_edge_n, tb_phong_perm);
#include "phong_build.glsl"

#define TB_EVALUATE_FUNCTION tbEvaluatePhong(TbPhongSurface s, vec3 tb_tess_coord)
#define TB_EVALUATE_PROLOGUE                                                           \
  const vec3 tb_phong_p[3] = s.p, tb_phong_n[3] = s.n, tb_phong_edge_n[6] = s.edge_n; \
  const uvec3 tb_phong_perm = s.perm;
#define TB_TESS_COORD tb_tess_coord
#include "phong_evaluate.glsl"

#define TB_SURFACE TbPhongSurface
#define TB_BUILD_SURFACE() tbBuildPhong()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluatePhong(s, coord)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
