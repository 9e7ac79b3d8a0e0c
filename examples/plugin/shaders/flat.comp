#version 460
// `flat` on tessbench's compute path (GpuPatchProgram::compute_shader): the TCS's and TES's
// functions (flat_surface.glsl) run by tessbench's shaders/common/compute_surface.glsl, which
// provides the passes: build each patch's surface, evaluate every domain point.
#extension GL_GOOGLE_include_directive : require
#define TB_SURFACE_BUILD
#include "flat_surface.glsl"

#define TB_SURFACE TbFlatSurface
#define TB_BUILD_SURFACE(patch_index) tbBuildFlatSurface(patch_index)
#define TB_EVALUATE_SURFACE(s, patch_index, coord, position, normal) \
  tbEvaluateFlatSurface(s, coord, position, normal)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
