// The oracle for wave simulations: u_tt + 2 k u_t = c^2 (u_xx + u_yy) on a square grid, the
// 5-point Laplacian and leapfrog, Neumann walls (the border and wall segments rasterised to
// the nodes within h/2), substeps with c dt / h <= 0.5 (CFL bound 1/sqrt(2)). A source is
// the wave-particle blob A/2 (cos(pi d / r) + 1) at zero velocity. Halving h shrinks the max
// difference 2.7-fold (the blob's curvature jumps at its rim; tests/reference/
// wave_equation_test.cpp; docs/derivations/simulations.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tb::ref {

struct WaveEquationSource {
  double x_m = 0, y_m = 0;
  double time_s = 0;       // added at the frame nearest this time
  double amplitude_m = 0;  // blob peak
  double radius_m = 0;     // blob radius
};

struct WaveEquationWall {
  double x0_m = 0, y0_m = 0, x1_m = 0, y1_m = 0;
};

struct WaveEquationSetup {
  double domain_size_m = 0;  // [-size/2, size/2]^2; its border reflects
  double wave_speed_m_per_s = 0;
  double spacing_m = 0;      // node spacing h
  double damping_per_s = 0;  // k
  std::vector<WaveEquationSource> sources;
  std::vector<WaveEquationWall> walls;
};

class WaveEquationSolver {
 public:
  // frame_dt_s: the time advance() moves by (the simulation's step).
  WaveEquationSolver(const WaveEquationSetup& setup, double frame_dt_s);
  void advance();  // one frame
  double timeS() const { return double(frames_) * frame_dt_s_; }
  // Bilinear interpolation of the displacement at (x, y), clamped to the domain.
  double sample(double x_m, double y_m) const;
  uint32_t nodes() const { return n_; }  // per side
  double substepS() const { return substep_s_; }
  bool solidAt(double x_m, double y_m) const;  // the nearest node is a wall node

 private:
  void addSources();
  size_t index(uint32_t i, uint32_t j) const { return size_t(j) * n_ + i; }

  WaveEquationSetup setup_;
  double frame_dt_s_ = 0, substep_s_ = 0;
  uint32_t substeps_ = 1;
  uint32_t n_ = 0;  // nodes per side, plus a solid ring around them
  uint64_t frames_ = 0;
  std::vector<uint8_t> solid_;
  std::vector<double> u_, u_prev_, u_next_;
};

}  // namespace tb::ref
