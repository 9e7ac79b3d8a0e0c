#version 460
// `flat` on tessbench's compute path (GpuPatchProgram::compute_shader): the TCS's and TES's
// functions (flat_surface.glsl) run by tessbench's shaders/common/compute_surface.glsl,
// which provides the passes: build each patch's surface, evaluate every domain point.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#define TB_SURFACE_BUILD
#include "flat_surface.glsl"

void flatEvaluate(TbFlatSurface s, vec3 coord) {
  vec3 position, normal;
  tbEvaluateFlatSurface(s, coord, position, normal);
  tbEmitVertex(position, normal);
}

#define TB_SURFACE TbFlatSurface
#define TB_BUILD_SURFACE() tbBuildFlatSurface(tbPatchIndex())
#define TB_EVALUATE_SURFACE(s, coord) flatEvaluate(s, coord)
#define TB_SURFACE_TRIANGLES
#include "compute_surface.glsl"
