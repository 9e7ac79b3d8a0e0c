#version 460
// gregory_acc's triangles on the compute path: gregory_tri.tesc's and gregory_tri.tese's
// functions (gregory_stencil.glsl, gregory_tri_surface.glsl) run by
// shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#define TB_SURFACE_BUILD
#include "gregory_tri_surface.glsl"

#define TB_SURFACE TbGregoryTriSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildGregoryTriangle(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluateGregoryTriangle(s, coord, position, normal)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
