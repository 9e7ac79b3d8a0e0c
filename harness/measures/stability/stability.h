// The stability of a simulation stepped with a constraint solver on a fixed iteration
// budget per frame, the way a game runs it (seed 003: a fixed number of dispatches per
// frame): energy drift and the largest stretch over a run of the animated scenario.
#pragma once

#include <cstddef>

#include "techniques/constraint_solver.h"
#include "techniques/simulation.h"

namespace tb::measures {

struct StabilitySettings {
  size_t steps = 60;           // frames simulated
  size_t dispatch_budget = 8;  // GPU dispatches per frame the solver may spend
};

struct StabilityFigures {
  size_t steps = 0;
  size_t dispatches_per_step = 0;  // the budget
  // Solver iterations the budget buys per step: budget / dispatches per iteration (below 1
  // when one Gauss-Seidel sweep takes more dispatches than the budget: a partial sweep).
  double iterations_per_step = 0;
  // Mean relative kinetic energy (StepDiagnostics, m^2/s^2 per vertex) over the first and
  // the last half of the run.
  double energy_first_half = 0, energy_last_half = 0;
  // energy_last_half / energy_first_half: below 1 the motion settles (damping, a decaying
  // blast), about 1 a steady periodic motion, above 1 the solver feeds energy in; a run
  // that blew up is +inf. Lower is better.
  double energy_drift = 0;
  double energy_peak = 0;  // largest per-step value (m^2/s^2)
  // Largest |length - rest| / rest of any surface spring at the end of any step (1): 0 is
  // a skin that never stretches; the budget's residual shows here.
  double max_stretch = 0;
  double mean_rms_stretch = 0;  // the RMS surface stretch, averaged over the steps (1)
  bool finite = true;           // every position stayed finite
};

// Steps `simulation` (at its scenario's time step) `settings.steps` times.
StabilityFigures measureStability(techniques::Simulation& simulation,
                                  techniques::ConstraintSolver& solver,
                                  const StabilitySettings& settings);

}  // namespace tb::measures
