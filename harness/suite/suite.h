// Runs techniques × variants × assets × measures into the results model.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "harness/measures/displaced_input.h"
#include "harness/measures/measure.h"
#include "harness/results/results_model.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/camera_path.h"
#include "harness/suite/shard.h"
#include "techniques/technique.h"

namespace tb::suite {

struct SuiteSelection {
  std::vector<const techniques::Technique*> techniques;  // empty: every registered technique
  std::vector<AssetRef> assets;                          // empty: every bundled asset
  std::vector<const measures::Measure*> measures;        // empty: every registered measure
  std::string device_name;                               // --device substring; empty: best device
  // The inputs of simulation techniques (one record per scenario, in place of the assets).
  // Empty: every bundled scenario (assets/scenarios, scenario_file.h), read only when a
  // selected technique is a simulation. A technique runs only on the scenarios whose
  // `technique` is its id or empty.
  std::vector<techniques::Scenario> scenarios;
  // Displacement maps (harness/suite/displacement_file.h): each adds a displaced asset, its
  // sidecar's asset displaced by the map, run by its technique and variant with the measures
  // that run on displaced surfaces (cracks, error, memory).
  std::vector<measures::DisplacedInput> displacements;
  // The paths view-dependent measures run along, around each asset's bounding box, for
  // kView and kCameraPath measures alike (`run --camera`). Empty: kView measures get the
  // fixed test orbit (testOrbitPath), kCameraPath measures suiteCameraPaths(suite).
  std::vector<CameraPathFn> camera_paths;
  // Which grid measures run (`run --suite`), and which paths kCameraPath measures get when
  // camera_paths is empty.
  measures::SuiteMode suite = measures::SuiteMode::kDefault;
  // Worker threads for the run (TBB): 0 = every core. Results are byte-identical
  // whatever the count: records are assembled in the serial order.
  int threads = 0;
  ShardSpec shard;  // the slice of the work list to run (shard.h); default: all of it
  // Runs of each measure on each record (`run --repetitions`), each timed: the record keeps
  // the first run's result, and a warning when a later run's differs (a measure must be
  // deterministic); the samples feed compare's U test. At least 1.
  int repetitions = 1;
  // `advise`: no control variant (techniques::VariantInfo::control) is measured, and measures
  // compute only the figures a decision reads (MeasureInput::decision_figures_only).
  bool skip_controls = false;
  bool decision_figures_only = false;
  // `run --technique ID/VARIANT`: per technique id, the only variants to run (a variant
  // named here runs even when it is full-suite only). A technique absent runs every
  // variant its suite runs.
  std::map<std::string, std::set<std::string>> variants;
};

// The variants of `technique` that a run with `selection` measures, in the technique's
// order: its suite's (no full-suite-only ones in the default suite, no controls with
// skip_controls), narrowed by SuiteSelection::variants.
std::vector<techniques::VariantInfo> selectedVariants(const techniques::Technique& technique,
                                                      const SuiteSelection& selection);

// Frames the bundled orbit is sampled to for kCameraPath measures in the default suite
// (its file has 24): enough to see factors change around the asset, within the suite's
// time budget (docs/ARCHITECTURE.md, section 3).
constexpr uint32_t kDefaultSuiteOrbitFrames = 4;

// The paths kCameraPath measures run along when SuiteSelection::camera_paths is empty: the
// default suite, the bundled "orbit" at kDefaultSuiteOrbitFrames frames; the full suite,
// "orbit", "dolly" and "flyby" at their own frame counts. Throws InputError when a bundled
// file is missing or bad.
std::vector<CameraPathFn> suiteCameraPaths(measures::SuiteMode mode);

// Wall time of one measure on one record (seconds; best 0). Timings vary run to run, so
// they never enter results.json (which is byte-stable); the CLI writes them beside it.
struct MeasureTiming {
  std::string technique, variant, asset, measure;
  double seconds = 0;  // the first run's
  // Every run's, in order (SuiteSelection::repetitions of them; samples[0] == seconds). The
  // first run may be slower: process-wide caches (boundary tessellations, shader counts) fill.
  std::vector<double> samples;
};

struct SuiteTimings {
  double wall_seconds = 0;              // the whole runSuite call, assets loading included
  int threads = 0;                      // worker threads the run had
  int repetitions = 1;                  // SuiteSelection::repetitions
  std::vector<MeasureTiming> measures;  // in record order
};

// Called after each technique × variant × asset (or scenario) step starts: (done, total,
// label). Steps run in parallel; calls are serialised, `done` counts up.
using ProgressFn = std::function<void(size_t, size_t, const std::string&)>;

// Called with each record as soon as its measures are done, in completion order (not the
// serial order of results.records); calls are serialised. An exception it throws stops the
// run and leaves runSuite.
using RecordFn = std::function<void(const results::Record&)>;

// Fills assets, records, skipped and the selected measures' declarations of `results`
// (never the context). An asset
// that fails to load aborts the run with InputError: a named asset must be
// usable. A technique that cannot take an asset is recorded as skipped, with
// its reason. Which measures run where is decided by measureRuns (measure_rule.h).
// Independent technique × input groups run in parallel (the variants of one group in
// order, since a variant's measures may depend on the default variant's patch data).
void runSuite(const SuiteSelection& selection, const ProgressFn& progress,
              results::Results* results, SuiteTimings* timings = nullptr,
              const RecordFn& on_record = {});

}  // namespace tb::suite
