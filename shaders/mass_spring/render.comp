#version 460
// The last pass of a mass-spring step (seed 003, "vertex buffer update"): every render
// vertex from its simulated triangle and the triangle's virtual apex, which keeps the
// tetrahedron's rest volume: DrawVertex = p0 w0 + p1 w1 + p2 w2 + p3 (1 - w0 - w1 - w2).
// Operation order: techniques/mass_spring/tet_binding.h (drawVertexFloat).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

#include "mass_spring_layout.h"  // Spring, End, Binding, Blast
layout(std430, set = 0, binding = 0) readonly buffer Positions { vec4 x[]; };
layout(std430, set = 0, binding = 1) readonly buffer Bindings { Binding bindings[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Render { vec4 render_positions[]; };

layout(push_constant) uniform Params { uint render_count; } params;

const float kThird = 0.333333343;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= params.render_count) return;
  const Binding b = bindings[i];
  const vec3 p0 = x[b.v0].xyz, p1 = x[b.v1].xyz, p2 = x[b.v2].xyz;
  precise vec3 c = vec3((p0.x + p1.x + p2.x) * kThird, (p0.y + p1.y + p2.y) * kThird,
                        (p0.z + p1.z + p2.z) * kThird);
  precise vec3 e1 = vec3(p1.x - p0.x, p1.y - p0.y, p1.z - p0.z);
  precise vec3 e2 = vec3(p2.x - p0.x, p2.y - p0.y, p2.z - p0.z);
  precise vec3 n = vec3(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                        e1.x * e2.y - e1.y * e2.x);
  precise float nn = n.x * n.x + n.y * n.y + n.z * n.z;
  precise float s = nn > 0.0 ? (6.0 * b.volume) / nn : 0.0;
  precise vec3 p3 = vec3(c.x + n.x * s, c.y + n.y * s, c.z + n.z * s);
  precise float w3 = 1.0 - b.w0 - b.w1 - b.w2;
  precise vec3 q = vec3(p0.x * b.w0 + p1.x * b.w1 + p2.x * b.w2 + p3.x * w3,
                        p0.y * b.w0 + p1.y * b.w1 + p2.y * b.w2 + p3.y * w3,
                        p0.z * b.w0 + p1.z * b.w1 + p2.z * b.w2 + p3.z * w3);
  render_positions[i] = vec4(q, 0.0);
}
