#include "techniques/wave_particles/height_field.h"

#include <algorithm>
#include <cmath>

namespace tb::wave_particles {

double HeightField::sample(double x, double y) const {
  const double u = std::clamp((x - origin_m) / spacing_m, 0.0, double(nodes - 1));
  const double v = std::clamp((y - origin_m) / spacing_m, 0.0, double(nodes - 1));
  const uint32_t i = std::min(uint32_t(u), nodes - 2), j = std::min(uint32_t(v), nodes - 2);
  const double fu = u - i, fv = v - j;
  return (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i + 1, j)) +
         fv * ((1 - fu) * at(i, j + 1) + fu * at(i + 1, j + 1));
}

HeightField splatAndFilter(const std::vector<Particle>& particles, float speed_m_per_s,
                           double domain_size_m, double spacing_m, double radius_m) {
  HeightField field;
  field.origin_m = -domain_size_m / 2;
  field.spacing_m = spacing_m;
  field.nodes = uint32_t(std::lround(domain_size_m / spacing_m)) + 1;
  const uint32_t n = field.nodes;
  std::vector<double> points(size_t(n) * n, 0.0);
  for (const Particle& p : particles) {
    float x, y;
    particlePosition(p, speed_m_per_s, &x, &y);
    const double u = (x - field.origin_m) / spacing_m, v = (y - field.origin_m) / spacing_m;
    if (!(u >= 0 && v >= 0 && u <= n - 1 && v <= n - 1)) continue;
    const uint32_t i = std::min(uint32_t(u), n - 2), j = std::min(uint32_t(v), n - 2);
    const double fu = u - i, fv = v - j, a = p.amplitude_m;
    points[size_t(j) * n + i] += a * (1 - fu) * (1 - fv);
    points[size_t(j) * n + i + 1] += a * fu * (1 - fv);
    points[size_t(j + 1) * n + i] += a * (1 - fu) * fv;
    points[size_t(j + 1) * n + i + 1] += a * fu * fv;
  }
  // The filter: the particle shape sampled at node offsets within the radius.
  const int reach = int(std::floor(radius_m / spacing_m));
  const int width = 2 * reach + 1;
  std::vector<double> kernel(size_t(width) * width);
  for (int dj = -reach; dj <= reach; ++dj) {
    for (int di = -reach; di <= reach; ++di) {
      kernel[size_t(dj + reach) * width + size_t(di + reach)] =
          particleShape(std::hypot(di * spacing_m, dj * spacing_m), radius_m);
    }
  }
  field.height_m.assign(size_t(n) * n, 0.0);
  for (uint32_t j = 0; j < n; ++j) {
    for (uint32_t i = 0; i < n; ++i) {
      const double a = points[size_t(j) * n + i];
      if (a == 0) continue;
      for (int dj = -reach; dj <= reach; ++dj) {
        const int jj = int(j) + dj;
        if (jj < 0 || jj >= int(n)) continue;
        for (int di = -reach; di <= reach; ++di) {
          const int ii = int(i) + di;
          if (ii < 0 || ii >= int(n)) continue;
          field.height_m[size_t(jj) * n + size_t(ii)] +=
              a * kernel[size_t(dj + reach) * width + size_t(di + reach)];
        }
      }
    }
  }
  return field;
}

double particleHeightAt(const std::vector<Particle>& particles, float speed_m_per_s, double x,
                        double y) {
  double h = 0;
  for (const Particle& p : particles) {
    float px, py;
    particlePosition(p, speed_m_per_s, &px, &py);
    h += p.amplitude_m * particleShape(std::hypot(x - px, y - py), p.radius_m);
  }
  return h;
}

}  // namespace tb::wave_particles
