// The stability measure's algorithm on the mass-spring soft body: against the analytic
// rest state (no animation, no gravity: nothing moves) and the decay of a blast's energy.
#include <gtest/gtest.h>

#include "harness/measures/stability/stability.h"
#include "tests/techniques/mass_spring_test_support.h"

namespace tb {
namespace {

measures::StabilityFigures runStability(const techniques::Scenario& scenario,
                                        const std::string& variant) {
  auto instance = testing::buildMassSpring(scenario, variant);
  auto& simulation = testing::massSpringOf(*instance);
  measures::StabilitySettings settings;
  settings.steps = scenario.stepCount();
  return measures::measureStability(simulation, simulation, settings);
}

// Oracle: the rest state. Without animation and gravity every spring is at its rest length
// and no vertex moves: energy 0 and a stretch of float rounding only (rest lengths are
// computed in double from the float rest pose).
TEST(MassSpringStability, TheRestStateStaysAtRest) {
  techniques::Scenario scenario = testing::massSpringScenario("[]", "rest");
  std::string& section = scenario.sections["mass_spring"];
  section.replace(section.find("[0, 0, -9.81]"), 13, "[0, 0, 0]");
  for (const char* variant : {"gs_serial", "gs_colored", "jacobi", "jacobi_chebyshev"}) {
    const measures::StabilityFigures f = runStability(scenario, variant);
    EXPECT_TRUE(f.finite) << variant;
    EXPECT_LT(f.energy_peak, 1e-10) << variant;
    EXPECT_LT(f.max_stretch, 1e-5) << variant;
    EXPECT_EQ(f.steps, 60u);
  }
  // The check can fail: with gravity the skin sags and moves.
  const measures::StabilityFigures sagging =
      runStability(testing::massSpringScenario("[]", "sag"), "jacobi");
  EXPECT_GT(sagging.energy_peak, 1e-6);
  EXPECT_GT(sagging.max_stretch, 1e-3);
}

// A blast kicks the skin once; with goal springs every solver brings it back, so the second
// half of the run holds less energy than the first (drift < 1).
TEST(MassSpringStability, ABlastsEnergyDecays) {
  const techniques::Scenario scenario =
      testing::massSpringScenario(testing::kBlastAnimation, "blast");
  for (const char* variant : {"gs_serial", "gs_colored", "jacobi", "jacobi_chebyshev"}) {
    const measures::StabilityFigures f = runStability(scenario, variant);
    EXPECT_TRUE(f.finite) << variant;
    EXPECT_LT(f.energy_drift, 1.0) << variant;
    EXPECT_GT(f.energy_peak, 0.0) << variant;
  }
}

}  // namespace
}  // namespace tb
