#version 460
// One dispatch of graph-coloured Gauss-Seidel inside a step with a fixed dispatch budget:
// dispatch d of step k projects colour (k * dispatches_per_step + d) mod colour_count, so a
// sweep of more colours than the budget goes on where it stopped next step
// (techniques/mass_spring/spring_solvers.cpp, iterateDispatches).
#extension GL_GOOGLE_include_directive : require
#include "springs.glsl"

layout(local_size_x = 64) in;

#include "mass_spring_layout.h"  // Spring, End, Binding, Blast
layout(std430, set = 0, binding = 0) buffer Positions { vec4 x[]; };
layout(std430, set = 0, binding = 1) readonly buffer Anchors { vec4 anchors[]; };
layout(std430, set = 0, binding = 2) readonly buffer Springs { Spring springs[]; };
layout(std430, set = 0, binding = 3) readonly buffer ColourStart { uint colour_start[]; };

layout(push_constant) uniform Params {
  uint dispatch_in_step;
  uint dispatches_per_step;
  uint colour_count;
  uint step;  // 0-based, written by the runner (step_index_word)
} params;

void main() {
  const uint colour = (params.step * params.dispatches_per_step + params.dispatch_in_step) %
                      params.colour_count;
  const uint s = colour_start[colour] + gl_GlobalInvocationID.x;
  if (s >= colour_start[colour + 1u]) return;
  const Spring spring = springs[s];
  const bool anchored = (spring.b & kAnchorBit) != 0u;
  const vec3 self = x[spring.a].xyz;
  const vec3 other = anchored ? anchors[spring.b & ~kAnchorBit].xyz : x[spring.b].xyz;
  const vec3 c = springCorrection(self, other, spring.rest, spring.weight);
  precise vec3 a = vec3(self.x + c.x, self.y + c.y, self.z + c.z);
  x[spring.a] = vec4(a, 0.0);
  if (!anchored) {
    const vec3 b0 = x[spring.b].xyz;
    precise vec3 b = vec3(b0.x - c.x, b0.y - c.y, b0.z - c.z);
    x[spring.b] = vec4(b, 0.0);
  }
}
