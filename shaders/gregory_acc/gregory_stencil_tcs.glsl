// The gregory_acc TCS body shared by the quad (20 points) and triangle (15 points)
// programs: one invocation per Gregory control point, its stencil's weighted sum of
// control-mesh vertices read by index from storage buffers, summed in the stencil's
// order (ascending vertex index) from zero: the same sum GregoryPatches computes on the
// CPU, so shared corner and edge points (one stencil per vertex / directed edge) get the
// same bits in every patch, quad or triangle. Define TB_GREGORY_POINTS before including.
#ifndef TB_GREGORY_STENCIL_TCS_GLSL
#define TB_GREGORY_STENCIL_TCS_GLSL

#include "patch_program_tcs.glsl"

layout(vertices = TB_GREGORY_POINTS) out;
layout(std430, set = 0, binding = 1) readonly buffer Vertices { vec4 vertices[]; };
layout(std430, set = 0, binding = 2) readonly buffer StencilOffsets { uint stencil_offsets[]; };
layout(std430, set = 0, binding = 3) readonly buffer StencilEntries { uvec2 stencil_entries[]; };
layout(std430, set = 0, binding = 4) readonly buffer PatchPoints { uint patch_points[]; };
layout(location = 0) out vec3 control_point[];

void main() {
  const uint s = patch_points[tbPatchIndex() * uint(TB_GREGORY_POINTS) + uint(gl_InvocationID)];
  precise vec3 sum = vec3(0.0);
  for (uint k = stencil_offsets[s]; k < stencil_offsets[s + 1u]; ++k) {
    const uvec2 entry = stencil_entries[k];
    precise vec3 term = vertices[entry.x].xyz * uintBitsToFloat(entry.y);
    sum = sum + term;
  }
  control_point[gl_InvocationID] = sum;
  if (gl_InvocationID == 0) tbWriteHarnessLevels();
}

#endif
