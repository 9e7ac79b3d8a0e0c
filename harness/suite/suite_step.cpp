// One technique × variant × input step of the suite (suite_step.h): the build, each measure
// run (over views or camera paths, repeated), and the steps of displaced assets.
#include "harness/suite/suite_step.h"

#include <algorithm>
#include <bit>
#include <cstdio>

#include "core/mesh/input_error.h"
#include "harness/suite/displacement_file.h"
#include "harness/suite/measure_rule.h"
#include "techniques/common/displaced_patches.h"

namespace tb::suite::suite_detail {
namespace {

void formatParameters(const techniques::VariantInfo& variant,
                      std::map<std::string, std::string>* out) {
  for (const auto& [key, value] : variant.parameters) {
    // Shortest text that round-trips, so the JSON stays byte-stable.
    char text[32];
    double parsed = 0;
    for (int precision = 1; precision <= 17; ++precision) {
      std::snprintf(text, sizeof(text), "%.*g", precision, value);
      std::sscanf(text, "%lf", &parsed);
      if (parsed == value) break;
    }
    (*out)[key] = text;
  }
}

// Adds one run of a measure to the merged result, with `keys` added to each of its rows so
// rows of different runs never collide. The first run that is not ok gives the merged
// status and reason; the first with notes, the notes.
void mergeRun(results::MeasureResult one, const std::map<std::string, std::string>& keys,
              results::MeasureResult* merged) {
  for (results::MetricRow& row : one.rows) {
    for (const auto& [key, value] : keys) row.keys[key] = value;
    merged->rows.push_back(std::move(row));
  }
  if (merged->status == results::MeasureStatus::kOk && one.status != results::MeasureStatus::kOk) {
    merged->status = one.status;
    merged->reason = std::move(one.reason);
  }
  if (merged->notes.empty()) merged->notes = std::move(one.notes);
}

// Runs `measure` once per view of each camera path around the input, keyed "camera_path"
// and "view" (the index on the path).
results::MeasureResult runOverViews(const SuiteRun& run, const measures::Measure& measure,
                                    measures::MeasureInput input) {
  results::MeasureResult merged;
  merged.measure = measure.info().id;
  const mesh::Aabb bounds = mesh::boundsOf(input.mesh);
  for (const CameraPathFn& make_path : run.view_paths) {
    const view::CameraPath path = make_path(bounds);
    for (size_t v = 0; v < path.views.size(); ++v) {
      input.view = &path.views[v];
      mergeRun(measure.run(input), {{"camera_path", path.name}, {"view", std::to_string(v)}},
               &merged);
    }
  }
  return merged;
}

// Runs `measure` once per camera path around the input, with the whole path, keyed
// "camera_path"; the measure keys its rows by frame itself.
results::MeasureResult runOverPaths(const SuiteRun& run, const measures::Measure& measure,
                                    measures::MeasureInput input) {
  results::MeasureResult merged;
  merged.measure = measure.info().id;
  const mesh::Aabb bounds = mesh::boundsOf(input.mesh);
  const std::vector<CameraPathFn>* paths = &run.whole_paths;
  if (auto own = run.measure_paths.find(&measure); own != run.measure_paths.end()) {
    paths = &own->second;
  }
  std::vector<view::CameraPath> made;
  for (const CameraPathFn& make_path : *paths) made.push_back(make_path(bounds));
  std::vector<results::MeasureResult> results = measure.runPaths(input, made);
  for (size_t k = 0; k < made.size(); ++k) {
    mergeRun(std::move(results.at(k)), {{"camera_path", made[k].name}}, &merged);
  }
  return merged;
}

// Runs one measure on a built instance. A measure that needs a simulation gets a fresh
// one (at time 0, built again) so that no measure sees another's steps.
results::MeasureResult runMeasure(const SuiteRun& run, const measures::Measure& measure,
                                  measures::MeasureInput input,
                                  const techniques::TechniqueInput& technique_input,
                                  techniques::TechniqueInstance* instance) {
  const measures::MeasureRequirements requirements = measure.requirements();
  std::unique_ptr<techniques::TechniqueInstance> fresh;
  if (requirements.has(measures::MeasureNeed::kSimulation) ||
      (requirements.has(measures::MeasureNeed::kSurfaceOrSimulation) &&
       instance->simulation() != nullptr)) {
    fresh = input.technique.build(technique_input, input.variant);
    instance = fresh.get();
  }
  input.simulation = instance->simulation();
  if (requirements.has(measures::MeasureNeed::kCameraPath))
    return runOverPaths(run, measure, input);
  if (requirements.has(measures::MeasureNeed::kView)) return runOverViews(run, measure, input);
  return measure.run(input);
}

// One run of a measure on a record. A measure that throws anything but InputError (a
// technique's evaluator throwing, a device error) fails this measure of this record only;
// the other records complete. Bad input stops the run: one line, exit 2, no folder.
results::MeasureResult runMeasureOnce(const SuiteRun& run, const measures::Measure& measure,
                                      const measures::MeasureInput& input,
                                      const techniques::TechniqueInput& technique_input,
                                      techniques::TechniqueInstance* instance) {
  try {
    return runMeasure(run, measure, input, technique_input, instance);
  } catch (const mesh::InputError&) {
    throw;
  } catch (const std::exception& error) {
    return {measure.info().id, results::MeasureStatus::kFailed, error.what(), {}, {}};
  }
}

// Whether two runs of a measure gave the same result: the same statuses, reasons, notes,
// row keys and metrics, every value bit for bit (so NaN equals NaN, and 0 is not -0).
bool sameResult(const results::MeasureResult& a, const results::MeasureResult& b) {
  if (a.status != b.status || a.reason != b.reason || a.notes != b.notes ||
      a.rows.size() != b.rows.size()) {
    return false;
  }
  for (size_t r = 0; r < a.rows.size(); ++r) {
    const results::MetricRow& x = a.rows[r];
    const results::MetricRow& y = b.rows[r];
    if (x.keys != y.keys || x.status != y.status || x.reason != y.reason ||
        x.metrics.size() != y.metrics.size()) {
      return false;
    }
    for (size_t m = 0; m < x.metrics.size(); ++m) {
      if (x.metrics[m].name != y.metrics[m].name || x.metrics[m].unit != y.metrics[m].unit ||
          std::bit_cast<uint64_t>(x.metrics[m].value) !=
              std::bit_cast<uint64_t>(y.metrics[m].value)) {
        return false;
      }
    }
  }
  return true;
}

// Records a technique that cannot take the input (on the default variant only, once).
void recordSkip(const techniques::Technique& technique, const SuiteInput& input, bool is_default,
                const std::string& reason, const ShardSpec& shard, StepOutcome* outcome) {
  if (is_default && ownsSkip(shard, technique.info().id, input.name)) {
    outcome->skip = results::Skip{technique.info().id, input.name, reason};
  }
}

// The record of a technique whose build threw: each measure that may run on it, failed
// with the message.
StepOutcome failedBuild(const SuiteRun& run, const techniques::Technique& technique,
                        const techniques::VariantInfo& variant, const SuiteInput& input,
                        const VariantStanding& standing, const std::string& what) {
  StepOutcome outcome;
  results::Record& record = outcome.record.emplace();
  record.technique = technique.info().id;
  record.variant = variant.name;
  record.asset = input.name;
  formatParameters(variant, &record.parameters);
  for (const measures::Measure* measure : run.measures) {
    if (measureRuns(measure->requirements(), technique, expectedCapabilities(technique),
                    standing) &&
        ownsMeasure(run.shard, record.technique, variant.name, input.name, measure->info().id)) {
      record.measures.push_back({measure->info().id,
                                 results::MeasureStatus::kFailed,
                                 "building the technique failed: " + what,
                                 {},
                                 {}});
    }
  }
  if (record.measures.empty()) outcome.record.reset();
  return outcome;
}

StepOutcome runDisplacedStep(const SuiteRun& run, const techniques::Technique& technique,
                             const techniques::VariantInfo& variant, const SuiteInput& input);

}  // namespace

std::optional<techniques::DataFootprint> patchFootprint(const techniques::Technique& technique,
                                                        const techniques::VariantInfo& variant,
                                                        const SuiteInput& input) {
  if (!input.is_asset() || input.displacement || !technique.checkSupport(*input.mesh).empty()) {
    return std::nullopt;
  }
  try {
    const std::unique_ptr<techniques::TechniqueInstance> instance =
        technique.build({input.mesh, nullptr}, variant);
    if (const techniques::SurfacePatches* patches = instance->surface()) {
      return patches->footprint();
    }
  } catch (const mesh::InputError&) {
    throw;
  } catch (const std::exception&) {
    // Unsupported or failed: the measured variants' steps report their own builds.
  }
  return std::nullopt;
}

StepOutcome runStep(const SuiteRun& run, const techniques::Technique& technique,
                    const techniques::VariantInfo& variant, bool is_default,
                    const SuiteInput& input,
                    std::optional<techniques::DataFootprint>* default_footprint) {
  if (input.displacement) return runDisplacedStep(run, technique, variant, input);
  StepOutcome outcome;
  // Measures that may run, before building: no instance is built that no measure would use.
  const bool full = run.suite == measures::SuiteMode::kFull;
  const VariantStanding maybe{
      is_default,
      default_footprint->has_value() ||
          technique.info().family == techniques::TechniqueFamily::kSimulation,
      full, variant.evaluation_order_only, input.first_supported};
  bool any_may_run = false;
  for (const measures::Measure* measure : run.measures) {
    any_may_run |=
        measureRuns(measure->requirements(), technique, expectedCapabilities(technique), maybe);
  }
  if (!any_may_run) return outcome;
  if (input.is_asset()) {
    if (std::string reason = technique.checkSupport(*input.mesh); !reason.empty()) {
      recordSkip(technique, input, is_default, reason, run.shard, &outcome);
      return outcome;
    }
  }
  const techniques::TechniqueInput technique_input{input.is_asset() ? input.mesh : nullptr,
                                                   input.scenario};
  std::unique_ptr<techniques::TechniqueInstance> instance;
  try {
    instance = technique.build(technique_input, variant);
  } catch (const techniques::UnsupportedInput& unsupported) {
    recordSkip(technique, input, is_default, unsupported.what(), run.shard, &outcome);
    return outcome;
  } catch (const mesh::InputError&) {
    throw;
  } catch (const std::exception& error) {
    // A technique (a plug-in, say) that throws while building: its record says so, with
    // every measure that could have run failed with the message, and the run goes on.
    return failedBuild(run, technique, variant, input, maybe, error.what());
  }
  const techniques::SurfacePatches* patches = instance->surface();
  if (patches && is_default) *default_footprint = patches->footprint();
  // A simulation's variants each keep their own state (wave particles' lp2 a fixed buffer).
  const bool own_patch_data =
      is_default ||
      (patches && *default_footprint && patches->footprint() != **default_footprint) ||
      (!patches && instance->simulation() != nullptr);
  std::vector<const measures::Measure*> runnable;
  for (const measures::Measure* measure : run.measures) {
    if (measureRuns(measure->requirements(), technique, capabilitiesOf(*instance),
                    {is_default, own_patch_data, full, variant.evaluation_order_only,
                     input.first_supported}) &&
        ownsMeasure(run.shard, technique.info().id, variant.name, input.name, measure->info().id)) {
      runnable.push_back(measure);
    }
  }
  if (runnable.empty()) return outcome;
  results::Record& record = outcome.record.emplace();
  record.technique = technique.info().id;
  record.variant = variant.name;
  record.asset = input.name;
  formatParameters(variant, &record.parameters);
  if (patches) {
    record.warnings = patches->warnings();
  } else if (const techniques::Simulation* simulation = instance->simulation()) {
    record.warnings = simulation->warnings();
  }
  measures::MeasureInput measure_input{technique, variant,       input.name,         *input.mesh,
                                       patches,   run.gpu.get(), run.gpu_unavailable};
  measure_input.suite = run.suite;
  measure_input.decision_figures_only = run.decision_figures_only;
  for (const measures::Measure* measure : runnable) {
    MeasureTiming timing{record.technique, record.variant, record.asset, measure->info().id, 0, {}};
    bool deterministic = true;
    for (int repetition = 0; repetition < std::max(run.repetitions, 1); ++repetition) {
      const auto start = std::chrono::steady_clock::now();
      results::MeasureResult result =
          runMeasureOnce(run, *measure, measure_input, technique_input, instance.get());
      timing.samples.push_back(secondsSince(start));
      if (repetition == 0) {
        record.measures.push_back(std::move(result));
      } else if (deterministic && !sameResult(record.measures.back(), result)) {
        deterministic = false;
        record.warnings.push_back("measure " + measure->info().id +
                                  " is not deterministic across repetitions");
      }
    }
    timing.seconds = timing.samples.front();
    outcome.timings.push_back(std::move(timing));
  }
  return outcome;
}

namespace {

// The map's target for `patches` (undisplaced), rebuilt once per map; null with the reason
// when it cannot be.
std::pair<std::shared_ptr<const measures::DisplacementTarget>, std::string> targetOf(
    const SuiteRun& run, const measures::DisplacedInput& input,
    const techniques::SurfacePatches& patches) {
  SuiteRun::TargetSlot& slot = *run.targets.at(&input);
  std::call_once(slot.once, [&] {
    try {
      slot.target = rebuildTarget(input, patches);
    } catch (const std::exception& error) {
      slot.unavailable = error.what();
    }
  });
  return {slot.target, slot.unavailable};
}

// An instance whose surface lives elsewhere (a DisplacedPatches over a build of the step).
class BorrowedSurface final : public techniques::TechniqueInstance {
 public:
  explicit BorrowedSurface(const techniques::SurfacePatches& surface) : surface_(surface) {}
  const techniques::SurfacePatches* surface() const override { return &surface_; }

