// The output of wave particles: a height field on a square grid of nodes, made as the
// paper makes it (Yuksel et al. 2007, section 5): each particle is splatted as a point
// (bilinear weights into the four nearest nodes), then the grid is filtered with the
// particle shape. The CPU does it in double, in particle order (a compute scatter on the
// GPU would need float atomics, whose sums depend on the order; the GPU comparison is on
// the particle state instead).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "techniques/wave_particles/particles.h"

namespace tb::wave_particles {

struct HeightField {
  double origin_m = 0;           // the coordinate of node 0 on both axes (-domain/2)
  double spacing_m = 0;          // node spacing
  uint32_t nodes = 0;            // per side
  std::vector<double> height_m;  // nodes x nodes, row-major (y rows)
  double at(uint32_t i, uint32_t j) const { return height_m[size_t(j) * nodes + i]; }
  // Bilinear interpolation at (x, y) (clamped to the grid).
  double sample(double x, double y) const;
};

HeightField splatAndFilter(const std::vector<Particle>& particles, float speed_m_per_s,
                           double domain_size_m, double spacing_m, double radius_m);

// The exact particle sum at one point: sum of amplitude * shape(|x - position|), for probes.
double particleHeightAt(const std::vector<Particle>& particles, float speed_m_per_s, double x,
                        double y);

}  // namespace tb::wave_particles
