// The "stability" measure: measureStability of each constraint solver (a variant) over the
// animated scenario with a budget of 8 dispatches per frame, with and without goal springs
// (row key goal_springs). The default suite runs the scenario's own duration; --suite full
// ten times as long.
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "harness/measures/stability/stability.h"
#include "techniques/constraint_solver.h"

namespace tb::measures {
namespace {

constexpr size_t kDispatchBudget = 8;
constexpr size_t kFullSuiteLength = 10;  // --suite full: this many times the scenario

const MetricTable<StabilityFigures>& stabilityTable() {
  using D = results::Direction;
  using F = StabilityFigures;
  using O = std::optional<double>;
  auto finite = [](double F::*member) {
    return [member](const F& f) -> O {
      if (!std::isfinite(f.*member)) return std::nullopt;
      return f.*member;
    };
  };
  static const MetricTable<F> kTable{
      // energy_drift: ratio; below 1 the motion settles (best), about 1 steady, +inf for a run that
      //   blew up (worst)
      {"energy_drift", results::Unit::kRatio, D::kLowerIsBetter, finite(&F::energy_drift)},
      // max_stretch: ratio |length - rest| / rest; 0 when no surface spring stretches (best),
      //   unbounded (worst)
      {"max_stretch", results::Unit::kRatio, D::kLowerIsBetter, finite(&F::max_stretch)},
      // mean_rms_stretch: ratio; 0 (best), unbounded (worst)
      {"mean_rms_stretch", results::Unit::kRatio, D::kLowerIsBetter, finite(&F::mean_rms_stretch)},
      // finite: flag; 1 when every position stayed finite (best), 0 (worst)
      {"finite", results::Unit::kFlag, D::kHigherIsBetter,
       [](const F& f) { return f.finite ? 1.0 : 0.0; }},
      // steps: count; context: frames simulated
      {"steps", results::Unit::kCount, D::kNone, &F::steps},
      // dispatches_per_step: count; context: the solver's dispatch budget per frame
      {"dispatches_per_step", results::Unit::kCount, D::kNone, &F::dispatches_per_step},
      // iterations_per_step: ratio; context: solver iterations the budget buys (below 1: a partial
      //   sweep)
      {"iterations_per_step", results::Unit::kRatio, D::kNone, &F::iterations_per_step},
  };
  return kTable;
}

class StabilityMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "stability",
        .title = "Stability of the constraint solvers over an animated run",
        .description =
            "energy drift and largest spring stretch over the animated scenario with a fixed "
            "budget of 8 GPU dispatches per frame, with and without goal springs",
        .metrics = stabilityTable().specs(),
        .headline = {"energy_drift", "max_stretch"},
        .notes =
            {"energy: kinetic energy of the motion relative to the skinned (goal) motion, per unit "
             "mass and vertex; energy_drift = mean over the run's last half / mean over its first "
             "half (below 1 the motion settles, above 1 the solver feeds energy in); absent with "
             "finite = 0 when the run blew up",
             "max_stretch: largest |length - rest| / rest of any surface spring after any step",
             "8 solver dispatches per step, as a game with a fixed per-frame budget (a coloured "
             "Gauss-Seidel sweep of more colours than that goes on where it stopped next step: "
             "iterations_per_step < 1; gs_serial, with no GPU path, runs max(1, round(8 / "
             "colours)) whole sweeps); the default suite runs the scenario's duration, --suite "
             "full " +
                 std::to_string(kFullSuiteLength) + " times as long"},
        .summary_scope = {},
        .plots = {},
        .decision_inputs = {{.role = results::DecisionRole::kSimulationFigure,
                             .label = "per scenario",
                             .metrics = {"energy_drift", "max_stretch"}}}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSimulation, MeasureNeed::kConstraintSolver},
            VariantPolicy::kEveryVariant,
            {}};
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    StabilitySettings settings;
    settings.dispatch_budget = kDispatchBudget;
    settings.steps = input.simulation->scenario().stepCount() *
                     (input.suite == SuiteMode::kFull ? kFullSuiteLength : 1);
    for (const bool goal : {true, false}) {
      techniques::VariantInfo variant = input.variant;
      variant.parameters["goal_springs"] = goal ? 1 : 0;
      const std::unique_ptr<techniques::TechniqueInstance> instance =
          input.technique.build({nullptr, &input.simulation->scenario()}, variant);
      techniques::Simulation* simulation = instance->simulation();
      techniques::ConstraintSolver* solver = simulation ? simulation->constraintSolver() : nullptr;
      const std::string goal_key = goal ? "true" : "false";
      if (solver == nullptr) {
        result.rows.push_back(results::unmeasuredRow({{"goal_springs", goal_key}},
                                                     results::MeasureStatus::kSkipped,
                                                     "the simulation has no constraint solver"));
        continue;
      }
      results::MetricRow row;
      row.keys = {{"goal_springs", goal_key}};
      row.metrics = stabilityTable().metrics(measureStability(*simulation, *solver, settings));
      result.rows.push_back(std::move(row));
    }
    return result;
  }
};

TB_REGISTER_MEASURE(StabilityMeasure);

}  // namespace
}  // namespace tb::measures
