// The oracle for wave simulations: the linear 2-D wave equation
//   u_tt + 2 k u_t = c^2 (u_xx + u_yy)
// on a square grid of nodes, second-order central differences in space and time (the
// 5-point Laplacian, leapfrog in time), with reflecting (Neumann) walls: the domain border
// and any wall segments, rasterised to the nodes within half a spacing of them. The time
// step is split into substeps with c dt / h <= 0.5, inside the CFL bound 1/sqrt(2) of this
// scheme. A source is an initial displacement blob of the wave-particle shape
// (A/2 (cos(pi d / r) + 1) for d < r) at zero velocity, added at its time. The scheme is
// second order for smooth data; with this blob (its curvature jumps at the rim) halving h
// shrinks the max difference 2.7-fold (h = 0.05 -> 0.025 -> 0.0125, r = 0.5, t = 1 s:
// 0.0072 then 0.0027 of a unit peak; tests/reference/wave_equation_test.cpp).
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
