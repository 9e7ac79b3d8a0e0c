// Issue 19, acceptance 4: the measured convergence of the four solvers on the bundled
// pawn scenario's convergence frame, against the seed's claim (Gauss-Seidel needs fewer
// iterations than Jacobi) and Wang's (Chebyshev needs fewer than plain Jacobi).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "harness/measures/convergence/convergence.h"
#include "harness/measures/stability/stability.h"
#include "tests/techniques/mass_spring_test_support.h"

namespace tb {
namespace {

measures::ConvergenceFigures converge(const std::string& variant, bool goal) {
  auto instance = testing::buildMassSpring(testing::massSpringScenario(), variant,
                                           {{"goal_springs", goal ? 1 : 0}});
  measures::ConvergenceSettings settings;
  settings.max_iterations = 20000;
  settings.reference_max_iterations = goal ? 20000 : 1;
  return measures::measureConvergence(testing::massSpringOf(*instance), settings);
}

std::string text(const std::optional<size_t>& n) { return n ? std::to_string(*n) : "not reached"; }

TEST(MassSpringConvergence, GaussSeidelAndChebyshevNeedFewerIterationsThanJacobi) {
  std::map<std::pair<std::string, bool>, measures::ConvergenceFigures> figures;
  for (const bool goal : {false, true}) {
    for (const char* variant : {"gs_serial", "gs_colored", "jacobi", "jacobi_chebyshev"}) {
      const measures::ConvergenceFigures f = converge(variant, goal);
      std::printf(
          "%-17s goal=%d colours=%u to1e-3=%s to1e-5=%s r0=%.3g r@8=%.3g ref=%zu/%d err=%.3g\n",
          variant, goal, f.counts.colours, text(f.iterations_to_1e3).c_str(),
          text(f.iterations_to_1e5).c_str(), f.initial_residual, f.residual_at_budget,
          f.reference_iterations, f.reference_converged, f.final_position_error);
      if (goal) {
        EXPECT_TRUE(f.reference_converged) << variant;
      }
      figures[{variant, goal}] = f;
    }
  }
  // Seed 003: Gauss-Seidel reaches 1e-3 in fewer iterations than Jacobi without goal springs
  // (first measurement: 2007 against over 5000). Not asserted with goal springs: there the
  // seed says it matters little, and the ratio is reported.
  const measures::ConvergenceFigures& gs = figures[{"gs_serial", false}];
  const measures::ConvergenceFigures& jacobi = figures[{"jacobi", false}];
  ASSERT_TRUE(gs.iterations_to_1e3);
  EXPECT_TRUE(!jacobi.iterations_to_1e3 || *gs.iterations_to_1e3 < *jacobi.iterations_to_1e3);
  // Wang 2015: Chebyshev needs fewer iterations than plain Jacobi. First measurement with
  // goal springs (the game's configuration): 33 against 171 to 1e-3 (rho 0.97, 4 plain
  // iterations first); asserting half leaves room for a change of rho or of the frame.
  const measures::ConvergenceFigures& jacobi_goal = figures[{"jacobi", true}];
  const measures::ConvergenceFigures& chebyshev_goal = figures[{"jacobi_chebyshev", true}];
  ASSERT_TRUE(jacobi_goal.iterations_to_1e3 && chebyshev_goal.iterations_to_1e3);
  EXPECT_LT(2 * *chebyshev_goal.iterations_to_1e3, *jacobi_goal.iterations_to_1e3);
  // Without goal springs too: fewer iterations to 1e-3, or Jacobi never gets there.
  const measures::ConvergenceFigures& chebyshev = figures[{"jacobi_chebyshev", false}];
  ASSERT_TRUE(chebyshev.iterations_to_1e3);
  EXPECT_TRUE(!jacobi.iterations_to_1e3 ||
              *chebyshev.iterations_to_1e3 < *jacobi.iterations_to_1e3);
}

}  // namespace
}  // namespace tb
