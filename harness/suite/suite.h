// Runs techniques × variants × assets × measures into the results model.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/measures/measure.h"
#include "harness/results/results_model.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/camera_path.h"
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
};

// Called before each technique × variant × asset (or scenario) step: (done, total, label).
using ProgressFn = std::function<void(size_t, size_t, const std::string&)>;

// Fills assets, records, skipped and the selected measures' declarations of `results`
// (never the context). An asset
// that fails to load aborts the run with InputError: a named asset must be
// usable. A technique that cannot take an asset is recorded as skipped, with
// its reason. Which measures run where is decided by measureRuns (measure_rule.h).
void runSuite(const SuiteSelection& selection, const ProgressFn& progress, Results* results);

}  // namespace tb
