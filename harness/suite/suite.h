// Runs techniques × variants × assets × measures into the results model.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/measures/measure.h"
#include "harness/results/results_model.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/camera_path.h"
#include "harness/suite/shard.h"
#include "techniques/technique.h"

namespace tb {

struct SuiteSelection {
  std::vector<const Technique*> techniques;  // empty: every registered technique
  std::vector<AssetRef> assets;              // empty: every bundled asset
  std::vector<const Measure*> measures;      // empty: every registered measure
  std::string device_name;                   // --device substring; empty: best device
  // The inputs of simulation techniques (one record per scenario, in place of the assets);
  // none bundled yet, so simulation techniques run on none by default.
  std::vector<Scenario> scenarios;
  // The paths view-dependent measures run along, around each asset's bounding box;
  // empty: the fixed test orbit (testOrbitPath).
  std::vector<CameraPathFn> camera_paths;
  // Worker threads for the run (TBB): 0 = every core. Results are byte-identical
  // whatever the count: records are assembled in the serial order.
  int threads = 0;
  ShardSpec shard;  // the slice of the work list to run (shard.h); default: all of it
};

// Wall time of one measure on one record (seconds; best 0). Timings vary run to run, so
// they never enter results.json (which is byte-stable); the CLI writes them beside it.
struct MeasureTiming {
  std::string technique, variant, asset, measure;
  double seconds = 0;
};

struct SuiteTimings {
  double wall_seconds = 0;  // the whole runSuite call, assets loading included
  int threads = 0;          // worker threads the run had
  std::vector<MeasureTiming> measures;  // in record order
};

// Called after each technique × variant × asset (or scenario) step starts: (done, total,
// label). Steps run in parallel; calls are serialised, `done` counts up.
using ProgressFn = std::function<void(size_t, size_t, const std::string&)>;

// Fills assets, records, skipped and the selected measures' declarations of `results`
// (never the context). An asset
// that fails to load aborts the run with InputError: a named asset must be
// usable. A technique that cannot take an asset is recorded as skipped, with
// its reason. Which measures run where is decided by measureRuns (measure_rule.h).
// Independent technique × input groups run in parallel (the variants of one group in
// order, since a variant's measures may depend on the default variant's patch data).
void runSuite(const SuiteSelection& selection, const ProgressFn& progress, Results* results,
              SuiteTimings* timings = nullptr);

}  // namespace tb
