#version 460
// Closes a step without a CPU read-back (seed 003's CopyStructureCount + DispatchIndirect):
// clamps the output count to the buffer, counts what was dropped, sizes the next update's
// indirect dispatch (64 particles a group) and clears the counter the next step appends to.
#extension GL_GOOGLE_include_directive : require
#include "particle.glsl"

layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 0) buffer CounterIn TB_COUNTER_BLOCK counter_in;
layout(std430, set = 0, binding = 1) buffer CounterOut TB_COUNTER_BLOCK counter_out;
// peak particles alive, particles dropped at a full buffer
layout(std430, set = 0, binding = 2) buffer Stats { uint peak; uint dropped; } stats;
layout(push_constant) uniform Params { uint capacity; } params;

void main() {
  uint count = counter_out.count;
  if (count > params.capacity) {
    stats.dropped += count - params.capacity;
    count = params.capacity;
  }
  counter_out.count = count;
  counter_out.groups_x = (count + 63u) / 64u;
  counter_out.groups_y = 1u;
  counter_out.groups_z = 1u;
  stats.peak = max(stats.peak, count);
  counter_in.count = 0u;
  counter_in.groups_x = 0u;
}
