// gregory_acc's control points, shared by the quad (20 points) and triangle (15 points)
// TCSs and the compute path's build pass: one point is its stencil's weighted sum of
// control-mesh vertices read by index from storage buffers, summed in the stencil's order
// (ascending vertex index) from zero: the same sum GregoryPatches computes on the CPU, so
// shared corner and edge points (one stencil per vertex / directed edge) get the same bits
// in every patch, quad or triangle.
#ifndef TB_GREGORY_STENCIL_GLSL
#define TB_GREGORY_STENCIL_GLSL

#include "gregory_layout.h"
layout(std430, set = 0, binding = TB_GREGORY_BINDING_VERTICES) readonly buffer Vertices {
  vec4 vertices[];
};
layout(std430, set = 0, binding = TB_GREGORY_BINDING_STENCIL_OFFSETS) readonly buffer
    StencilOffsets {
  uint stencil_offsets[];
};
layout(std430, set = 0, binding = TB_GREGORY_BINDING_STENCIL_ENTRIES) readonly buffer
    StencilEntries {
  uvec2 stencil_entries[];
};
layout(std430, set = 0, binding = TB_GREGORY_BINDING_PATCH_POINTS) readonly buffer PatchPoints {
  uint patch_points[];
};

// Control point `point` of program patch `patch_index`, whose patches have
// `points_per_patch` points.
vec3 tbGregoryControlPoint(uint patch_index, uint point, uint points_per_patch) {
  const uint s = patch_points[patch_index * points_per_patch + point];
  precise vec3 sum = vec3(0.0);
  for (uint k = stencil_offsets[s]; k < stencil_offsets[s + 1u]; ++k) {
    const uvec2 entry = stencil_entries[k];
    precise vec3 term = vertices[entry.x].xyz * uintBitsToFloat(entry.y);
    sum = sum + term;
  }
  return sum;
}

#endif
