#include "techniques/wave_particles/particles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tb::wave_particles {
namespace {

// 1/3 in float; the shader multiplies by the same constant (a division might be lowered to
// a reciprocal and a product on the device).
constexpr float kOneThird = 0.333333343f;

// A crossing of segment x0 -> x1 with a wall, as the fraction t = num / den (den > 0), so
// two crossings compare without a division (the shader does the same).
struct Crossing {
  float num = 0, den = 0;
  int32_t wall = -1;
  bool before(const Crossing& other) const {
    if (other.wall < 0) return true;
    const float lhs = num * other.den;
    const float rhs = other.num * den;
    return lhs < rhs || (lhs == rhs && wall < other.wall);
  }
};

void crossWall(const float x0[2], const float e[2], const WallSegment& w, int32_t index,
               Crossing* best) {
  const float f[2] = {w.b[0] - w.a[0], w.b[1] - w.a[1]};
  float den = e[0] * f[1] - e[1] * f[0];
  const float g[2] = {w.a[0] - x0[0], w.a[1] - x0[1]};
  float tn = g[0] * f[1] - g[1] * f[0];
  float un = g[0] * e[1] - g[1] * e[0];
  if (den == 0.0f) return;
  if (den < 0.0f) {
    den = -den;
    tn = -tn;
    un = -un;
  }
  // t in (0, 1]: a particle that starts on a wall (just reflected) does not hit it again.
  if (!(tn > 0.0f && tn <= den && un >= 0.0f && un <= den)) return;
  const Crossing candidate{tn, den, index};
  if (candidate.before(*best)) *best = candidate;
}

void append(const Particle& p, const StepSettings& settings, std::vector<Particle>* out,
            uint32_t* appended, uint64_t* dropped) {
  if (out->size() < settings.capacity) {
    out->push_back(p);
    ++*appended;
  } else {
    ++*dropped;
  }
}

}  // namespace

double particleShape(double distance_m, double radius_m) {
  if (!(distance_m < radius_m)) return 0;
  return 0.5 * (std::cos(std::numbers::pi * distance_m / radius_m) + 1.0);
}

