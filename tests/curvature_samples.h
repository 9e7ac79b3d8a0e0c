// Sampled second derivatives of a surface patch, by exact identities rather than
// finite-difference approximations, so each sampled value is a lower bound of the
// supremum it samples (never above it beyond double rounding):
//  - (S(u+h, v) - 2 S(u, v) + S(u-h, v)) / h^2 is the average of S_uu over [u-h, u+h] with
//    the hat kernel (1 - |x - u| / h) / h, whose weights are >= 0 and sum to 1, so its norm
//    is <= sup |S_uu| (vv alike; on a triangle the step is (1, 0, -1) or (0, 1, -1) in
//    barycentrics, the domain's u and v with w dependent);
//  - (S(u+h, v+h) - S(u+h, v-h) - S(u-h, v+h) + S(u-h, v-h)) / (4 h^2) is the mean of S_uv
//    over the square [u-h, u+h] x [v-h, v+h], so its norm is <= sup |S_uv|;
//  - along each edge, the edge curve's second difference / h^2 (<= sup |C''|).
// Used against techniques::CurvatureBounds (curvature_bounds_test.cpp: a bound is never
// below them) and as the tightest bound any technique could give (error_bound_floor_test.cpp).
#pragma once

#include <algorithm>
#include <array>

#include "core/mesh/vec.h"
#include "techniques/technique.h"

namespace tb::testing {

// Step in domain units. A quad is sampled at u, v = (2k + 1) / (2 n) + 1/96 for n = 6 or 24
// (k < n), which keeps 1/96 from every line k / 16 (osd_adaptive's sub-patch seams to
// isolation level 4, where a Gregory end cap's first derivative may jump) and from the
// domain's edges, far more than 2 h; a triangle at ((i + 1/3) / n, (j + 1/3) / n), i + j < n.
constexpr double kStep = 2e-3;
constexpr int kDefaultSamples = 6;  // per direction
constexpr double kQuadShift = 1.0 / 96;
// The largest sampled second-difference norms of one patch: uu, uv, vv, then edges 0..3.
using Sampled = std::array<double, 7>;

// Folds the second differences of `at` (a function of the domain's (u, v)) at (u, v) into
// m[0..2]: uu, uv, vv.
template <class At>
void sampleInterior(const At& at, double u, double v, Sampled& m) {
  const double h = kStep, inv = 1 / (h * h);
  const mesh::Vec3d c = at(u, v);
  m[0] = std::max(m[0], length(at(u + h, v) - c * 2.0 + at(u - h, v)) * inv);
  m[1] = std::max(
      m[1], length(at(u + h, v + h) - at(u + h, v - h) - at(u - h, v + h) + at(u - h, v - h)) *
                (0.25 * inv));
  m[2] = std::max(m[2], length(at(u, v + h) - c * 2.0 + at(u, v - h)) * inv);
}

// Folds each edge curve's second differences at t = (2k + 1) / (2 n) + shift into m[3 + e];
// edges[e] = {u0, v0, du/dt, dv/dt}.
template <class At, size_t kEdges>
void sampleEdges(const At& at, const std::array<std::array<double, 4>, kEdges>& edges, int n,
                 double shift, Sampled& m) {
  const double h = kStep, inv = 1 / (h * h);
  for (size_t e = 0; e < kEdges; ++e) {
    const auto& [u0, v0, du, dv] = edges[e];
    const auto curve = [&](double t) { return at(u0 + du * t, v0 + dv * t); };
    for (int k = 0; k < n; ++k) {
      const double t = (2 * k + 1) / (2.0 * n) + shift;
      m[3 + e] = std::max(m[3 + e], length(curve(t + h) - curve(t) * 2.0 + curve(t - h)) * inv);
    }
  }
}

inline Sampled sampleQuad(const techniques::SurfacePatches& s, size_t patch,
                          int n = kDefaultSamples) {
  const auto at = [&](double u, double v) { return s.evaluate(patch, {u, v, 0}).position; };
  Sampled m{};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      sampleInterior(at, (2 * i + 1) / (2.0 * n) + kQuadShift, (2 * j + 1) / (2.0 * n) + kQuadShift,
                     m);
    }
  }
  // Edges u = 0, v = 0, u = 1, v = 1 as curves of t.
  sampleEdges<decltype(at), 4>(at, {{{0, 0, 0, 1}, {0, 0, 1, 0}, {1, 0, 0, 1}, {0, 1, 1, 0}}}, n,
                               kQuadShift, m);
  return m;
}

inline Sampled sampleTriangle(const techniques::SurfacePatches& s, size_t patch,
                              int n = kDefaultSamples) {
  const auto at = [&](double u, double v) { return s.evaluate(patch, {u, v, 1 - u - v}).position; };
  Sampled m{};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i + j < n; ++i) sampleInterior(at, (i + 1.0 / 3) / n, (j + 1.0 / 3) / n, m);
  }
  // Edges u = 0 (corner 1 to 2), v = 0 (2 to 0), w = 0 (0 to 1); edge 3 stays 0.
  sampleEdges<decltype(at), 3>(at, {{{0, 1, 0, -1}, {0, 0, 1, 0}, {1, 0, -1, 1}}}, n, 0, m);
  return m;
}

// sampleQuad or sampleTriangle by the patch's domain.
inline Sampled sampleSecondDerivatives(const techniques::SurfacePatches& s, size_t patch,
                                       int n = kDefaultSamples) {
  return s.patchDomain(patch) == techniques::PatchDomain::kQuad ? sampleQuad(s, patch, n)
                                                                : sampleTriangle(s, patch, n);
}

}  // namespace tb::testing
