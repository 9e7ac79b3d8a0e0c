#version 460
// Appends the emissions due at the end of this step (the CPU computes them once, with
// their step; seed 003 emits from chosen points) to the output buffer.
#extension GL_GOOGLE_include_directive : require
#include "particle.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Pending { Particle pending[]; };
layout(std430, set = 0, binding = 1) writeonly buffer ParticlesOut { Particle particles_out[]; };
layout(std430, set = 0, binding = 2) buffer CounterOut TB_COUNTER_BLOCK counter_out;
layout(push_constant) uniform Params {
  uint step;  // 0-based index of the step this dispatch ends (the runner's step word)
  uint pending_count;
  uint capacity;
} params;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= params.pending_count || pending[i].emit_step != params.step + 1u) return;
  const uint slot = atomicAdd(counter_out.count, 1u);
  if (slot < params.capacity) particles_out[slot] = pending[i];
}