 private:
  const techniques::SurfacePatches& surface_;
};

// A displaced asset (docs/derivations/displacement.md): the map's own technique
// and variant only, each measure that runs on displaced surfaces once per sampling (naive,
// watertight), the rows keyed `displacement` (the map's file name) and `sampling`.
StepOutcome runDisplacedStep(const SuiteRun& run, const techniques::Technique& technique,
                             const techniques::VariantInfo& variant, const SuiteInput& input) {
  StepOutcome outcome;
  const measures::DisplacedInput& map = *input.displacement;
  if (variant.name != map.variant) return outcome;
  std::vector<const measures::Measure*> runnable;
  for (const measures::Measure* measure : run.measures) {
    if (measure->requirements().displaced_surfaces &&
        ownsMeasure(run.shard, technique.info().id, variant.name, input.name, measure->info().id)) {
      runnable.push_back(measure);
    }
  }
  if (runnable.empty()) return outcome;
  if (std::string reason = technique.checkSupport(*input.mesh); !reason.empty()) {
    throw mesh::InputError(
        map.path, "",
        "baked for " + map.technique + " on " + map.asset + ", which refuses the asset: " + reason);
  }
  const techniques::TechniqueInput technique_input{input.mesh, nullptr};
  const std::unique_ptr<techniques::TechniqueInstance> undisplaced =
      technique.build(technique_input, variant);
  if (undisplaced->surface() == nullptr) {
    throw mesh::InputError(map.path, "", map.technique + " has no surface to displace");
  }
  const auto [target, target_unavailable] = targetOf(run, map, *undisplaced->surface());
  results::Record& record = outcome.record.emplace();
  record.technique = technique.info().id;
  record.variant = variant.name;
  record.asset = input.name;
  formatParameters(variant, &record.parameters);
  record.parameters["displacement"] = map.name;
  std::vector<results::MeasureResult> merged(runnable.size());
  std::vector<MeasureTiming> timings(runnable.size());
  for (size_t m = 0; m < runnable.size(); ++m) {
    merged[m].measure = runnable[m]->info().id;
    timings[m] = {record.technique, record.variant, record.asset, merged[m].measure, 0, {0.0}};
  }
  for (techniques::DisplacementSampling sampling :
       {techniques::DisplacementSampling::kNaive, techniques::DisplacementSampling::kWatertight}) {
    // Both samplings wrap the one build of the technique's patches (the wrapper only reads
    // them).
    const techniques::DisplacedPatches displaced(*undisplaced->surface(), map.map, sampling,
                                                 map.name);
    BorrowedSurface instance(displaced);
    const measures::DisplacementRun displacement{&map, sampling, target, target_unavailable};
    if (record.warnings.empty()) record.warnings = instance.surface()->warnings();
    measures::MeasureInput measure_input{
        technique,          variant,       input.name,         *input.mesh,
        instance.surface(), run.gpu.get(), run.gpu_unavailable};
    measure_input.suite = run.suite;
    measure_input.decision_figures_only = run.decision_figures_only;
    measure_input.displacement = &displacement;
    for (size_t m = 0; m < runnable.size(); ++m) {
      const auto start = std::chrono::steady_clock::now();
      results::MeasureResult result =
          runMeasureOnce(run, *runnable[m], measure_input, technique_input, &instance);
      timings[m].samples[0] += secondsSince(start);
      mergeRun(std::move(result),
               {{"displacement", map.name}, {"sampling", techniques::samplingName(sampling)}},
               &merged[m]);
    }
  }
  record.measures = std::move(merged);
  for (MeasureTiming& timing : timings) {
    timing.seconds = timing.samples[0];
    outcome.timings.push_back(std::move(timing));
  }
  return outcome;
}

}  // namespace
}  // namespace tb::suite::suite_detail
