#version 460
// Curved PN triangles on the compute path: pn.tesc's and pn.tese's functions
// (pn_surface.glsl) run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#define TB_SURFACE_BUILD
#include "pn_surface.glsl"

#define TB_SURFACE TbPnSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildPnSurface(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluatePnSurface(s, coord, position, normal)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
