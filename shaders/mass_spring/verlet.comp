#version 460
// The first pass of a mass-spring step: the bones' animation moves the anchors (inner
// springs' bone points, goal springs' skinned positions), a blast due this step kicks the
// vertices near it, and Verlet integration predicts the positions (seed 003):
//   x' = x + (1 - damping) (x - x_prev) + g dt^2 + kick.
// Operation order: techniques/mass_spring/mass_spring.cpp (anchorsAt, step).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;
// 1: also copy the prediction to positions_other (Chebyshev's x_{k-1} before iteration 0).
layout(constant_id = 0) const uint kCopyToOther = 0;

#include "mass_spring_layout.h"  // Spring, End, Binding, Blast
layout(std430, set = 0, binding = 0) buffer Positions { vec4 x[]; };
layout(std430, set = 0, binding = 1) buffer Previous { vec4 x_prev[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Anchors { vec4 anchors[]; };
layout(std430, set = 0, binding = 3) readonly buffer Rest { vec4 rest[]; };
layout(std430, set = 0, binding = 4) readonly buffer BoneRest { vec4 bone_rest[]; };
layout(std430, set = 0, binding = 5) readonly buffer Amplitudes { vec4 stomp_amplitude[]; };
// Row j: float(sin(2 pi f_s j dt)) for each stomp s; rows past the table repeat the last.
layout(std430, set = 0, binding = 6) readonly buffer Sines { float stomp_sine[]; };
layout(std430, set = 0, binding = 7) readonly buffer Blasts { Blast blasts[]; };
layout(std430, set = 0, binding = 8) writeonly buffer Other { vec4 x_other[]; };

layout(push_constant) uniform Params {
  uint vertex_count;
  uint stomp_count;
  uint sine_rows;
  uint blast_count;
  float keep;  // 1 - damping
  float gx, gy, gz;  // g dt^2
  float dt;
  uint step;   // 0-based, written by the runner (step_index_word)
} params;

void main() {
  const uint v = gl_GlobalInvocationID.x;
  if (v >= params.vertex_count) return;
  const uint row = min(params.step + 1u, params.sine_rows - 1u);
  precise vec3 offset = vec3(0.0);
  for (uint s = 0u; s < params.stomp_count; ++s) {
    const float sine = stomp_sine[row * params.stomp_count + s];
    const vec3 a = stomp_amplitude[v * params.stomp_count + s].xyz;
    offset = vec3(offset.x + a.x * sine, offset.y + a.y * sine, offset.z + a.z * sine);
  }
  const vec3 b = bone_rest[v].xyz, r = rest[v].xyz;
  precise vec3 inner = vec3(b.x + offset.x, b.y + offset.y, b.z + offset.z);
  precise vec3 goal = vec3(r.x + offset.x, r.y + offset.y, r.z + offset.z);
  anchors[v] = vec4(inner, 0.0);
  anchors[params.vertex_count + v] = vec4(goal, 0.0);

  const vec3 p = x[v].xyz, q = x_prev[v].xyz;
  precise vec3 kick = vec3(0.0);
  for (uint i = 0u; i < params.blast_count; ++i) {
    if (blasts[i].step != params.step) continue;
    const vec3 c = blasts[i].centre.xyz;
    precise vec3 away = vec3(p.x - c.x, p.y - c.y, p.z - c.z);
    precise float distance = sqrt(away.x * away.x + away.y * away.y + away.z * away.z);
    if (!(distance < blasts[i].radius) || !(distance > 0.0)) continue;
    precise float speed = blasts[i].speed * (1.0 - distance / blasts[i].radius);
    precise float f = (speed * params.dt) / distance;
    kick = vec3(kick.x + away.x * f, kick.y + away.y * f, kick.z + away.z * f);
  }
  precise vec3 next = vec3(p.x + params.keep * (p.x - q.x) + params.gx + kick.x,
                           p.y + params.keep * (p.y - q.y) + params.gy + kick.y,
                           p.z + params.keep * (p.z - q.z) + params.gz + kick.z);
  x_prev[v] = vec4(p, 0.0);
  x[v] = vec4(next, 0.0);
  if (kCopyToOther != 0u) x_other[v] = vec4(next, 0.0);
}
