// The "sim_cost" measure: what a simulation costs to run, per technique, variant and
// scenario: elements alive over time (rows keyed by time), the CPU run's peak and the
// buffers it is sized for (part = cpu), dispatches per step and the device run's resident
// bytes (part = gpu). Times per step are measured but kept out of results.json.
#include <cstdio>
#include <string>

#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "harness/measures/sim_cost/sim_cost.h"

namespace tb::measures {
namespace {

constexpr uint32_t kDefaultSamples = 4;
constexpr uint32_t kFullSamples = 12;
// Device steps: a few in the default suite (the figures kept in rows do not depend on the
// count), the whole scenario in the full suite.
constexpr uint64_t kDefaultGpuSteps = 10;

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  return text;
}

std::vector<results::MetricSpec> specs() {
  using D = results::Direction;
  return {
      // Context: how many elements the scenario has alive at the row's time.
      // elements: count; context (no best or worst)
      {"elements", results::Unit::kCount, D::kNone},
      // The most alive at once; lower is cheaper (lp2's fixed buffer caps it).
      // peak_elements: count; 0 (best), unbounded (worst)
      {"peak_elements", results::Unit::kCount, D::kLowerIsBetter},
      // steps: count; context: steps the run took
      {"steps", results::Unit::kCount, D::kNone},
      // Buffers sized for the whole run (both ping-pong copies) and the rest
      // (Simulation::footprint).
      // state_bytes: bytes; 0 (best), unbounded (worst)
      {"state_bytes", results::Unit::kBytes, D::kLowerIsBetter},
      // auxiliary_bytes: bytes; 0 (best), unbounded (worst)
      {"auxiliary_bytes", results::Unit::kBytes, D::kLowerIsBetter},
      // Passes of one step and their dispatches (passes x repeats_per_step); best 1.
      // compute_passes: count; 1 (best), unbounded (worst)
      {"compute_passes", results::Unit::kCount, D::kLowerIsBetter},
      // dispatches_per_step: count; 1 (best), unbounded (worst)
      {"dispatches_per_step", results::Unit::kCount, D::kLowerIsBetter},
      // gpu_steps: count; context: steps run on the device
      {"gpu_steps", results::Unit::kCount, D::kNone},
      // Every buffer the compute runner allocated for the programs.
      // gpu_resident_bytes: bytes; 0 (best), unbounded (worst)
      {"gpu_resident_bytes", results::Unit::kBytes, D::kLowerIsBetter},
  };
}

results::Metric metric(const char* name, double value, results::Unit unit) {
  return {name, value, std::string(toString(unit))};
}

class SimCostMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "sim_cost",
        .title = "Simulation cost",
        .description =
            "elements alive over time and at the peak, buffer bytes, compute passes and dispatches "
            "per step, and the bytes the Vulkan compute run keeps resident",
        .metrics = specs(),
        .headline = {"dispatches_per_step", "peak_elements"},
        .notes =
            {"rows keyed by time: the CPU twin's element count (SimulationState::element_count) at "
             "evenly spaced times, the last at the scenario's end",
             "part = gpu: the simulation's compute programs run by core/gpu/compute_runner (every "
             "pass of every step in one command buffer, no read-back inside the step loop) for " +
                 std::to_string(kDefaultGpuSteps) +
                 " steps in the default suite and the whole scenario in the full suite",
             "times per step (CPU twin, device) are measured but, like every timing, kept out of "
             "results.json; the suite's timings.json has the measure's wall time"},
        .summary_scope = {},
        .plots = {results::PlotSpec{.title = "Elements alive over time",
                                    .kind = results::PlotKind::kLine,
                                    .x = "time",
                                    .y = "elements",
                                    .series = "variant",
                                    .facet = "",
                                    .where = {},
                                    .log_x = false}},
        .decision_inputs = {{.role = results::DecisionRole::kSimulationFigure,
                             .label = "per scenario",
                             .metrics = {"dispatches_per_step", "peak_elements"}}}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSimulation, MeasureNeed::kGpu}, VariantPolicy::kEveryVariant, {}};
  }
  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    const bool full = input.suite == SuiteMode::kFull;
    const SimCostFigures figures =
        measureSimCost(*input.simulation, full ? kFullSamples : kDefaultSamples, input.gpu,
                       input.gpu_unavailable, full ? UINT64_MAX : kDefaultGpuSteps);
    for (const SimCostSample& sample : figures.samples) {
      results::MetricRow row;
      row.keys["time"] = shortNumber(sample.time_s);
      row.metrics = {metric("elements", double(sample.elements), results::Unit::kCount)};
      result.rows.push_back(std::move(row));
    }
    results::MetricRow cpu;
    cpu.keys["part"] = "cpu";
    cpu.metrics = {
        metric("peak_elements", double(figures.peak_elements), results::Unit::kCount),
        metric("steps", double(figures.steps), results::Unit::kCount),
        metric("state_bytes", double(figures.footprint.state_bytes), results::Unit::kBytes),
        metric("auxiliary_bytes", double(figures.footprint.auxiliary_bytes),
               results::Unit::kBytes)};
    result.rows.push_back(std::move(cpu));
    if (!figures.gpu_steps) {
      result.rows.push_back(results::unmeasuredRow(
          {{"part", "gpu"}}, results::MeasureStatus::kSkipped, figures.gpu_skip_reason));
      return result;
    }
    results::MetricRow gpu;
    gpu.keys["part"] = "gpu";
    gpu.metrics = {
        metric("compute_passes", double(figures.compute_passes), results::Unit::kCount),
        metric("dispatches_per_step", double(figures.dispatches_per_step), results::Unit::kCount),
        metric("gpu_steps", double(*figures.gpu_steps), results::Unit::kCount),
        metric("gpu_resident_bytes", double(*figures.gpu_resident_bytes), results::Unit::kBytes)};
    result.rows.push_back(std::move(gpu));
    return result;
  }
};

TB_REGISTER_MEASURE(SimCostMeasure);

}  // namespace
}  // namespace tb::measures
