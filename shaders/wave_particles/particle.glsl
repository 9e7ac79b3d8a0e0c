// The wave particle record and the bindings every wave-particle pass shares
// (techniques/wave_particles/particles.h is the CPU twin: same layout, same float order).
#ifndef TB_WAVE_PARTICLE_GLSL
#define TB_WAVE_PARTICLE_GLSL

struct Particle {
  vec2 origin;       // m
  vec2 direction;    // unit
  float age;         // s
  float lifetime;    // s (lp2)
  float amplitude;   // m
  float dispersion;  // rad
  float radius;      // m
  uint id;
  uint emit_step;
  uint pad;
};

// VkDispatchIndirectCommand, then the particle count the appends advance.
#define TB_COUNTER_BLOCK { uint groups_x; uint groups_y; uint groups_z; uint count; }

uint hashId(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

#endif
