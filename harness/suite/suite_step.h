// One technique × variant × input step of runSuite (suite.cpp): what the steps share, what
// one produces, and the step itself (suite_step.cpp). Internal to harness/suite.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "harness/suite/scenario_file.h"
#include "harness/suite/suite.h"

namespace tb::suite::suite_detail {

// What one technique runs on: a loaded asset (surface techniques) or a scenario
// (simulations). `mesh` is empty for a scenario.
struct SuiteInput {
  std::string name;  // the record's asset column
  const mesh::Mesh* mesh = nullptr;
  const techniques::Scenario* scenario = nullptr;
  // A displaced asset: `mesh` displaced by this map (for its technique and variant only).
  const measures::DisplacedInput* displacement = nullptr;
  // The first input of the technique's run that it supports (checkSupport): measures
  // with MeasureRequirements::first_input_only run on it alone.
  bool first_supported = false;
  bool is_asset() const { return scenario == nullptr; }
};

// Everything a technique × variant × input step shares with the others of the run.
struct SuiteRun {
  std::vector<const measures::Measure*> measures;
  std::vector<CameraPathFn> view_paths;   // walked view by view by kView measures
  std::vector<CameraPathFn> whole_paths;  // given whole to kCameraPath measures
  // The default suite's paths of measures that declare their own (default_suite_paths).
  std::map<const measures::Measure*, std::vector<CameraPathFn>> measure_paths;
  measures::SuiteMode suite = measures::SuiteMode::kDefault;
  bool decision_figures_only = false;  // SuiteSelection::decision_figures_only
  std::unique_ptr<gpu::Context> gpu;   // null when no device is usable
  std::string gpu_unavailable;         // why, when gpu is null
  ShardSpec shard;
  int repetitions = 1;  // runs of each measure on each record
  // Each displacement map's target, rebuilt once (by the first record that needs it).
  struct TargetSlot {
    std::once_flag once;
    std::shared_ptr<const measures::DisplacementTarget> target;
    std::string unavailable;
  };
  std::map<const measures::DisplacedInput*, std::unique_ptr<TargetSlot>> targets;
};

// What one technique × variant × input step produced; steps run in parallel and their
// outcomes are put in the serial order afterwards.
struct StepOutcome {
  std::optional<results::Record> record;
  std::optional<results::Skip> skip;
  std::vector<MeasureTiming> timings;
};

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The patch data of `variant` on `input` (built, not measured): the default variant's when
// a run leaves it out, which decide the measures of the others (VariantStanding). None when
// the input is no asset, a displaced one, or one the technique cannot take.
std::optional<techniques::DataFootprint> patchFootprint(const techniques::Technique& technique,
                                                        const techniques::VariantInfo& variant,
                                                        const SuiteInput& input);

// Builds the technique on one input and variant, and runs every measure the rule admits
// into one record. `default_footprint` is the default variant's patch data on this input:
// set by the default variant's step, read by the others.
StepOutcome runStep(const SuiteRun& run, const techniques::Technique& technique,
                    const techniques::VariantInfo& variant, bool is_default,
                    const SuiteInput& input,
                    std::optional<techniques::DataFootprint>* default_footprint);

}  // namespace tb::suite::suite_detail
