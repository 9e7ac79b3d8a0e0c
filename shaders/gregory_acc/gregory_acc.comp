#version 460
// gregory_acc's quads on the compute path: gregory_acc.tesc's per-point stencil sum
// (gregory_stencil.glsl) for each of the 20 points and gregory_acc.tese's body
// (gregory_quad_evaluate.glsl), run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#include "gregory_stencil.glsl"

vec3 control_point[20];  // the TES's input: the evaluated patch's points
#include "gregory_surface.glsl"

struct TbGregoryQuadSurface {
  vec3 cp[20];
};

TbGregoryQuadSurface tbBuildGregoryQuad() {
  TbGregoryQuadSurface s;
  for (uint i = 0u; i < 20u; ++i) s.cp[i] = tbGregoryControlPoint(tbPatchIndex(), i, 20u);
  return s;
}

#define TB_EVALUATE_FUNCTION tbEvaluateGregoryQuad(TbGregoryQuadSurface s, vec3 tb_tess_coord)
#define TB_EVALUATE_PROLOGUE control_point = s.cp;
#define TB_TESS_COORD tb_tess_coord
#include "gregory_quad_evaluate.glsl"

#define TB_SURFACE TbGregoryQuadSurface
#define TB_BUILD_SURFACE() tbBuildGregoryQuad()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluateGregoryQuad(s, coord)
#include "compute_surface.glsl"
