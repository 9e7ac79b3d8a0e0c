#version 460
// One step of every live particle (Yuksel et al. 2007; seed 003's update: advance the age,
// test the move against the boundary, expire), appending survivors to the other buffer
// through an atomic counter. Dispatched indirectly from the input counter. The float
// operations follow techniques/wave_particles/particles.cpp in order; `precise` keeps
// them from being contracted or reassociated.
#extension GL_GOOGLE_include_directive : require
#include "particle.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kLp2 = 0;  // 0: full, 1: lp2

layout(std430, set = 0, binding = 0) readonly buffer ParticlesIn { Particle particles_in[]; };
layout(std430, set = 0, binding = 1) writeonly buffer ParticlesOut { Particle particles_out[]; };
layout(std430, set = 0, binding = 2) readonly buffer CounterIn TB_COUNTER_BLOCK counter_in;
layout(std430, set = 0, binding = 3) buffer CounterOut TB_COUNTER_BLOCK counter_out;
struct Wall { vec2 a; vec2 b; vec2 normal; };
layout(std430, set = 0, binding = 4) readonly buffer Walls { Wall walls[]; };
struct Node { vec2 lo; vec2 hi; uint skip; int wall; uint pad0; uint pad1; };
layout(std430, set = 0, binding = 5) readonly buffer Tree { Node nodes[]; };
struct Level { float theta; float child_cos; float child_sin; };
layout(std430, set = 0, binding = 6) readonly buffer Table { Level levels[]; };

layout(push_constant) uniform Params {
  float dt;
  float speed;
  float decay;
  float min_amplitude;
  float subdivide_fraction;
  uint capacity;
  uint wall_count;
  uint node_count;
  uint level_count;
} params;

const float kOneThird = 0.333333343;

vec2 positionOf(Particle p) {
  precise float s = params.speed * p.age;
  precise vec2 x = p.origin + p.direction * s;
  return x;
}

// The earliest crossing so far as num / den (den > 0), compared without a division.
float best_num = 0.0, best_den = 0.0;
int best_wall = -1;

void crossWall(vec2 x0, vec2 e, int index) {
  const Wall w = walls[index];
  precise vec2 f = w.b - w.a;
  precise float den = e.x * f.y - e.y * f.x;
  precise vec2 g = w.a - x0;
  precise float tn = g.x * f.y - g.y * f.x;
  precise float un = g.x * e.y - g.y * e.x;
  if (den == 0.0) return;
  if (den < 0.0) {
    den = -den;
    tn = -tn;
    un = -un;
  }
  if (!(tn > 0.0 && tn <= den && un >= 0.0 && un <= den)) return;
  bool before = best_wall < 0;
  if (!before) {
    precise float lhs = tn * best_den;
    precise float rhs = best_num * den;
    before = lhs < rhs || (lhs == rhs && index < best_wall);
  }
  if (before) {
    best_num = tn;
    best_den = den;
    best_wall = index;
  }
}

void append(Particle p, uint slot) {
  if (slot < params.capacity) particles_out[slot] = p;
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= counter_in.count) return;
  Particle p = particles_in[i];
  precise float age1 = p.age + params.dt;
  const vec2 x0 = positionOf(p);
  p.age = age1;
  const vec2 x1 = positionOf(p);
  precise vec2 e = x1 - x0;
  if (kLp2 == 1u) {
    const vec2 lo = min(x0, x1), hi = max(x0, x1);
    uint n = 0u;
    while (n < params.node_count) {
      const Node node = nodes[n];
      const bool overlaps = node.lo.x <= hi.x && lo.x <= node.hi.x && node.lo.y <= hi.y &&
                            lo.y <= node.hi.y;
      if (!overlaps) {
        n = node.skip;
        continue;
      }
      if (node.wall >= 0) crossWall(x0, e, node.wall);
      ++n;
    }
  } else {
    for (int w = 0; w < int(params.wall_count); ++w) crossWall(x0, e, w);
  }
  if (best_wall >= 0) {
    const Wall w = walls[best_wall];
    precise float dn = p.direction.x * w.normal.x + p.direction.y * w.normal.y;
    precise float dx = p.direction.x - (2.0 * dn) * w.normal.x;
    precise float dy = p.direction.y - (2.0 * dn) * w.normal.y;
    precise float on = (p.origin.x - w.a.x) * w.normal.x + (p.origin.y - w.a.y) * w.normal.y;
    precise float ox = p.origin.x - (2.0 * on) * w.normal.x;
    precise float oy = p.origin.y - (2.0 * on) * w.normal.y;
    p.direction = vec2(dx, dy);
    p.origin = vec2(ox, oy);
  }
  if (kLp2 == 1u) {
    if (p.age >= p.lifetime) return;  // expiry at the lifetime (seed 003)
    append(p, atomicAdd(counter_out.count, 1u));
    return;
  }
  precise float amplitude = p.amplitude * params.decay;
  p.amplitude = amplitude;
  if (abs(p.amplitude) < params.min_amplitude) return;
  precise float travelled = params.speed * p.age;
  precise float spacing = p.dispersion * travelled;
  precise float limit = params.subdivide_fraction * p.radius;
  int level = -1;
  if (spacing > limit) {
    for (uint k = 0u; k + 1u < params.level_count; ++k) {
      if (levels[k].theta == p.dispersion) level = int(k);
    }
  }
  if (level < 0) {
    append(p, atomicAdd(counter_out.count, 1u));
    return;
  }
  const float c = levels[level].child_cos, s = levels[level].child_sin;
  const vec2 d = p.direction;
  Particle middle = p;
  middle.dispersion = levels[level + 1].theta;
  precise float third = p.amplitude * kOneThird;
  middle.amplitude = third;
  Particle left = middle, right = middle;
  precise float lx = d.x * c - d.y * s;
  precise float ly = d.x * s + d.y * c;
  precise float rx = d.x * c + d.y * s;
  precise float ry = d.y * c - d.x * s;
  left.direction = vec2(lx, ly);
  right.direction = vec2(rx, ry);
  middle.id = hashId(p.id * 3u + 1u);
  left.id = hashId(p.id * 3u + 2u);
  right.id = hashId(p.id * 3u + 3u);
  const uint slot = atomicAdd(counter_out.count, 3u);
  append(middle, slot);
  append(left, slot + 1u);
  append(right, slot + 2u);
}
