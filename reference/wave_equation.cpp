#include "reference/wave_equation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tb::ref {
namespace {

double blob(double distance, double radius) {
  if (!(distance < radius)) return 0;
  return 0.5 * (std::cos(std::numbers::pi * distance / radius) + 1.0);
}

double segmentDistance(double px, double py, const WaveEquationWall& w) {
  const double dx = w.x1_m - w.x0_m, dy = w.y1_m - w.y0_m;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - w.x0_m) * dx + (py - w.y0_m) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(px - (w.x0_m + t * dx), py - (w.y0_m + t * dy));
}

}  // namespace

// Node (i, j), 1 <= i, j <= n - 2, sits at (-size/2 + (i - 1) h, ...); ring nodes are solid.
WaveEquationSolver::WaveEquationSolver(const WaveEquationSetup& setup, double frame_dt_s)
    : setup_(setup), frame_dt_s_(frame_dt_s) {
  if (!(setup.spacing_m > 0 && setup.domain_size_m > 0 && setup.wave_speed_m_per_s > 0 &&
        frame_dt_s > 0)) {
    throw std::invalid_argument("wave equation: spacing, size, speed and step must be > 0");
  }
  const double h = setup.spacing_m;
  n_ = uint32_t(std::lround(setup.domain_size_m / h)) + 1 + 2;
  substeps_ = uint32_t(std::ceil(setup.wave_speed_m_per_s * frame_dt_s / (0.5 * h)));
  substeps_ = std::max(substeps_, 1u);
  substep_s_ = frame_dt_s / substeps_;
  solid_.assign(size_t(n_) * n_, 0);
  const double origin = -setup.domain_size_m / 2;
  for (uint32_t j = 0; j < n_; ++j) {
    for (uint32_t i = 0; i < n_; ++i) {
      bool solid = i == 0 || j == 0 || i == n_ - 1 || j == n_ - 1;
      const double x = origin + (double(i) - 1) * h, y = origin + (double(j) - 1) * h;
      for (const WaveEquationWall& wall : setup.walls) {
        solid |= segmentDistance(x, y, wall) < 0.5 * h;
      }
      solid_[index(i, j)] = solid;
    }
  }
  u_.assign(solid_.size(), 0.0);
  u_prev_ = u_;
  u_next_ = u_;
  addSources();
}

void WaveEquationSolver::addSources() {
  const double h = setup_.spacing_m, origin = -setup_.domain_size_m / 2;
  for (const WaveEquationSource& source : setup_.sources) {
    if (uint64_t(std::llround(source.time_s / frame_dt_s_)) != frames_) continue;
    for (uint32_t j = 1; j + 1 < n_; ++j) {
      for (uint32_t i = 1; i + 1 < n_; ++i) {
        if (solid_[index(i, j)]) continue;
        const double x = origin + (double(i) - 1) * h, y = origin + (double(j) - 1) * h;
        const double add =
            source.amplitude_m * blob(std::hypot(x - source.x_m, y - source.y_m), source.radius_m);
        u_[index(i, j)] += add;
        u_prev_[index(i, j)] += add;  // zero initial velocity
      }
    }
  }
}

void WaveEquationSolver::advance() {
  const double courant = setup_.wave_speed_m_per_s * substep_s_ / setup_.spacing_m;
  const double c2 = courant * courant;
  const double kdt = setup_.damping_per_s * substep_s_;
  const size_t n = n_;
  for (uint32_t s = 0; s < substeps_; ++s) {
    for (size_t j = 1; j + 1 < n; ++j) {
      for (size_t i = 1; i + 1 < n; ++i) {
        const size_t c = j * n + i;
        if (solid_[c]) continue;
        const double uc = u_[c];
        // Neumann at walls: a solid neighbour mirrors this node (contributes 0).
        double lap = 0;
        for (const size_t nb : {c - 1, c + 1, c - n, c + n}) {
          if (!solid_[nb]) lap += u_[nb] - uc;
        }
        u_next_[c] = (2 * uc - (1 - kdt) * u_prev_[c] + c2 * lap) / (1 + kdt);
      }
    }
    std::swap(u_prev_, u_);
    std::swap(u_, u_next_);
  }
  ++frames_;
  addSources();
}

double WaveEquationSolver::sample(double x_m, double y_m) const {
  const double h = setup_.spacing_m, origin = -setup_.domain_size_m / 2;
  const double u = std::clamp((x_m - origin) / h + 1, 1.0, double(n_ - 2));
  const double v = std::clamp((y_m - origin) / h + 1, 1.0, double(n_ - 2));
  const uint32_t i = std::min(uint32_t(u), n_ - 3), j = std::min(uint32_t(v), n_ - 3);
  const double fu = u - i, fv = v - j;
  auto at = [&](uint32_t a, uint32_t b) { return u_[index(a, b)]; };
  return (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i + 1, j)) +
         fv * ((1 - fu) * at(i, j + 1) + fu * at(i + 1, j + 1));
}

bool WaveEquationSolver::solidAt(double x_m, double y_m) const {
  const double h = setup_.spacing_m, origin = -setup_.domain_size_m / 2;
  const long i = std::lround((x_m - origin) / h) + 1, j = std::lround((y_m - origin) / h) + 1;
  if (i < 0 || j < 0 || i >= long(n_) || j >= long(n_)) return true;
  return solid_[index(uint32_t(i), uint32_t(j))];
}

}  // namespace tb::ref
