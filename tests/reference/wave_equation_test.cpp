// The wave-equation reference (reference/wave_equation.h). Oracles: the solver's own
// finer grids (halving h shrinks the difference: 2.7-fold in the max norm for this source),
// the method of images (a straight Neumann wall equals an open domain with a mirrored
// source), and the wave speed (the front reaches a probe at distance R between (R - r)/c and
// R/c).
#include "reference/wave_equation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tb::ref {
namespace {

WaveEquationSetup pointSetup(double spacing) {
  WaveEquationSetup setup;
  setup.domain_size_m = 4;
  setup.wave_speed_m_per_s = 1;
  setup.spacing_m = spacing;
  setup.sources = {{0.1, -0.2, 0, 1.0, 0.5}};
  return setup;
}

// Max |difference| of two solvers at the nodes of the coarsest grid (h = 0.05) within
// |x|, |y| <= 1.6 (the front, 1 + r from the source, never meets the border).
double maxDifference(const WaveEquationSolver& a, const WaveEquationSolver& b) {
  double worst = 0;
  for (double y = -1.6; y <= 1.6 + 1e-9; y += 0.05) {
    for (double x = -1.6; x <= 1.6 + 1e-9; x += 0.05) {
      worst = std::max(worst, std::abs(a.sample(x, y) - b.sample(x, y)));
    }
  }
  return worst;
}

TEST(WaveEquation, HalvingTheSpacingShrinksTheDifferenceAsASecondOrderScheme) {
  std::vector<WaveEquationSolver> solvers;
  for (double h : {0.05, 0.025, 0.0125}) solvers.emplace_back(pointSetup(h), 0.05);
  for (int frame = 0; frame < 20; ++frame) {
    for (WaveEquationSolver& solver : solvers) solver.advance();
  }
  const double coarse = maxDifference(solvers[0], solvers[1]);
  const double fine = maxDifference(solvers[1], solvers[2]);
  std::printf(
      "reference convergence at t = 1 s: |u(0.05) - u(0.025)| = %.3g, "
      "|u(0.025) - u(0.0125)| = %.3g, ratio %.2f\n",
      coarse, fine, coarse / fine);
  EXPECT_GT(coarse, 0.0);
  // Second order would shrink it fourfold; the particle-shape blob's curvature jumps at its
  // rim (W''(r) = pi^2 / 2r^2 outside, 0 inside), which costs the max norm some order: it
  // shrinks 2.7-fold (order 1.4). Halving must at least halve it.
  EXPECT_LT(fine, coarse / 2.0);
  EXPECT_LT(fine, 0.01) << "the h = 0.025 grid is within 1% of the peak";
}

TEST(WaveEquation, AStraightWallReflectsLikeTheMirrorImageSource) {
  const double h = 0.025;
  WaveEquationSetup walled = pointSetup(h);
  walled.domain_size_m = 8;
  walled.sources = {{0, 0, 0, 1.0, 0.25}};
  walled.walls = {{1.0, -4.0, 1.0, 4.0}};
  // The wall's nodes are solid, so the mirror line is half a spacing in front of them.
  WaveEquationSetup images = walled;
  images.walls.clear();
  images.sources.push_back({2.0 - h, 0, 0, 1.0, 0.25});
  WaveEquationSolver a(walled, 0.05), b(images, 0.05);
  for (int frame = 0; frame < 36; ++frame) {  // t = 1.8 s: the reflection is back past x = 0
    a.advance();
    b.advance();
  }
  double worst = 0, peak = 0;
  for (double y = -2.5; y <= 2.5; y += h) {
    for (double x = -2.5; x <= 1.0 - 1.5 * h; x += h) {
      worst = std::max(worst, std::abs(a.sample(x, y) - b.sample(x, y)));
      peak = std::max(peak, std::abs(b.sample(x, y)));
    }
  }
  EXPECT_GT(peak, 0.01);
  EXPECT_LT(worst, 1e-9) << "peak " << peak;
  // A broken oracle (no mirror source) is caught.
  WaveEquationSetup lone = images;
  lone.sources.pop_back();
  WaveEquationSolver c(lone, 0.05);
  for (int frame = 0; frame < 36; ++frame) c.advance();
  EXPECT_GT(std::abs(a.sample(0.2, 0.0) - c.sample(0.2, 0.0)) +
                std::abs(a.sample(-0.3, 0.3) - c.sample(-0.3, 0.3)),
            1e-3);
}

TEST(WaveEquation, TheFrontTravelsAtTheWaveSpeed) {
  WaveEquationSetup setup = pointSetup(0.025);
  setup.sources = {{0, 0, 0, 1.0, 0.25}};
  WaveEquationSolver solver(setup, 0.01);
  double peak = 0;
  std::vector<double> trace;
  for (int frame = 0; frame < 180; ++frame) {
    solver.advance();
    trace.push_back(solver.sample(1.5, 0));
    peak = std::max(peak, std::abs(trace.back()));
  }
  size_t first = 0;
  while (first < trace.size() && std::abs(trace[first]) <= 0.1 * peak) ++first;
  const double arrival = 0.01 * double(first + 1);
  EXPECT_GE(arrival, (1.5 - 0.25) - 0.02);
  EXPECT_LE(arrival, 1.5 + 0.02);
}

}  // namespace
}  // namespace tb::ref
