#version 460
// gregory_acc's triangles on the compute path: gregory_tri.tesc's per-point stencil sum
// (gregory_stencil.glsl) for each of the 15 points and gregory_tri.tese's body
// (gregory_tri_evaluate.glsl), run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#include "gregory_stencil.glsl"

vec3 control_point[15];  // the TES's input: the evaluated patch's points
#define TB_GREGORY_TRIANGLE
#include "gregory_surface.glsl"

struct TbGregoryTriSurface {
  vec3 cp[15];
};

TbGregoryTriSurface tbBuildGregoryTriangle() {
  TbGregoryTriSurface s;
  for (uint i = 0u; i < 15u; ++i) s.cp[i] = tbGregoryControlPoint(tbPatchIndex(), i, 15u);
  return s;
}

#define TB_EVALUATE_FUNCTION tbEvaluateGregoryTriangle(TbGregoryTriSurface s, vec3 tb_tess_coord)
#define TB_EVALUATE_PROLOGUE control_point = s.cp;
#define TB_TESS_COORD tb_tess_coord
#include "gregory_tri_evaluate.glsl"

#define TB_SURFACE TbGregoryTriSurface
#define TB_BUILD_SURFACE() tbBuildGregoryTriangle()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluateGregoryTriangle(s, coord)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
