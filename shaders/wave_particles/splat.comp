#version 460
// Point splatting (Yuksel et al. 2007, section 5) as a compute scatter: each live particle
// adds amplitude x bilinear weight to the four nearest nodes. The sums are fixed-point
// integers (amplitude x scale, rounded) so that atomic adds in any order give the same
// map. Dispatched indirectly from the step's output counter (sized by prepare.comp).
#extension GL_GOOGLE_include_directive : require
#include "particle.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Particles { Particle particles[]; };
layout(std430, set = 0, binding = 1) readonly buffer Counter TB_COUNTER_BLOCK counter;
layout(std430, set = 0, binding = 2) buffer Grid { int accum[]; };
layout(push_constant) uniform Params {
  float origin;   // m: coordinate of node 0
  float spacing;  // m
  float speed;    // m/s
  float scale;    // fixed-point units per metre of height
  uint nodes;     // per side
} params;

void add(uint i, uint j, float value) {
  atomicAdd(accum[j * params.nodes + i], int(round(value * params.scale)));
}

void main() {
  const uint p = gl_GlobalInvocationID.x;
  if (p >= counter.count) return;
  const Particle particle = particles[p];
  precise float s = params.speed * particle.age;
  precise vec2 x = particle.origin + particle.direction * s;
  precise vec2 uv = (x - vec2(params.origin)) / params.spacing;
  const float last = float(params.nodes - 1u);
  if (!(uv.x >= 0.0 && uv.y >= 0.0 && uv.x <= last && uv.y <= last)) return;
  const uint i = min(uint(uv.x), params.nodes - 2u), j = min(uint(uv.y), params.nodes - 2u);
  precise float fu = uv.x - float(i), fv = uv.y - float(j);
  const float a = particle.amplitude;
  add(i, j, a * (1.0 - fu) * (1.0 - fv));
  add(i + 1u, j, a * fu * (1.0 - fv));
  add(i, j + 1u, a * (1.0 - fu) * fv);
  add(i + 1u, j + 1u, a * fu * fv);
}
