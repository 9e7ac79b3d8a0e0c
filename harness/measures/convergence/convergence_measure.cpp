// The "convergence" measure: measureConvergence of each constraint solver (a variant) on its
// scenario's convergence frame, with and without goal springs (row key goal_springs). Rows
// of kind "iteration" give the residual after each iteration k; the row of kind "summary"
// per goal_springs value gives the iterations to 1e-3 and 1e-5 and the residual a budget of
// 8 dispatches reaches, which report.md's summary shows per solver.
#include <memory>
#include <optional>
#include <string>

#include "harness/measures/convergence/convergence.h"
#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "techniques/constraint_solver.h"

namespace tb::measures {
namespace {

constexpr size_t kDispatchBudget = 8;

struct ConvergenceRowFigures {
  const ConvergenceFigures* figures = nullptr;
  const ConvergenceIteration* iteration = nullptr;  // null on the summary row
  bool goal_springs = true;
};

// Accessors: a figure of the iteration rows, of the summary row, and the summary's residual
// at the dispatch budget with or without goal springs.
auto perIteration(double ConvergenceIteration::*member) {
  return [member](const ConvergenceRowFigures& r) -> std::optional<double> {
    if (r.iteration == nullptr) return std::nullopt;
    return r.iteration->*member;
  };
}
constexpr auto summaryFigure = [](auto fn) {
  return [fn](const ConvergenceRowFigures& r) -> std::optional<double> {
    if (r.iteration != nullptr) return std::nullopt;
    return fn(*r.figures);
  };
};
auto budgetResidual(bool goal) {
  return [goal](const ConvergenceRowFigures& r) -> std::optional<double> {
    if (r.iteration != nullptr || r.goal_springs != goal) return std::nullopt;
    return r.figures->residual_at_budget;
  };
}

const MetricTable<ConvergenceRowFigures>& convergenceTable() {
  using D = results::Direction;
  using R = ConvergenceRowFigures;
  using O = std::optional<double>;
  using F = ConvergenceFigures;
  static const MetricTable<R> kTable{
      // kind = iteration
      // residual: ratio (RMS relative stretch); 0 when every constraint is met (best), unbounded
      //   (worst)
      {"residual", results::Unit::kRatio, D::kLowerIsBetter,
       perIteration(&ConvergenceIteration::residual)},
      // residual_ratio: ratio to the initial residual; 0 (best), above 1 diverging (worst)
      {"residual_ratio", results::Unit::kRatio, D::kLowerIsBetter,
       perIteration(&ConvergenceIteration::residual_ratio)},
      // position_error: ratio of the mean spring length; 0 at the converged reference (best),
      //   unbounded (worst)
      {"position_error", results::Unit::kRatio, D::kLowerIsBetter,
       perIteration(&ConvergenceIteration::position_error)},
      // kind = summary
      // residual_at_8_dispatches_no_goal_springs: ratio to the initial residual; 0 (best),
      //   unbounded (worst)
      {"residual_at_8_dispatches_no_goal_springs", results::Unit::kRatio, D::kLowerIsBetter,
       budgetResidual(false)},
      // residual_at_8_dispatches_goal_springs: ratio to the initial residual; 0 (best), unbounded
      //   (worst)
      {"residual_at_8_dispatches_goal_springs", results::Unit::kRatio, D::kLowerIsBetter,
       budgetResidual(true)},
      // iterations_to_1e-3: count; 1 (best), up to the iteration budget (worst; absent when not
      //   reached)
      {"iterations_to_1e-3", results::Unit::kCount, D::kLowerIsBetter,
       [](const R& r) -> O {
         if (r.iteration != nullptr || !r.figures->iterations_to_1e3) return std::nullopt;
         return double(*r.figures->iterations_to_1e3);
       }},
      // iterations_to_1e-5: count; 1 (best), up to the iteration budget (worst; absent when not
      //   reached)
      {"iterations_to_1e-5", results::Unit::kCount, D::kLowerIsBetter,
       [](const R& r) -> O {
         if (r.iteration != nullptr || !r.figures->iterations_to_1e5) return std::nullopt;
         return double(*r.figures->iterations_to_1e5);
       }},
      // reached_1e-3: flag; 1 when reached within the budget (best), 0 (worst)
      {"reached_1e-3", results::Unit::kFlag, D::kHigherIsBetter,
       summaryFigure([](const F& f) { return f.iterations_to_1e3 ? 1.0 : 0.0; })},
      // reached_1e-5: flag; 1 when reached within the budget (best), 0 (worst)
      {"reached_1e-5", results::Unit::kFlag, D::kHigherIsBetter,
       summaryFigure([](const F& f) { return f.iterations_to_1e5 ? 1.0 : 0.0; })},
      // iteration_budget: count; context
      {"iteration_budget", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.iteration_budget); })},
      // dispatches_per_iteration: count; 1 for Jacobi (best), the colour count for Gauss-Seidel,
      //   unbounded (worst)
      {"dispatches_per_iteration", results::Unit::kCount, D::kLowerIsBetter,
       summaryFigure([](const F& f) { return double(f.counts.dispatches_per_iteration); })},
      // iterations_at_8_dispatches: ratio; context: iterations 8 dispatches buy (below 1: a partial
      //   sweep)
      {"iterations_at_8_dispatches", results::Unit::kRatio, D::kNone,
       summaryFigure([](const F& f) { return double(f.budget_iterations); })},
      // colours: count; context: independent constraint batches, 0 when not coloured
      {"colours", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.counts.colours); })},
      // colours_surface: count; context
      {"colours_surface", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.counts.colours_surface); })},
      // colours_surface_goal: count; context
      {"colours_surface_goal", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.counts.colours_surface_goal); })},
      // tile_local_fraction: ratio; context: 1 when every gather read is in-tile, 0 for a solver
      //   without tiles
      {"tile_local_fraction", results::Unit::kRatio, D::kNone,
       summaryFigure([](const F& f) { return f.counts.tile_local_fraction; })},
      // constraints: count; context
      {"constraints", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.counts.constraints); })},
      // constraint_ends: count; context
      {"constraint_ends", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.counts.constraint_ends); })},
      // initial_residual: ratio; context: the convergence frame's starting residual
      {"initial_residual", results::Unit::kRatio, D::kNone,
       summaryFigure([](const F& f) { return f.initial_residual; })},
      // final_residual_ratio: ratio to the initial residual; 0 (best), unbounded (worst)
      {"final_residual_ratio", results::Unit::kRatio, D::kLowerIsBetter,
       summaryFigure([](const F& f) { return f.final_residual_ratio; })},
      // final_position_error: ratio of the mean spring length; 0 (best), unbounded (worst)
      {"final_position_error", results::Unit::kRatio, D::kLowerIsBetter,
       summaryFigure([](const F& f) { return f.final_position_error; })},
      // reference_iterations: count; context: sweeps the double reference took
      {"reference_iterations", results::Unit::kCount, D::kNone,
       summaryFigure([](const F& f) { return double(f.reference_iterations); })},
      // reference_converged: flag; context: 1 when the reference reached its tolerance
      {"reference_converged", results::Unit::kFlag, D::kNone,
       summaryFigure([](const F& f) { return f.reference_converged ? 1.0 : 0.0; })},
  };
  return kTable;
}

