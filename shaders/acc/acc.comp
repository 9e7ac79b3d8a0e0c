#version 460
// ACC on the compute path: acc.tesc's and acc.tese's functions (acc_surface.glsl) run by
// shaders/common/compute_surface.glsl; one build invocation computes the patch's 16 points
// in turn, as acc.tesc's 16 invocations do.
#extension GL_GOOGLE_include_directive : require
#define TB_SURFACE_BUILD
#include "acc_surface.glsl"

#define TB_SURFACE TbAccSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildAccSurface(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluateAcc(s, coord, position, normal)
#include "compute_surface.glsl"
