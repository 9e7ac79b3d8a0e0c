#version 460
// osd_adaptive on the compute path: osd_adaptive.tese's functions
// (osd_adaptive_surface.glsl) run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#include "osd_adaptive_surface.glsl"

#define TB_SURFACE TbOsdSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildOsdSurface(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluateOsdSurface(s, coord, position, normal)
#include "compute_surface.glsl"