ConvergenceSettings settingsFor(SuiteMode suite) {
  ConvergenceSettings settings;
  settings.dispatch_budget = kDispatchBudget;
  settings.max_iterations = 3000;
  settings.reference_max_iterations = 3000;
  if (suite == SuiteMode::kFull) {
    settings.rows = 128;
    settings.max_iterations = 20000;
    settings.reference_max_iterations = 200000;
  }
  return settings;
}

class ConvergenceMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "convergence",
        .title = "Convergence of the constraint solvers",
        .description =
            "RMS relative stretch after each solver iteration on a fixed satisfiable frame, "
            "iterations to 1e-3 and 1e-5 of the initial residual, and the residual a budget of "
            "8 GPU dispatches per frame reaches, with and without goal springs",
        .metrics = convergenceTable().specs(),
        // iterations_to_1e-3's worst counts only the rows that reached it; reached_1e-3's
        // worst (0) says when one did not.
        .headline = {"residual_at_8_dispatches_no_goal_springs",
                     "residual_at_8_dispatches_goal_springs", "iterations_to_1e-3", "reached_1e-3",
                     "dispatches_per_iteration"},
        .notes =
            {"frame: the rest pose's constraints (every spring at rest length, every goal spring "
             "on "
             "its vertex: satisfiable), from positions displaced by a hashed jitter of up to 0.3 "
             "mean spring lengths per coordinate",
             "residual: RMS over every spring of (length - rest) / rest, goal springs (rest 0) as "
             "length / mean spring length; iterations_to_1e-3 counts iterations until residual / "
             "initial residual <= 1e-3; absent with reached_1e-3 = 0 when not reached within "
             "iteration_budget",
             "position_error: RMS distance from the converged reference (serial Gauss-Seidel in "
             "double, index order, to 1e-12 of the initial residual) over the mean spring length; "
             "without goal springs the constraints have many solutions, so a solver may converge "
             "to another one",
             "8 dispatches: dispatches per iteration are the colour count for Gauss-Seidel (one "
             "batch per dispatch) and 1 for Jacobi; a coloured sweep of more than 8 colours does "
             "its first 8 (iterations_at_8_dispatches = 8 / dispatches_per_iteration < 1); "
             "gs_serial, with no GPU path, is the reference: max(1, round(8 / colours)) whole "
             "sweeps",
             "colours: the greedy colouring of every spring (in spring order: surface, inner, "
             "goal); colours_surface and colours_surface_goal colour those subsets, to set "
             "beside the Lost Planet 2 talk's 'at most 8 batches' for its DirectX 9 version "
             "(surface and goal springs only); every count is at least the largest valence",
             "solvers run in float, as the GPU; the reference in double"},
        .summary_scope = {{"kind", "summary"}},
        .plots = {results::PlotSpec{.title = "Residual against solver iterations",
                                    .kind = results::PlotKind::kLine,
                                    .x = "iteration",
                                    .y = "residual",
                                    .series = "variant",
                                    .facet = "goal_springs",
                                    .where = {{"kind", "iteration"}},
                                    .log_y = true}},
        .decision_inputs = {
            {.role = results::DecisionRole::kSolverResidual,
             .label = "residual after 8 compute dispatches",
             .metrics = {"residual_at_8_dispatches_no_goal_springs"}},
            {.role = results::DecisionRole::kSimulationFigure,
             .label = "per scenario",
             .metrics = {"residual_at_8_dispatches_no_goal_springs",
                         "residual_at_8_dispatches_goal_springs", "iterations_to_1e-3"}},
            {.role = results::DecisionRole::kDispatchesPerIteration,
             .label = "compute dispatches per iteration",
             .metrics = {"dispatches_per_iteration"},
             .where = {{"kind", "summary"}, {"goal_springs", "false"}},
             .reduce = results::DecisionReduce::kLast},
            {.role = results::DecisionRole::kResidualPerDispatch,
             .label = "residual",
             .column = "residual (ratio)",
             .metrics = {"residual"},
             .where = {{"kind", "iteration"}, {"goal_springs", "false"}},
             .chosen_key = "iteration"}}};
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
    const ConvergenceSettings settings = settingsFor(input.suite);
    for (const bool goal : {true, false}) {
      techniques::VariantInfo variant = input.variant;
      variant.parameters["goal_springs"] = goal ? 1 : 0;
      const std::unique_ptr<techniques::TechniqueInstance> instance =
          input.technique.build({nullptr, &input.simulation->scenario()}, variant);
      techniques::Simulation* simulation = instance->simulation();
      techniques::ConstraintSolver* solver = simulation ? simulation->constraintSolver() : nullptr;
      const std::string goal_key = goal ? "true" : "false";
      if (solver == nullptr) {
        result.rows.push_back(results::unmeasuredRow(
            {{"goal_springs", goal_key}, {"kind", "summary"}}, results::MeasureStatus::kSkipped,
            "the simulation has no constraint solver"));
        continue;
      }
      const ConvergenceFigures figures = measureConvergence(*solver, settings);
      results::MetricRow summary;
      summary.keys = {{"goal_springs", goal_key}, {"kind", "summary"}};
      summary.metrics = convergenceTable().metrics({&figures, nullptr, goal});
      result.rows.push_back(std::move(summary));
      for (const ConvergenceIteration& iteration : figures.iterations) {
        results::MetricRow row;
        row.keys = {{"goal_springs", goal_key},
                    {"kind", "iteration"},
                    {"iteration", std::to_string(iteration.k)}};
        row.metrics = convergenceTable().metrics({&figures, &iteration, goal});
        result.rows.push_back(std::move(row));
      }
    }
    return result;
  }
};

TB_REGISTER_MEASURE(ConvergenceMeasure);

}  // namespace
}  // namespace tb::measures
