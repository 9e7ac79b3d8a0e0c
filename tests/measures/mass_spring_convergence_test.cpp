// Issue 19, acceptance 4: the measured convergence of the four solvers on the bundled
// pawn scenario's convergence frame, against the seed's claim (Gauss-Seidel needs fewer
// iterations than Jacobi) and Wang's (Chebyshev needs fewer than plain Jacobi).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "harness/measures/convergence.h"
#include "harness/measures/stability.h"
#include "tests/techniques/mass_spring_test_support.h"

namespace tb {
namespace {

ConvergenceFigures converge(const std::string& variant, bool goal) {
  auto instance = testing::buildMassSpring(testing::massSpringScenario(), variant,
                                           {{"goal_springs", goal ? 1 : 0}});
  ConvergenceSettings settings;
  settings.max_iterations = 5000;
  return measureConvergence(testing::massSpringOf(*instance), settings);
}

std::string text(const std::optional<size_t>& n) { return n ? std::to_string(*n) : "not reached"; }

TEST(MassSpringConvergence, GaussSeidelAndChebyshevNeedFewerIterationsThanJacobi) {
  std::map<std::pair<std::string, bool>, ConvergenceFigures> figures;
  for (const bool goal : {false, true}) {
    for (const char* variant : {"gs_serial", "gs_colored", "jacobi", "jacobi_chebyshev"}) {
      const ConvergenceFigures f = converge(variant, goal);
      std::printf("%-17s goal=%d colours=%u to1e-3=%s to1e-5=%s r0=%.3g r@8=%.3g ref=%zu/%d err=%.3g\n",
                  variant, goal, f.counts.colours, text(f.iterations_to_1e3).c_str(),
                  text(f.iterations_to_1e5).c_str(), f.initial_residual, f.residual_at_budget,
                  f.reference_iterations, f.reference_converged, f.final_position_error);
      EXPECT_TRUE(f.reference_converged) << variant;
      figures[{variant, goal}] = f;
    }
  }
  // Gauss-Seidel and its coloured twin are the same sweep up to the order.
  for (const bool goal : {false, true}) {
    const ConvergenceFigures& gs = figures[{"gs_serial", goal}];
    const ConvergenceFigures& jacobi = figures[{"jacobi", goal}];
    const ConvergenceFigures& chebyshev = figures[{"jacobi_chebyshev", goal}];
    ASSERT_TRUE(gs.iterations_to_1e3 && jacobi.iterations_to_1e3 && chebyshev.iterations_to_1e3);
    if (!goal) {
      EXPECT_LT(*gs.iterations_to_1e3, *jacobi.iterations_to_1e3);
    }
    EXPECT_LT(double(*chebyshev.iterations_to_1e3), 0.8 * double(*jacobi.iterations_to_1e3))
        << "goal_springs " << goal;
  }
}

}  // namespace
}  // namespace tb
