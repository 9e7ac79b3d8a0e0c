#version 460
// Phong tessellation on the compute path: phong.tesc's and phong.tese's functions
// (phong_surface.glsl) run by shaders/common/compute_surface.glsl.
#extension GL_GOOGLE_include_directive : require
#define TB_SURFACE_BUILD
#include "phong_surface.glsl"

#define TB_SURFACE TbPhongSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildPhongSurface(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluatePhongSurface(s, coord, position, normal)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
