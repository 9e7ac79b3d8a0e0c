#version 460
// One colour of graph-coloured Gauss-Seidel (gs_colored): the springs of one independent
// batch, one thread each; no two share a vertex, so the writes never race. One dispatch
// per colour, in colour order (techniques/mass_spring/spring_solvers.cpp, project()).
#extension GL_GOOGLE_include_directive : require
#include "springs.glsl"

layout(local_size_x = 64) in;

#include "mass_spring_layout.h"  // Spring, End, Binding, Blast
layout(std430, set = 0, binding = 0) buffer Positions { vec4 x[]; };
layout(std430, set = 0, binding = 1) readonly buffer Anchors { vec4 anchors[]; };
layout(std430, set = 0, binding = 2) readonly buffer Springs { Spring springs[]; };

layout(push_constant) uniform Params {
  uint begin;  // the colour's first spring in colour-major order
  uint end;    // one past its last
} params;

void main() {
  const uint s = params.begin + gl_GlobalInvocationID.x;
  if (s >= params.end) return;
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
