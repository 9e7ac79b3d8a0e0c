#include "harness/suite/suite.h"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "harness/suite/displacement_file.h"
#include "harness/suite/measure_rule.h"
#include "harness/suite/scenario_file.h"
#include "techniques/common/displaced_patches.h"
#include "techniques/registry.h"

namespace tb {
namespace {

std::string describeFaceKinds(const Mesh& mesh) {
  if (mesh.allFacesOfSize(3)) return "triangles";
  if (mesh.allFacesOfSize(4)) return "quads";
  return "mixed (max " + std::to_string(mesh.maxFaceSize()) + " vertices)";
}

void formatParameters(const VariantInfo& variant, std::map<std::string, std::string>* out) {
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

// What one technique runs on: a loaded asset (surface techniques) or a scenario
// (simulations). `mesh` is empty for a scenario.
struct SuiteInput {
  std::string name;  // the record's asset column
  const Mesh* mesh = nullptr;
  const Scenario* scenario = nullptr;
  // A displaced asset: `mesh` displaced by this map (for its technique and variant only).
  const DisplacedInput* displacement = nullptr;
  bool is_asset() const { return scenario == nullptr; }
};

// Everything a technique × variant × input step shares with the others of the run.
struct SuiteRun {
  std::vector<const Measure*> measures;
  std::vector<CameraPathFn> view_paths;   // walked view by view by kView measures
  std::vector<CameraPathFn> whole_paths;  // given whole to kCameraPath measures
  // The default suite's paths of measures that declare their own (default_suite_paths).
  std::map<const Measure*, std::vector<CameraPathFn>> measure_paths;
  SuiteMode suite = SuiteMode::kDefault;
  std::unique_ptr<gpu::Context> gpu;  // null when no device is usable
  std::string gpu_unavailable;        // why, when gpu is null
  ShardSpec shard;
  int repetitions = 1;  // runs of each measure on each record
  // Each displacement map's target, rebuilt once (by the first record that needs it).
  struct TargetSlot {
    std::once_flag once;
    std::shared_ptr<const DisplacementTarget> target;
    std::string unavailable;
  };
  std::map<const DisplacedInput*, std::unique_ptr<TargetSlot>> targets;
};

// What one technique × variant × input step produced; steps run in parallel and their
// outcomes are put in the serial order afterwards.
struct StepOutcome {
  std::optional<Record> record;
  std::optional<Skip> skip;
  std::vector<MeasureTiming> timings;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One Vulkan device for the whole run (GPU measures share it); its absence is a reason
// each GPU measure reports, never an abort.
void openDevice(const std::string& device_name, SuiteRun* run) {
  gpu::ContextOptions options;
  options.device_name = device_name;
  auto created = gpu::Context::create(options);
  if (created) {
    run->gpu = std::move(created.value());
  } else {
    run->gpu_unavailable = created.error();
  }
}

// Loads every asset (InputError aborts the run) and lists it in results->assets.
std::vector<Mesh> loadAssets(const std::vector<AssetRef>& refs, Results* results) {
  std::vector<Mesh> meshes;
  for (const AssetRef& ref : refs) {
    Mesh mesh = loadObjFile(ref.path);
    mesh.source = ref.shownPath();  // what warnings and skip reasons name
    results->assets.push_back({ref.name, ref.shownPath(), mesh.faceCount(), mesh.positions.size(),
                               describeFaceKinds(mesh), mesh.normals_computed});
    meshes.push_back(std::move(mesh));
  }
  return meshes;
}

// Adds one run of a measure to the merged result, with `keys` added to each of its rows so
// rows of different runs never collide. The first run that is not ok gives the merged
// status and reason; the first with notes, the notes.
void mergeRun(MeasureResult one, const std::map<std::string, std::string>& keys,
              MeasureResult* merged) {
  for (MetricRow& row : one.rows) {
    for (const auto& [key, value] : keys) row.keys[key] = value;
    merged->rows.push_back(std::move(row));
  }
  if (merged->status == MeasureStatus::kOk && one.status != MeasureStatus::kOk) {
    merged->status = one.status;
    merged->reason = std::move(one.reason);
  }
  if (merged->notes.empty()) merged->notes = std::move(one.notes);
}

// Runs `measure` once per view of each camera path around the input, keyed "camera_path"
// and "view" (the index on the path).
MeasureResult runOverViews(const SuiteRun& run, const Measure& measure, MeasureInput input) {
  MeasureResult merged;
  merged.measure = measure.info().id;
  const Aabb bounds = boundsOf(input.mesh);
  for (const CameraPathFn& make_path : run.view_paths) {
    const CameraPath path = make_path(bounds);
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
MeasureResult runOverPaths(const SuiteRun& run, const Measure& measure, MeasureInput input) {
  MeasureResult merged;
  merged.measure = measure.info().id;
  const Aabb bounds = boundsOf(input.mesh);
  const std::vector<CameraPathFn>* paths = &run.whole_paths;
  if (auto own = run.measure_paths.find(&measure); own != run.measure_paths.end()) {
    paths = &own->second;
  }
  for (const CameraPathFn& make_path : *paths) {
    const CameraPath path = make_path(bounds);
    input.camera_path = &path;
    mergeRun(measure.run(input), {{"camera_path", path.name}}, &merged);
  }
  return merged;
}

// Runs one measure on a built instance. A measure that needs a simulation gets a fresh
// one (at time 0, built again) so that no measure sees another's steps.
MeasureResult runMeasure(const SuiteRun& run, const Measure& measure, MeasureInput input,
                         const TechniqueInput& technique_input, TechniqueInstance* instance) {
  const MeasureRequirements requirements = measure.requirements();
  std::unique_ptr<TechniqueInstance> fresh;
  if (requirements.has(MeasureNeed::kSimulation) ||
      (requirements.has(MeasureNeed::kSurfaceOrSimulation) && instance->simulation() != nullptr)) {
    fresh = input.technique.build(technique_input, input.variant);
    instance = fresh.get();
  }
  input.simulation = instance->simulation();
  if (requirements.has(MeasureNeed::kCameraPath)) return runOverPaths(run, measure, input);
  if (requirements.has(MeasureNeed::kView)) return runOverViews(run, measure, input);
  return measure.run(input);
}

// One run of a measure on a record. A measure that throws anything but InputError (a
// technique's evaluator throwing, a device error) fails this measure of this record only;
// the other records complete. Bad input stops the run: one line, exit 2, no folder.
MeasureResult runMeasureOnce(const SuiteRun& run, const Measure& measure,
                             const MeasureInput& input, const TechniqueInput& technique_input,
                             TechniqueInstance* instance) {
  try {
    return runMeasure(run, measure, input, technique_input, instance);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    return {measure.info().id, MeasureStatus::kFailed, error.what(), {}, {}};
  }
}

// Whether two runs of a measure gave the same result: the same statuses, reasons, notes,
// row keys and metrics, every value bit for bit (so NaN equals NaN, and 0 is not -0).
bool sameResult(const MeasureResult& a, const MeasureResult& b) {
  if (a.status != b.status || a.reason != b.reason || a.notes != b.notes ||
      a.rows.size() != b.rows.size()) {
    return false;
  }
  for (size_t r = 0; r < a.rows.size(); ++r) {
    const MetricRow& x = a.rows[r];
    const MetricRow& y = b.rows[r];
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
void recordSkip(const Technique& technique, const SuiteInput& input, bool is_default,
                const std::string& reason, const ShardSpec& shard, StepOutcome* outcome) {
  if (is_default && ownsSkip(shard, technique.info().id, input.name)) {
    outcome->skip = Skip{technique.info().id, input.name, reason};
  }
}

// The record of a technique whose build threw: each measure that may run on it, failed
// with the message.
StepOutcome failedBuild(const SuiteRun& run, const Technique& technique,
                        const VariantInfo& variant, const SuiteInput& input,
                        const VariantStanding& standing, const std::string& what) {
  StepOutcome outcome;
  Record& record = outcome.record.emplace();
  record.technique = technique.info().id;
  record.variant = variant.name;
  record.asset = input.name;
  formatParameters(variant, &record.parameters);
  for (const Measure* measure : run.measures) {
    if (measureRuns(measure->requirements(), technique, expectedCapabilities(technique),
                    standing) &&
        ownsMeasure(run.shard, record.technique, variant.name, input.name, measure->info().id)) {
      record.measures.push_back({measure->info().id, MeasureStatus::kFailed,
                                 "building the technique failed: " + what, {}, {}});
    }
  }
  if (record.measures.empty()) outcome.record.reset();
  return outcome;
}

// Builds the technique on one input and variant, and runs every measure the rule admits
// into one record. `default_footprint` is the default variant's patch data on this input:
// set by the default variant's step, read by the others.
StepOutcome runDisplacedStep(const SuiteRun& run, const Technique& technique,
                             const VariantInfo& variant, const SuiteInput& input);

StepOutcome runStep(const SuiteRun& run, const Technique& technique, const VariantInfo& variant,
                    bool is_default, const SuiteInput& input,
                    std::optional<DataFootprint>* default_footprint) {
  if (input.displacement) return runDisplacedStep(run, technique, variant, input);
  StepOutcome outcome;
  // Measures that may run, before building: no instance is built that no measure would use.
  const bool full = run.suite == SuiteMode::kFull;
  const VariantStanding maybe{
      is_default,
      default_footprint->has_value() || technique.info().family == TechniqueFamily::kSimulation,
      full, variant.evaluation_order_only};
  bool any_may_run = false;
  for (const Measure* measure : run.measures) {
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
  const TechniqueInput technique_input{input.is_asset() ? input.mesh : nullptr, input.scenario};
  std::unique_ptr<TechniqueInstance> instance;
  try {
    instance = technique.build(technique_input, variant);
  } catch (const UnsupportedInput& unsupported) {
    recordSkip(technique, input, is_default, unsupported.what(), run.shard, &outcome);
    return outcome;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    // A technique (a plug-in, say) that throws while building: its record says so, with
    // every measure that could have run failed with the message, and the run goes on.
    return failedBuild(run, technique, variant, input, maybe, error.what());
  }
  const SurfacePatches* patches = instance->surface();
  if (patches && is_default) *default_footprint = patches->footprint();
  // A simulation's variants each keep their own state (wave particles' lp2 a fixed buffer).
  const bool own_patch_data =
      is_default || (patches && *default_footprint && patches->footprint() != **default_footprint) ||
      (!patches && instance->simulation() != nullptr);
  std::vector<const Measure*> runnable;
  for (const Measure* measure : run.measures) {
    if (measureRuns(measure->requirements(), technique, capabilitiesOf(*instance),
                    {is_default, own_patch_data, full, variant.evaluation_order_only}) &&
        ownsMeasure(run.shard, technique.info().id, variant.name, input.name, measure->info().id)) {
      runnable.push_back(measure);
    }
  }
  if (runnable.empty()) return outcome;
  Record& record = outcome.record.emplace();
  record.technique = technique.info().id;
  record.variant = variant.name;
  record.asset = input.name;
  formatParameters(variant, &record.parameters);
  if (patches) {
    record.warnings = patches->warnings();
  } else if (const Simulation* simulation = instance->simulation()) {
    record.warnings = simulation->warnings();
  }
  MeasureInput measure_input{technique, variant,       input.name,         *input.mesh,
                             patches,   run.gpu.get(), run.gpu_unavailable};
  measure_input.suite = run.suite;
  for (const Measure* measure : runnable) {
    MeasureTiming timing{record.technique, record.variant, record.asset, measure->info().id, 0, {}};
    bool deterministic = true;
    for (int repetition = 0; repetition < std::max(run.repetitions, 1); ++repetition) {
      const auto start = std::chrono::steady_clock::now();
      MeasureResult result =
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

// The map's target for `patches` (undisplaced), rebuilt once per map; null with the reason
// when it cannot be.
std::pair<std::shared_ptr<const DisplacementTarget>, std::string> targetOf(
    const SuiteRun& run, const DisplacedInput& input, const SurfacePatches& patches) {
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
class BorrowedSurface final : public TechniqueInstance {
 public:
  explicit BorrowedSurface(const SurfacePatches& surface) : surface_(surface) {}
  const SurfacePatches* surface() const override { return &surface_; }

 private:
  const SurfacePatches& surface_;
};

// A displaced asset (docs/ARCHITECTURE.md, "Displaced surfaces"): the map's own technique
// and variant only, each measure that runs on displaced surfaces once per sampling (naive,
// watertight), the rows keyed `displacement` (the map's file name) and `sampling`.
StepOutcome runDisplacedStep(const SuiteRun& run, const Technique& technique,
                             const VariantInfo& variant, const SuiteInput& input) {
  StepOutcome outcome;
  const DisplacedInput& map = *input.displacement;
  if (variant.name != map.variant) return outcome;
  std::vector<const Measure*> runnable;
  for (const Measure* measure : run.measures) {
    if (measure->requirements().displaced_surfaces &&
        ownsMeasure(run.shard, technique.info().id, variant.name, input.name, measure->info().id)) {
      runnable.push_back(measure);
    }
  }
  if (runnable.empty()) return outcome;
  if (std::string reason = technique.checkSupport(*input.mesh); !reason.empty()) {
    throw InputError(map.path, "", "baked for " + map.technique + " on " + map.asset +
                                       ", which refuses the asset: " + reason);
  }
  const TechniqueInput technique_input{input.mesh, nullptr};
  const std::unique_ptr<TechniqueInstance> undisplaced = technique.build(technique_input, variant);
  if (undisplaced->surface() == nullptr) {
    throw InputError(map.path, "", map.technique + " has no surface to displace");
  }
  const auto [target, target_unavailable] = targetOf(run, map, *undisplaced->surface());
  Record& record = outcome.record.emplace();
  record.technique = technique.info().id;
  record.variant = variant.name;
  record.asset = input.name;
  formatParameters(variant, &record.parameters);
  record.parameters["displacement"] = map.name;
  std::vector<MeasureResult> merged(runnable.size());
  std::vector<MeasureTiming> timings(runnable.size());
  for (size_t m = 0; m < runnable.size(); ++m) {
    merged[m].measure = runnable[m]->info().id;
    timings[m] = {record.technique, record.variant, record.asset, merged[m].measure, 0, {0.0}};
  }
  for (DisplacementSampling sampling :
       {DisplacementSampling::kNaive, DisplacementSampling::kWatertight}) {
    // Both samplings wrap the one build of the technique's patches (the wrapper only reads
    // them).
    const DisplacedPatches displaced(*undisplaced->surface(), map.map, sampling, map.name);
    BorrowedSurface instance(displaced);
    const DisplacementRun displacement{&map, sampling, target, target_unavailable};
    if (record.warnings.empty()) record.warnings = instance.surface()->warnings();
    MeasureInput measure_input{technique, variant,       input.name,         *input.mesh,
                               instance.surface(), run.gpu.get(), run.gpu_unavailable};
    measure_input.suite = run.suite;
    measure_input.displacement = &displacement;
    for (size_t m = 0; m < runnable.size(); ++m) {
      const auto start = std::chrono::steady_clock::now();
      MeasureResult result = runMeasureOnce(run, *runnable[m], measure_input, technique_input,
                                            &instance);
      timings[m].samples[0] += secondsSince(start);
      mergeRun(std::move(result), {{"displacement", map.name}, {"sampling", samplingName(sampling)}},
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

// The record's asset name of a displaced asset: "<asset>+<map file stem>".
std::string displacedAssetName(const DisplacedInput& input) {
  const std::string stem = input.name.substr(0, input.name.rfind('.'));
  return input.asset + "+" + stem;
}

// The inputs a technique runs on: the assets for a surface technique (then the displaced
// assets baked for it), the scenarios for a simulation.
std::vector<SuiteInput> inputsFor(const Technique& technique, const std::vector<AssetRef>& refs,
                                  const std::vector<Mesh>& meshes,
                                  const std::vector<Scenario>& scenarios,
                                  const std::vector<DisplacedInput>& displacements,
                                  const std::vector<const Mesh*>& displacement_meshes) {
  static const Mesh kNoMesh;
  std::vector<SuiteInput> inputs;
  if (technique.info().family == TechniqueFamily::kSimulation) {
    for (const Scenario& scenario : scenarios) {
      if (scenario.technique.empty() || scenario.technique == technique.info().id) {
        inputs.push_back({scenario.name, &kNoMesh, &scenario});
      }
    }
  } else {
    for (size_t a = 0; a < refs.size(); ++a) inputs.push_back({refs[a].name, &meshes[a], nullptr});
    for (size_t d = 0; d < displacements.size(); ++d) {
      if (displacements[d].technique != technique.info().id) continue;
      inputs.push_back({displacedAssetName(displacements[d]), displacement_meshes[d], nullptr,
                        &displacements[d]});
    }
  }
  return inputs;
}

}  // namespace

std::vector<CameraPathFn> suiteCameraPaths(SuiteMode mode) {
  if (mode == SuiteMode::kDefault) {
    const CameraPathSpec orbit = resolveCameraPath("orbit");
    // Read at its own frame count; sampled once more at the suite's, so a path that has no
    // camera there fails here, before any measure runs.
    sampleCameraPath(orbit, Aabb{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}}, kDefaultSuiteOrbitFrames);
    return {cameraPathFn(orbit, kDefaultSuiteOrbitFrames)};
  }
  std::vector<CameraPathFn> paths;
  for (const char* name : {"orbit", "dolly", "flyby"}) {
    paths.push_back(cameraPathFn(resolveCameraPath(name)));
  }
  return paths;
}

void runSuite(const SuiteSelection& selection, const ProgressFn& progress, Results* results,
              SuiteTimings* timings, const RecordFn& on_record) {
  const auto run_start = std::chrono::steady_clock::now();
  const int threads =
      selection.threads > 0 ? selection.threads : tbb::info::default_concurrency();
  tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  std::vector<const Technique*> techniques = selection.techniques;
  if (techniques.empty()) techniques = TechniqueRegistry::instance().all();
  SuiteRun run;
  run.measures = selection.measures;
  if (run.measures.empty()) run.measures = MeasureRegistry::instance().all();
  run.suite = selection.suite;
  run.view_paths = selection.camera_paths;
  if (run.view_paths.empty()) run.view_paths = {testOrbitPath};
  const bool whole_paths_needed =
      std::any_of(run.measures.begin(), run.measures.end(), [](const Measure* measure) {
        return measure->requirements().has(MeasureNeed::kCameraPath);
      });
  // Read only when a measure takes them, so a run without one never needs the files.
  if (whole_paths_needed) {
    run.whole_paths = selection.camera_paths;
    if (run.whole_paths.empty()) run.whole_paths = suiteCameraPaths(selection.suite);
    if (selection.camera_paths.empty() && selection.suite == SuiteMode::kDefault) {
      for (const Measure* measure : run.measures) {
        for (const auto& [name, frames] : measure->defaultSuitePaths()) {
          const CameraPathSpec spec = resolveCameraPath(name);
          sampleCameraPath(spec, Aabb{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}}, frames);
          run.measure_paths[measure].push_back(cameraPathFn(spec, frames));
        }
      }
    }
  }
  run.shard = selection.shard;
  run.repetitions = selection.repetitions;
  for (const Measure* measure : run.measures) {
    results->measures.push_back(declarationOf(measure->info()));
  }
  std::sort(results->measures.begin(), results->measures.end(),
            [](const MeasureDeclaration& a, const MeasureDeclaration& b) {
              return a.measure < b.measure;
            });
  std::vector<AssetRef> refs = selection.assets;
  if (refs.empty()) refs = suiteAssets(selection.suite == SuiteMode::kFull);
  openDevice(selection.device_name, &run);
  const std::vector<Mesh> meshes = loadAssets(refs, results);
  // Displaced assets: the asset each map was baked on (loaded again when the run does not
  // measure it undisplaced), listed after the assets.
  std::vector<Mesh> extra_meshes;
  extra_meshes.reserve(selection.displacements.size());
  std::vector<const Mesh*> displacement_meshes;
  for (const DisplacedInput& input : selection.displacements) {
    const auto same = std::find_if(refs.begin(), refs.end(),
                                   [&](const AssetRef& ref) { return ref.name == input.asset; });
    const Mesh* mesh = nullptr;
    if (same != refs.end()) {
      mesh = &meshes[size_t(same - refs.begin())];
    } else {
      const AssetRef ref = resolveAsset(input.asset);
      extra_meshes.push_back(loadObjFile(ref.path));
      extra_meshes.back().source = ref.shownPath();
      mesh = &extra_meshes.back();
    }
    displacement_meshes.push_back(mesh);
    results->assets.push_back({displacedAssetName(input), input.path, mesh->faceCount(),
                               mesh->positions.size(),
                               describeFaceKinds(*mesh) + ", displaced by " + input.name + " (" +
                                   std::string(kindName(input.map->kind)) + ", " +
                                   std::to_string(input.resolution) + " texels a patch side)",
                               mesh->normals_computed});
    run.targets.emplace(&input, std::make_unique<SuiteRun::TargetSlot>());
  }
  std::vector<Scenario> scenarios = selection.scenarios;
  const bool any_simulation =
      std::any_of(techniques.begin(), techniques.end(), [](const Technique* technique) {
        return technique->info().family == TechniqueFamily::kSimulation;
      });
  if (scenarios.empty() && any_simulation) scenarios = bundledScenarios();

  // One group per technique × input: its variants run in order (default first), groups in
  // parallel. Outcomes go to slots in the serial order technique, variant, input.
  struct Group {
    const Technique* technique;
    std::vector<VariantInfo> variants;
    SuiteInput input;
    size_t input_index, input_count, first_slot;
  };
  std::vector<Group> groups;
  size_t total = 0;
  for (const Technique* technique : techniques) {
    std::vector<VariantInfo> variants = technique->variants();
    if (selection.suite != SuiteMode::kFull) {
      std::erase_if(variants, [](const VariantInfo& v) { return v.full_suite_only; });
    }
    const std::vector<SuiteInput> inputs = inputsFor(*technique, refs, meshes, scenarios,
                                                     selection.displacements, displacement_meshes);
    for (size_t i = 0; i < inputs.size(); ++i) {
      groups.push_back({technique, variants, inputs[i], i, inputs.size(), total});
    }
    total += variants.size() * inputs.size();
  }
  std::vector<StepOutcome> outcomes(total);
  std::mutex progress_mutex;
  size_t started = 0;
  tbb::parallel_for(size_t(0), groups.size(), [&](size_t g) {
    const Group& group = groups[g];
    // The default variant's patch data on this input, for kWhenPatchDataDiffers measures.
    std::optional<DataFootprint> default_footprint;
    for (size_t v = 0; v < group.variants.size(); ++v) {
      if (progress) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        progress(started++, total,
                 group.technique->info().id + "/" + group.variants[v].name + " " +
                     group.input.name);
      }
      const size_t slot = group.first_slot + v * group.input_count + group.input_index;
      outcomes[slot] = runStep(run, *group.technique, group.variants[v], v == 0, group.input,
                               &default_footprint);
      if (on_record && outcomes[slot].record) {
        const std::lock_guard<std::mutex> lock(progress_mutex);
        on_record(*outcomes[slot].record);
      }
    }
  }, tbb::simple_partitioner());
  for (StepOutcome& outcome : outcomes) {
    if (outcome.skip) results->skipped.push_back(std::move(*outcome.skip));
    if (outcome.record) results->records.push_back(std::move(*outcome.record));
    if (timings) {
      for (MeasureTiming& timing : outcome.timings) timings->measures.push_back(std::move(timing));
    }
  }
  if (progress) progress(total, total, "done");
  if (timings) {
    timings->threads = threads;
    timings->repetitions = std::max(selection.repetitions, 1);
    timings->wall_seconds = secondsSince(run_start);
  }
}

}  // namespace tb
