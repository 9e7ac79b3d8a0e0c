#version 460
// gregory_acc's quads on the compute path: gregory_acc.tesc's and gregory_acc.tese's
// functions (gregory_stencil.glsl, gregory_quad_surface.glsl) run by
// shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#define TB_SURFACE_BUILD
#include "gregory_quad_surface.glsl"

#define TB_SURFACE TbGregoryQuadSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildGregoryQuad(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluateGregoryQuad(s, coord, position, normal)
#include "compute_surface.glsl"
