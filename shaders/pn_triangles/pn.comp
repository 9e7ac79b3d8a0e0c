#version 460
// Curved PN triangles on the compute path: pn.tesc's and pn.tese's bodies (pn_build.glsl,
// pn_evaluate.glsl) run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#define TB_SURFACE_BUILD
#include "pn_surface.glsl"

// What pn.tesc hands pn.tese.
struct TbPnSurface {
  vec3 b[10];  // corners 0..2, edge e end k at 3 + 2e + k, centre 9
  vec3 n[6];   // corner normals 0..2, edge normals 3..5
  uvec3 perm;  // canonical label -> gl_TessCoord component
};

#define TB_BUILD_FUNCTION TbPnSurface tbBuildPn()
#define TB_BUILD_PROLOGUE       \
  vec3 tb_pn_b[10], tb_pn_n[6]; \
  uvec3 tb_pn_perm;
#define TB_BUILD_EPILOGUE return TbPnSurface(tb_pn_b, tb_pn_n, tb_pn_perm);
#include "pn_build.glsl"

#define TB_EVALUATE_FUNCTION tbEvaluatePn(TbPnSurface s, vec3 tb_tess_coord)
#define TB_EVALUATE_PROLOGUE                      \
  const vec3 tb_pn_b[10] = s.b, tb_pn_n[6] = s.n; \
  const uvec3 tb_pn_perm = s.perm;
#define TB_TESS_COORD tb_tess_coord
#include "pn_evaluate.glsl"

#define TB_SURFACE TbPnSurface
#define TB_BUILD_SURFACE() tbBuildPn()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluatePn(s, coord)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
