#include "harness/measures/stability/stability.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tb::measures {

StabilityFigures measureStability(techniques::Simulation& simulation,
                                  techniques::ConstraintSolver& solver,
                                  const StabilitySettings& settings) {
  StabilityFigures figures;
  figures.steps = settings.steps;
  figures.dispatches_per_step = settings.dispatch_budget;
  figures.iterations_per_step = solver.counts().iterationsFor(settings.dispatch_budget);
  solver.setDispatchesPerStep(settings.dispatch_budget);
  const double dt = simulation.scenario().time_step_s;
  const size_t half = settings.steps / 2;
  double first = 0, last = 0, stretch_sum = 0;
  for (size_t i = 0; i < settings.steps; ++i) {
    simulation.step(dt);
    const techniques::StepDiagnostics d = solver.diagnostics();
    if (!d.finite) figures.finite = false;
    (i < half ? first : last) += d.relative_kinetic_energy;
    figures.energy_peak = std::max(figures.energy_peak, d.relative_kinetic_energy);
    figures.max_stretch = std::max(figures.max_stretch, d.max_stretch);
    stretch_sum += d.rms_stretch;
  }
  figures.energy_first_half = half ? first / double(half) : 0;
  figures.energy_last_half = settings.steps > half ? last / double(settings.steps - half) : 0;
  figures.energy_drift = !figures.finite ? std::numeric_limits<double>::infinity()
                         : figures.energy_first_half > 0
                             ? figures.energy_last_half / figures.energy_first_half
                             : 0;
  figures.mean_rms_stretch = settings.steps ? stretch_sum / double(settings.steps) : 0;
  if (!figures.finite) figures.max_stretch = std::numeric_limits<double>::infinity();
  return figures;
}

}  // namespace tb::measures
