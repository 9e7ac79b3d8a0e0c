#include "harness/suite/suite.h"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <mutex>
#include <optional>

#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "harness/suite/displacement_file.h"
#include "harness/suite/scenario_file.h"
#include "harness/suite/suite_step.h"
#include "techniques/registry.h"

namespace tb::suite {

using namespace suite_detail;

namespace {

std::string describeFaceKinds(const mesh::Mesh& mesh) {
  if (mesh.allFacesOfSize(3)) return "triangles";
  if (mesh.allFacesOfSize(4)) return "quads";
  return "mixed (max " + std::to_string(mesh.maxFaceSize()) + " vertices)";
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
std::vector<mesh::Mesh> loadAssets(const std::vector<AssetRef>& refs, results::Results* results) {
  std::vector<mesh::Mesh> meshes;
  for (const AssetRef& ref : refs) {
    mesh::Mesh mesh = loadAsset(ref);
    mesh.source = ref.shownPath();  // what warnings and skip reasons name
    results->assets.push_back({ref.name, ref.shownPath(), mesh.faceCount(), mesh.positions.size(),
                               describeFaceKinds(mesh), mesh.normals_computed,
                               mesh::connectivityWarnings(mesh, mesh::buildTopology(mesh))});
    meshes.push_back(std::move(mesh));
  }
  return meshes;
}

// The record's asset name of a displaced asset: "<asset>+<map file stem>".
std::string displacedAssetName(const measures::DisplacedInput& input) {
  const std::string stem = input.name.substr(0, input.name.rfind('.'));
  return input.asset + "+" + stem;
}

// The inputs a technique runs on: the assets for a surface technique (then the displaced
// assets baked for it), the scenarios for a simulation.
std::vector<SuiteInput> inputsFor(const techniques::Technique& technique,
                                  const std::vector<AssetRef>& refs,
                                  const std::vector<mesh::Mesh>& meshes,
                                  const std::vector<techniques::Scenario>& scenarios,
                                  const std::vector<measures::DisplacedInput>& displacements,
                                  const std::vector<const mesh::Mesh*>& displacement_meshes) {
  static const mesh::Mesh kNoMesh;
  std::vector<SuiteInput> inputs;
  if (technique.info().family == techniques::TechniqueFamily::kSimulation) {
    for (const techniques::Scenario& scenario : scenarios) {
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

// The measures of the run, the camera paths they walk, and their declarations
// (results->measures, by id).
void setUpMeasures(const SuiteSelection& selection, SuiteRun* run, results::Results* results) {
  run->measures = selection.measures;
  if (run->measures.empty()) run->measures = measures::MeasureRegistry::instance().all();
  run->suite = selection.suite;
  run->decision_figures_only = selection.decision_figures_only;
  run->view_paths = selection.camera_paths;
  if (run->view_paths.empty()) run->view_paths = {testOrbitPath};
  const bool whole_paths_needed =
      std::any_of(run->measures.begin(), run->measures.end(), [](const measures::Measure* measure) {
        return measure->requirements().has(measures::MeasureNeed::kCameraPath);
      });
  // Read only when a measure takes them, so a run without one never needs the files.
  if (whole_paths_needed) {
    run->whole_paths = selection.camera_paths;
    if (run->whole_paths.empty()) run->whole_paths = suiteCameraPaths(selection.suite);
    if (selection.camera_paths.empty() && selection.suite == measures::SuiteMode::kDefault) {
      for (const measures::Measure* measure : run->measures) {
        for (const auto& [name, frames] : measure->defaultSuitePaths()) {
          const CameraPathSpec spec = resolveCameraPath(name);
          sampleCameraPath(spec, mesh::Aabb{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}}, frames);
          run->measure_paths[measure].push_back(cameraPathFn(spec, frames));
        }
      }
    }
  }
  run->shard = selection.shard;
  run->repetitions = selection.repetitions;
  for (const measures::Measure* measure : run->measures) {
    results->measures.push_back(measures::declarationOf(measure->info()));
  }
  std::sort(results->measures.begin(), results->measures.end(),
            [](const results::MeasureDeclaration& a, const results::MeasureDeclaration& b) {
              return a.measure < b.measure;
            });
}

// The meshes of the displaced assets, one per map: the run's own mesh of the asset each
// map was baked on, or one loaded again into `extra` (reserved, so the pointers hold).
struct DisplacedMeshes {
  std::vector<mesh::Mesh> extra;
  std::vector<const mesh::Mesh*> meshes;
};

// Displaced assets: the asset each map was baked on (loaded again when the run does not
// measure it undisplaced), listed after the assets.
void loadDisplacedAssets(const SuiteSelection& selection, const std::vector<AssetRef>& refs,
                         const std::vector<mesh::Mesh>& meshes, SuiteRun* run,
                         results::Results* results, DisplacedMeshes* displaced) {
  std::vector<mesh::Mesh>& extra_meshes = displaced->extra;
  extra_meshes.reserve(selection.displacements.size());
  std::vector<const mesh::Mesh*>& displacement_meshes = displaced->meshes;
  for (const measures::DisplacedInput& input : selection.displacements) {
    const auto same = std::find_if(refs.begin(), refs.end(),
                                   [&](const AssetRef& ref) { return ref.name == input.asset; });
    const mesh::Mesh* mesh = nullptr;
    if (same != refs.end()) {
      mesh = &meshes[size_t(same - refs.begin())];
    } else {
      const AssetRef ref = resolveAsset(input.asset);
      extra_meshes.push_back(loadAsset(ref));
      extra_meshes.back().source = ref.shownPath();
      mesh = &extra_meshes.back();
    }
    displacement_meshes.push_back(mesh);
    results->assets.push_back({displacedAssetName(input), input.path, mesh->faceCount(),
                               mesh->positions.size(),
                               describeFaceKinds(*mesh) + ", displaced by " + input.name + " (" +
                                   std::string(displacement::kindName(input.map->kind)) + ", " +
                                   std::to_string(input.resolution) + " texels a patch side)",
                               mesh->normals_computed});
    run->targets.emplace(&input, std::make_unique<SuiteRun::TargetSlot>());
  }
}

// The selected scenarios; none selected: every bundled one, read only when a technique is
// a simulation.
std::vector<techniques::Scenario> scenariosFor(
    const SuiteSelection& selection, const std::vector<const techniques::Technique*>& techniques) {
  std::vector<techniques::Scenario> scenarios = selection.scenarios;
  const bool any_simulation =
      std::any_of(techniques.begin(), techniques.end(), [](const techniques::Technique* technique) {
        return technique->info().family == techniques::TechniqueFamily::kSimulation;
      });
  if (scenarios.empty() && any_simulation) scenarios = bundledScenarios();
  return scenarios;
}

// One group per technique × input: its variants run in order (default first), groups in
// parallel. Outcomes go to slots in the serial order technique, variant, input.
struct Group {
  const techniques::Technique* technique;
  std::vector<techniques::VariantInfo> variants;
  SuiteInput input;
  size_t input_index, input_count, first_slot;
  // The technique's default variant when the selection leaves it out: built (not measured)
  // for its patch data, which decide the measures of the others (VariantStanding).
  std::optional<techniques::VariantInfo> unselected_default;
};

struct GroupPlan {
  std::vector<Group> groups;
  size_t total = 0;  // steps (technique × variant × input), the outcome slots
};

// What the suite's inputs are, for the groups.
struct SuiteInputs {
  const std::vector<AssetRef>& refs;
  const std::vector<mesh::Mesh>& meshes;
  const std::vector<techniques::Scenario>& scenarios;
  const std::vector<measures::DisplacedInput>& displacements;
  const std::vector<const mesh::Mesh*>& displacement_meshes;
};

GroupPlan planGroups(const std::vector<const techniques::Technique*>& techniques,
                     const SuiteSelection& selection, const SuiteInputs& all) {
  GroupPlan plan;
  for (const techniques::Technique* technique : techniques) {
    const std::vector<techniques::VariantInfo> variants = selectedVariants(*technique, selection);
    std::optional<techniques::VariantInfo> unselected_default;
    if (const techniques::VariantInfo first = technique->variants().front();
        variants.empty() || variants.front().name != first.name) {
      unselected_default = first;
    }
    std::vector<SuiteInput> inputs = inputsFor(*technique, all.refs, all.meshes, all.scenarios,
                                               all.displacements, all.displacement_meshes);
    for (SuiteInput& input : inputs) {
      if (input.displacement) continue;
      if (input.is_asset() && !technique->checkSupport(*input.mesh).empty()) continue;
      input.first_supported = true;
      break;
    }
    for (size_t i = 0; i < inputs.size(); ++i) {
      plan.groups.push_back(
          {technique, variants, inputs[i], i, inputs.size(), plan.total, unselected_default});
    }
    plan.total += variants.size() * inputs.size();
  }
  // Every technique's inputs spread evenly over the run (ordered by the fraction of its
  // inputs done, (i + 1/2) / n), so the steps done at any moment are a fair sample of the
  // run's mix: the time left, estimated from them (cli/progress_estimate.h), is not thrown
  // off by a cheap technique's steps, or one with few inputs, coming first. The outcomes keep
  // their serial slots, so the results do not change.
  std::stable_sort(plan.groups.begin(), plan.groups.end(), [](const Group& a, const Group& b) {
    return (2 * a.input_index + 1) * b.input_count < (2 * b.input_index + 1) * a.input_count;
  });
  return plan;
}

// Runs the groups in parallel; the outcomes in the serial order.
std::vector<StepOutcome> runGroups(const SuiteRun& run, const GroupPlan& plan,
                                   const ProgressFn& progress, const RecordFn& on_record) {
  const std::vector<Group>& groups = plan.groups;
  const size_t total = plan.total;
  std::vector<StepOutcome> outcomes(total);
  std::mutex progress_mutex;
  size_t started = 0;
  // Only kWhenPatchDataDiffers measures read the default variant's patch data.
  const bool reads_default_footprint =
      std::any_of(run.measures.begin(), run.measures.end(), [](const measures::Measure* m) {
        return m->requirements().variants == measures::VariantPolicy::kWhenPatchDataDiffers;
      });
  tbb::parallel_for(
      size_t(0), groups.size(),
      [&](size_t g) {
        const Group& group = groups[g];
        // The default variant's patch data on this input, for kWhenPatchDataDiffers measures.
        std::optional<techniques::DataFootprint> default_footprint;
        if (group.unselected_default && !group.variants.empty() && reads_default_footprint) {
          default_footprint =
              patchFootprint(*group.technique, *group.unselected_default, group.input);
        }
        for (size_t v = 0; v < group.variants.size(); ++v) {
          if (progress) {
            const std::lock_guard<std::mutex> lock(progress_mutex);
            progress(
                started++, total,
                group.technique->info().id + "/" + group.variants[v].name + " " + group.input.name);
          }
          const size_t slot = group.first_slot + v * group.input_count + group.input_index;
          const bool is_default = v == 0 && !group.unselected_default;
          outcomes[slot] = runStep(run, *group.technique, group.variants[v], is_default,
                                   group.input, &default_footprint);
          if (on_record && outcomes[slot].record) {
            const std::lock_guard<std::mutex> lock(progress_mutex);
            on_record(*outcomes[slot].record);
          }
        }
      },
      tbb::simple_partitioner());
  return outcomes;
}

// The outcomes into results (skips, records) and timings, in the serial order.
void collectOutcomes(std::vector<StepOutcome>* outcomes, results::Results* results,
                     SuiteTimings* timings) {
  for (StepOutcome& outcome : *outcomes) {
    if (outcome.skip) results->skipped.push_back(std::move(*outcome.skip));
    if (outcome.record) results->records.push_back(std::move(*outcome.record));
    if (timings) {
      for (MeasureTiming& timing : outcome.timings) timings->measures.push_back(std::move(timing));
    }
  }
}

}  // namespace

std::vector<CameraPathFn> suiteCameraPaths(measures::SuiteMode mode) {
  if (mode == measures::SuiteMode::kDefault) {
    const CameraPathSpec orbit = resolveCameraPath("orbit");
    // Read at its own frame count; sampled once more at the suite's, so a path that has no
    // camera there fails here, before any measure runs.
    sampleCameraPath(orbit, mesh::Aabb{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}},
                     kDefaultSuiteOrbitFrames);
    return {cameraPathFn(orbit, kDefaultSuiteOrbitFrames)};
  }
  std::vector<CameraPathFn> paths;
  for (const char* name : {"orbit", "dolly", "flyby"}) {
    paths.push_back(cameraPathFn(resolveCameraPath(name)));
  }
  return paths;
}

std::vector<techniques::VariantInfo> selectedVariants(const techniques::Technique& technique,
                                                      const SuiteSelection& selection) {
  const auto named = selection.variants.find(technique.info().id);
  std::vector<techniques::VariantInfo> variants = technique.variants();
  std::erase_if(variants, [&](const techniques::VariantInfo& v) {
    if (named != selection.variants.end()) return !named->second.contains(v.name);
    return (v.full_suite_only && selection.suite != measures::SuiteMode::kFull) ||
           (selection.skip_controls && !v.control.empty());
  });
  return variants;
}

void runSuite(const SuiteSelection& selection, const ProgressFn& progress,
              results::Results* results, SuiteTimings* timings, const RecordFn& on_record) {
  const auto run_start = std::chrono::steady_clock::now();
  const int threads = selection.threads > 0 ? selection.threads : tbb::info::default_concurrency();
  tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  std::vector<const techniques::Technique*> techniques = selection.techniques;
  if (techniques.empty()) techniques = techniques::TechniqueRegistry::instance().all();
  SuiteRun run;
  setUpMeasures(selection, &run, results);
  std::vector<AssetRef> refs = selection.assets;
  if (refs.empty()) refs = suiteAssets(selection.suite == measures::SuiteMode::kFull);
  openDevice(selection.device_name, &run);
  const std::vector<mesh::Mesh> meshes = loadAssets(refs, results);
  DisplacedMeshes displaced;
  loadDisplacedAssets(selection, refs, meshes, &run, results, &displaced);
  const std::vector<techniques::Scenario> scenarios = scenariosFor(selection, techniques);
  const GroupPlan plan = planGroups(
      techniques, selection, {refs, meshes, scenarios, selection.displacements, displaced.meshes});
  std::vector<StepOutcome> outcomes = runGroups(run, plan, progress, on_record);
  collectOutcomes(&outcomes, results, timings);
  if (progress) progress(plan.total, plan.total, "done");
  if (timings) {
    timings->threads = threads;
    timings->repetitions = std::max(selection.repetitions, 1);
    timings->wall_seconds = secondsSince(run_start);
  }
}

}  // namespace tb::suite