uint32_t hashId(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

SubdivisionTable subdivisionTable(float initial_dispersion_rad, int levels) {
  SubdivisionTable table;
  double theta = initial_dispersion_rad;
  for (int k = 0; k < levels; ++k) {
    table.theta.push_back(float(theta));
    const double child = theta / 3.0;
    table.child_cos.push_back(float(std::cos(child)));
    table.child_sin.push_back(float(std::sin(child)));
    theta = child;
  }
  return table;
}

std::vector<AabbNode> buildWallTree(const std::vector<WallSegment>& walls) {
  std::vector<AabbNode> nodes;
  std::vector<int32_t> order(walls.size());
  for (size_t i = 0; i < walls.size(); ++i) order[i] = int32_t(i);
  // Median split on the longer axis of the centres, depth first.
  auto build = [&](auto&& self, size_t begin, size_t end) -> void {
    AabbNode node{};
    node.lo[0] = node.lo[1] = INFINITY;
    node.hi[0] = node.hi[1] = -INFINITY;
    for (size_t i = begin; i < end; ++i) {
      const WallSegment& w = walls[size_t(order[i])];
      for (int c = 0; c < 2; ++c) {
        node.lo[c] = std::min({node.lo[c], w.a[c], w.b[c]});
        node.hi[c] = std::max({node.hi[c], w.a[c], w.b[c]});
      }
    }
    const size_t at = nodes.size();
    node.wall = end - begin == 1 ? order[begin] : -1;
    nodes.push_back(node);
    if (end - begin > 1) {
      const int axis = node.hi[0] - node.lo[0] >= node.hi[1] - node.lo[1] ? 0 : 1;
      const size_t mid = (begin + end) / 2;
      std::nth_element(order.begin() + long(begin), order.begin() + long(mid),
                       order.begin() + long(end), [&](int32_t x, int32_t y) {
                         const float cx = walls[size_t(x)].a[axis] + walls[size_t(x)].b[axis];
                         const float cy = walls[size_t(y)].a[axis] + walls[size_t(y)].b[axis];
                         return cx < cy || (cx == cy && x < y);
                       });
      self(self, begin, mid);
      self(self, mid, end);
    }
    nodes[at].skip = uint32_t(nodes.size());
  };
  if (!walls.empty()) build(build, 0, walls.size());
  return nodes;
}

void particlePosition(const Particle& p, float speed_m_per_s, float* x, float* y) {
  const float s = speed_m_per_s * p.age_s;
  *x = p.origin[0] + p.direction[0] * s;
  *y = p.origin[1] + p.direction[1] * s;
}

uint32_t updateParticle(const Particle& in, const StepSettings& settings,
                        const std::vector<WallSegment>& walls, const std::vector<AabbNode>& tree,
                        const SubdivisionTable& table, std::vector<Particle>* out,
                        uint64_t* dropped) {
  Particle p = in;
  const float age1 = p.age_s + settings.dt_s;
  float x0[2], x1[2];
  particlePosition(p, settings.speed_m_per_s, &x0[0], &x0[1]);
  p.age_s = age1;
  particlePosition(p, settings.speed_m_per_s, &x1[0], &x1[1]);
  const float e[2] = {x1[0] - x0[0], x1[1] - x0[1]};
  Crossing best;
  if (settings.variant == Variant::kLp2) {
    const float lo[2] = {std::min(x0[0], x1[0]), std::min(x0[1], x1[1])};
    const float hi[2] = {std::max(x0[0], x1[0]), std::max(x0[1], x1[1])};
    uint32_t i = 0;
    while (i < tree.size()) {
      const AabbNode& node = tree[i];
      const bool overlaps =
          node.lo[0] <= hi[0] && lo[0] <= node.hi[0] && node.lo[1] <= hi[1] && lo[1] <= node.hi[1];
      if (!overlaps) {
        i = node.skip;
        continue;
      }
      if (node.wall >= 0) crossWall(x0, e, walls[size_t(node.wall)], node.wall, &best);
      ++i;
    }
  } else {
    for (size_t w = 0; w < walls.size(); ++w) crossWall(x0, e, walls[w], int32_t(w), &best);
  }
  if (best.wall >= 0) {
    const WallSegment& w = walls[size_t(best.wall)];
    const float dn = p.direction[0] * w.normal[0] + p.direction[1] * w.normal[1];
    p.direction[0] = p.direction[0] - 2.0f * dn * w.normal[0];
    p.direction[1] = p.direction[1] - 2.0f * dn * w.normal[1];
    const float on = (p.origin[0] - w.a[0]) * w.normal[0] + (p.origin[1] - w.a[1]) * w.normal[1];
    p.origin[0] = p.origin[0] - 2.0f * on * w.normal[0];
    p.origin[1] = p.origin[1] - 2.0f * on * w.normal[1];
  }
  uint32_t appended = 0;
  if (settings.variant == Variant::kLp2) {
    if (p.age_s >= p.lifetime_s) return 0;  // expiry at the lifetime (seed 003)
    append(p, settings, out, &appended, dropped);
    return appended;
  }
  p.amplitude_m = p.amplitude_m * settings.decay_per_step;
  if (std::abs(p.amplitude_m) < settings.min_amplitude_m) return 0;
  // Subdivision (Yuksel et al. 2007, section 4.2): when the arc between wavefront
  // neighbours, dispersion * distance travelled, exceeds a fraction of the radius, the
  // particle becomes three with a third of the dispersion and of the amplitude each.
  const float travelled = settings.speed_m_per_s * p.age_s;
  int level = -1;
  if (p.dispersion_rad * travelled > settings.subdivide_fraction * p.radius_m) {
    for (size_t k = 0; k + 1 < table.theta.size(); ++k) {
      if (table.theta[k] == p.dispersion_rad) level = int(k);
    }
  }
  if (level < 0) {
    append(p, settings, out, &appended, dropped);
    return appended;
  }
  const float c = table.child_cos[size_t(level)];
  const float s = table.child_sin[size_t(level)];
  Particle middle = p;
  middle.dispersion_rad = table.theta[size_t(level) + 1];
  middle.amplitude_m = p.amplitude_m * kOneThird;
  Particle left = middle, right = middle;
  left.direction[0] = p.direction[0] * c - p.direction[1] * s;
  left.direction[1] = p.direction[0] * s + p.direction[1] * c;
  right.direction[0] = p.direction[0] * c + p.direction[1] * s;
  right.direction[1] = p.direction[1] * c - p.direction[0] * s;
  middle.id = hashId(p.id * 3u + 1u);
  left.id = hashId(p.id * 3u + 2u);
  right.id = hashId(p.id * 3u + 3u);
  append(middle, settings, out, &appended, dropped);
  append(left, settings, out, &appended, dropped);
  append(right, settings, out, &appended, dropped);
  return appended;
}

}  // namespace tb::wave_particles
