// The wave particles themselves (Yuksel, House and Keyser, "Wave Particles", SIGGRAPH 2007)
// and the CPU twin of their compute update (shaders/wave_particles/update.comp): the same
// record layout, the same float operations in the same order, so CPU and GPU states
// compare in ulp. A particle's position is derived, origin + direction * speed * age, as in
// the paper and seed 003's state table (origin, direction, age, lifetime, amplitude); a
// reflection mirrors origin and direction across the wall, which mirrors the position.
#pragma once

#include <cstdint>
#include <vector>

namespace tb::wave_particles {

// One particle, 12 32-bit words (std430 in the shaders: 48 bytes).
struct Particle {
  float origin[2];       // m: where the particle's (possibly mirrored) wavefront started
  float direction[2];    // unit vector of travel
  float age_s;           // seconds since emission
  float lifetime_s;      // lp2: expiry age; full: unused (kept for the shared layout)
  float amplitude_m;     // the particle's amplitude (decayed in full)
  float dispersion_rad;  // angle between this particle and its wavefront neighbours
  float radius_m;        // r of the particle shape
  uint32_t id;           // a label that survives reflection and is hashed on subdivision
  uint32_t emit_step;    // pending emissions: the step whose end emits it; 0 otherwise
  uint32_t pad;
};
static_assert(sizeof(Particle) == 48);

enum class Variant : uint32_t { kFull = 0, kLp2 = 1 };

// A reflecting segment as the update reads it: endpoints and unit normal, in float.
struct WallSegment {
  float a[2], b[2], normal[2];
};

// A node of the stackless AABB tree over wall segments (seed 003: the boundary between
// water and scene, extracted in advance, tested through a stackless AABB tree). Nodes are in
// depth-first order; a traversal goes to the next node when the query box overlaps, and to
// `skip` (the first node after the subtree) when it does not. Leaves carry one wall.
struct AabbNode {
  float lo[2], hi[2];
  uint32_t skip;
  int32_t wall;  // leaf: the wall index; internal: -1
  uint32_t pad[2];
};
static_assert(sizeof(AabbNode) == 32);

std::vector<AabbNode> buildWallTree(const std::vector<WallSegment>& walls);

// Settings of one update step, shared by the CPU twin and the shader's push block.
struct StepSettings {
  float dt_s = 0;
  float speed_m_per_s = 0;
  float decay_per_step = 1;   // full: amplitude *= this each step (exp(-damping dt), in double)
  float min_amplitude_m = 0;  // full: particles below it die
  float subdivide_fraction = 0.5f;  // full: subdivide when neighbour spacing > this * radius
  uint32_t capacity = 0;            // particles the output buffer holds; appends beyond are dropped
  Variant variant = Variant::kFull;
};

// Subdivision angles (full): level k's dispersion angle, and the cosine and sine of the
// next level's (the children's rotation), computed once in double and stored in float so
// the GPU never evaluates a trigonometric function.
struct SubdivisionTable {
  std::vector<float> theta, child_cos, child_sin;
};
SubdivisionTable subdivisionTable(float initial_dispersion_rad, int levels);

uint32_t hashId(uint32_t x);

// One step of one particle, appending what survives (one particle, three after a
// subdivision, none after expiry) to `out`. Returns how many were appended; `dropped`
// counts those beyond settings.capacity.
uint32_t updateParticle(const Particle& in, const StepSettings& settings,
                        const std::vector<WallSegment>& walls, const std::vector<AabbNode>& tree,
                        const SubdivisionTable& table, std::vector<Particle>* out,
                        uint64_t* dropped);

// Where the particle is now: origin + direction * (speed * age), in float.
void particlePosition(const Particle& p, float speed_m_per_s, float* x, float* y);

// The particle shape (Yuksel et al. 2007, eq. 3): 1/2 (cos(pi d / r) + 1) for d < r, else 0.
double particleShape(double distance_m, double radius_m);

}  // namespace tb::wave_particles
