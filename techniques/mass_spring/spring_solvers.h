// The four constraint solvers of the mass-spring soft body, templated on the scalar: float
// is what the GPU computes (shaders/mass_spring/ repeat these operations in this order),
// double is the converged reference and the hand-computed tests.
//
// One projection (seed 003's code, with the signs of Jakobsen's "Advanced character
// physics", GDC 2001, which pull a stretched spring together): d = x_b - x_a,
// f = weight (|d| - rest) / |d|, x_a += f d, x_b -= f d; weight = stiffness / 2 for a spring
// between two vertices, = stiffness for one ending at an anchor (the anchor never moves).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh/vec.h"
#include "techniques/mass_spring/spring_system.h"

namespace tb::mass_spring {

enum class SolverKind : uint8_t {
  kGaussSeidelSerial,    // gs_serial: one spring at a time, in index or colour-major order
  kGaussSeidelColoured,  // gs_colored: colour by colour, the springs of a colour in parallel
  kJacobi,               // jacobi: every vertex gathers its springs' corrections from old positions
  kJacobiChebyshev,      // jacobi_chebyshev: Jacobi with Wang's Chebyshev weights
};

struct SolverSettings {
  SolverKind kind = SolverKind::kGaussSeidelSerial;
  bool colour_major = false;  // gs_serial: visit springs in colour-major order
  // Jacobi relaxation: x += omega / n_v * (sum of the n_v corrections at v). The average
  // (omega = 1) is stable at any valence; omega < 1 under-relaxes.
  double omega = 1;
  // Chebyshev (Wang, SIGGRAPH Asia 2015, section 4): the estimated spectral radius of the
  // Jacobi iteration and the iterations run with weight 1 before the schedule starts.
  double rho = 0.9;
  size_t delay = 4;
  // GPU Jacobi: seed 003's shared-memory tiling of the gather (shaders/mass_spring/
  // jacobi.comp, kTiled); the same values either way.
  bool tiled = true;
};

// The correction a spring end at `self` takes towards `other` (operation order fixed: the
// GLSL in shaders/mass_spring/springs.glsl is the same).
template <class Real>
inline mesh::Vec3T<Real> springCorrection(const mesh::Vec3T<Real>& self,
                                          const mesh::Vec3T<Real>& other, Real rest, Real weight) {
  const Real dx = other.x - self.x, dy = other.y - self.y, dz = other.z - self.z;
  const Real length = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (!(length > Real(0))) return {Real(0), Real(0), Real(0)};
  const Real f = weight * ((length - rest) / length);
  return {dx * f, dy * f, dz * f};
}

// The Chebyshev weight of 0-based iteration k given the previous one (Wang 2015, eq. 12:
// omega_1 = 1, omega_2 = 2 / (2 - rho^2), omega_{k+1} = 4 / (4 - rho^2 omega_k), the
// schedule starting after `delay` plain iterations).
inline double chebyshevWeight(size_t k, double previous, double rho, size_t delay) {
  if (k < delay) return 1;
  if (k == delay) return 2 / (2 - rho * rho);
  return 4 / (4 - rho * rho * previous);
}

// Positions and anchors of one solve, and the solver's running state.
template <class Real>
struct SolverState {
  std::vector<mesh::Vec3T<Real>> x;         // vertex positions, metres
  std::vector<mesh::Vec3T<Real>> anchors;   // kinematic anchor positions, metres
  std::vector<mesh::Vec3T<Real>> previous;  // Chebyshev: x of the iteration before
  std::vector<mesh::Vec3T<Real>> scratch;   // Jacobi output
  size_t iteration = 0;                     // iterations since the frame started
  double chebyshev_weight = 1;              // the last Chebyshev weight
  // Coloured Gauss-Seidel under a dispatch budget (iterateDispatches): the colour the cut
  // sweep goes on from next time. Kept across steps, so a sweep longer than the budget
  // completes over several frames.
  size_t sweep_cursor = 0;
};

// The springs of a SpringSystem in Real, and the solver over them.
template <class Real>
class SpringSolver {
 public:
  SpringSolver(const SpringSystem& system, const SolverSettings& settings);
  const SolverSettings& settings() const { return settings_; }
  // Runs `count` iterations on `state`.
  void iterate(SolverState<Real>& state, size_t count) const;
  // Spends `dispatches` GPU dispatches: Jacobi iterations one each; coloured Gauss-Seidel
  // (and the serial sweep in colour-major order) one colour each, going on from
  // state.sweep_cursor and wrapping to the next sweep. The serial index-order sweep has no
  // GPU path: it runs max(1, round(dispatches / colour_count)) whole sweeps.
  void iterateDispatches(SolverState<Real>& state, size_t dispatches) const;
  // One Gauss-Seidel projection of spring s.
  void project(SolverState<Real>& state, uint32_t s) const {
    const uint32_t a = a_[s], b = b_[s];
    const mesh::Vec3T<Real>& other = (b & kAnchorBit) ? state.anchors[b & ~kAnchorBit] : state.x[b];
    const mesh::Vec3T<Real> c = springCorrection(state.x[a], other, rest_[s], weight_[s]);
    state.x[a] = state.x[a] + c;
    if (!(b & kAnchorBit)) state.x[b] = state.x[b] - c;
  }
  // Jacobi's new position of vertex v from `in`.
  mesh::Vec3T<Real> gather(const SolverState<Real>& state, const std::vector<mesh::Vec3T<Real>>& in,
                           size_t v) const {
    mesh::Vec3T<Real> sum{Real(0), Real(0), Real(0)};
    for (uint32_t e = end_start_[v]; e < end_start_[v + 1]; ++e) {
      const uint32_t o = end_other_[e];
      const mesh::Vec3T<Real>& other = (o & kAnchorBit) ? state.anchors[o & ~kAnchorBit] : in[o];
      sum = sum + springCorrection(in[v], other, end_rest_[e], end_weight_[e]);
    }
    const Real s = vertex_scale_[v];
    return {in[v].x + s * sum.x, in[v].y + s * sum.y, in[v].z + s * sum.z};
  }

 private:
  void gaussSeidelSerial(SolverState<Real>& state) const;
  void gaussSeidelColoured(SolverState<Real>& state) const;
  void jacobi(SolverState<Real>& state) const;

  const SpringSystem& system_;
  SolverSettings settings_;
  std::vector<uint32_t> a_, b_;
  std::vector<Real> rest_, weight_;
  std::vector<uint32_t> end_start_, end_other_;
  std::vector<Real> end_rest_, end_weight_;
  std::vector<Real> vertex_scale_;  // omega / (spring ends at v); 0 for a lone vertex
};

// RMS relative stretch of `x` over every spring (surface and inner: (|d| - rest) / rest;
// anchor springs of rest 0: |d| / length_scale_m), in double. `kinds` selects the springs.
struct StretchFigures {
  double rms = 0;      // over the selected springs
  double max_abs = 0;  // largest |relative stretch|
  size_t springs = 0;
};
StretchFigures measureStretch(const SpringSystem& system, const std::vector<mesh::Vec3d>& x,
                              const std::vector<mesh::Vec3d>& anchors, bool surface_only = false);

extern template class SpringSolver<float>;
extern template class SpringSolver<double>;

}  // namespace tb::mass_spring
