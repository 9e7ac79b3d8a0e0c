// What the baker's oracle tests share (baker_test.cpp, displaced_oracle_test.cpp).
#pragma once

#include <algorithm>

#include "harness/bake/analytic_target.h"
#include "reference/limit_surface.h"

namespace tb::testing {

// M: the largest second directional derivative |d^2 S_d / dt^2| (unit t in the face's (u, v))
// of the displaced limit S_d(u, v) = L + h(L) N, bounded at each sample by
// max(|S_uu|, |S_vv|) + |S_uv| from central differences (step 1e-3: truncation ~1e-6
// relative, round-off ~1e-10), over a 7 x 7 grid of every face (a Loop face's samples with
// u + v <= 0.95 only: its domain is the triangle).
inline double secondDerivativeBound(const mesh::Mesh& mesh, osd::Scheme scheme,
                                    const bake::AnalyticDisplacement& h) {
  const ref::LimitSurface limit(mesh, scheme);
  auto displaced = [&](size_t face, double u, double v) {
    const ref::LimitPoint p = limit.evaluate(face, u, v);
    return p.position + h.height(p.position) * p.normal;
  };
  const double d = 1e-3;
  double bound = 0;
  for (size_t face = 0; face < limit.faceCount(); ++face) {
    if (!limit.hasLimitSurface(face)) continue;
    for (int i = 0; i < 7; ++i) {
      for (int j = 0; j < 7; ++j) {
        const double u = 0.05 + 0.15 * i, v = 0.05 + 0.15 * j;
        if (scheme == osd::Scheme::kLoop && u + v > 0.95) continue;
        const mesh::Vec3d c = displaced(face, u, v);
        const mesh::Vec3d uu =
            (displaced(face, u + d, v) - 2.0 * c + displaced(face, u - d, v)) * (1 / (d * d));
        const mesh::Vec3d vv =
            (displaced(face, u, v + d) - 2.0 * c + displaced(face, u, v - d)) * (1 / (d * d));
        const mesh::Vec3d uv = (displaced(face, u + d, v + d) - displaced(face, u + d, v - d) -
                                displaced(face, u - d, v + d) + displaced(face, u - d, v - d)) *
                               (1 / (4 * d * d));
        bound = std::max(bound, std::max(length(uu), length(vv)) + length(uv));
      }
    }
  }
  return bound;
}

}  // namespace tb::testing
