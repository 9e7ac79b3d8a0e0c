// Production size: every surface measure of each surface technique's default variant on the
// production assets (assets/production/assets.json: bundled shapes refined by OpenSubdiv to
// 9k-25k faces, among them a character-like figure), run exactly as `tessbench run
// --asset production/NAME --technique ID/DEFAULT` runs them (runSuite: the default suite's grid,
// every default camera path, on every core: the machine's 2), one iteration each.
//   production/<technique>/<asset>: one technique's default variant;
//   production/five_default_variants/<asset>: the five together, one run (issue 62's figure).
// Counters: seconds (wall of the run, the build and the asset's load included; best 0; the
// goal for the five together is at most 5 minutes), seconds_<measure> (that measure's time,
// summed over the run's records: the measures of two records overlap on 2 cores, so these
// add up to more than the wall), peak_rss_mb (the process's resident high-water mark during
// the run, reset before it; best 0, the goal at most 3 GB), skipped_records (techniques that
// cannot take the asset, e.g. osd_adaptive on a Loop mesh: the others' figures still count).
#include <benchmark/benchmark.h>

#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bench/technique_bench_support.h"
#include "harness/measures/measure.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"

namespace {

// The process's resident high-water mark (VmHWM), in MiB; reset by writing 5 to clear_refs.
double peakRssMiB() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0;
      status >> kib;
      return kib / 1024;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0;
}

void resetPeakRss() { std::ofstream("/proc/self/clear_refs") << "5"; }

std::vector<const tb::techniques::Technique*> surfaceTechniques() {
  std::vector<const tb::techniques::Technique*> out;
  for (const tb::techniques::Technique* technique :
       tb::techniques::TechniqueRegistry::instance().all()) {
    if (technique->info().family == tb::techniques::TechniqueFamily::kSurface) {
      out.push_back(technique);
    }
  }
  return out;
}

// The measures a surface technique's record runs (MeasureNeed::kSurface or kSurfaceOrSimulation).
std::vector<const tb::measures::Measure*> surfaceMeasures() {
  std::vector<const tb::measures::Measure*> out;
  for (const tb::measures::Measure* measure : tb::measures::MeasureRegistry::instance().all()) {
    const tb::measures::MeasureRequirements needs = measure->requirements();
    if (needs.has(tb::measures::MeasureNeed::kSurface) ||
        needs.has(tb::measures::MeasureNeed::kSurfaceOrSimulation)) {
      out.push_back(measure);
    }
  }
  return out;
}

void runProduction(benchmark::State& state,
                   const std::vector<const tb::techniques::Technique*>& techniques,
                   const tb::suite::AssetRef& asset) {
  tb::suite::SuiteSelection selection;
  selection.techniques = techniques;
  selection.assets = {asset};
  selection.measures = surfaceMeasures();
  for (const tb::techniques::Technique* technique : techniques) {
    selection.variants[technique->info().id] = {technique->variants().front().name};
  }
  tb::suite::SuiteTimings timings;
  double peak = 0;
  size_t skipped = 0;
  for (auto _ : state) {
    resetPeakRss();
    tb::results::Results results;
    tb::suite::runSuite(selection, {}, &results, &timings);
    peak = peakRssMiB();
    skipped = results.skipped.size();
    if (results.records.empty() && skipped > 0) {
      state.SkipWithError(results.skipped.front().reason.c_str());
    }
  }
  std::map<std::string, double> by_measure;
  for (const tb::suite::MeasureTiming& t : timings.measures) by_measure[t.measure] += t.seconds;
  for (const auto& [measure, seconds] : by_measure) state.counters["seconds_" + measure] = seconds;
  state.counters["peak_rss_mb"] = peak;
  state.counters["skipped_records"] = double(skipped);
}

void registerProductionBenchmarks() {
  const std::vector<const tb::techniques::Technique*> techniques = surfaceTechniques();
  for (const tb::suite::AssetRef& asset : tb::suite::productionAssets()) {
    auto add = [&](const std::string& label, std::vector<const tb::techniques::Technique*> run) {
      const std::string name = "production/" + label + "/" + asset.name;
      benchmark::RegisterBenchmark(
          name.c_str(), [run, asset](benchmark::State& s) { runProduction(s, run, asset); })
          ->Iterations(1)
          ->UseRealTime()
          ->Unit(benchmark::kSecond);
    };
    for (const tb::techniques::Technique* technique : techniques) {
      add(technique->info().id, {technique});
    }
    add("five_default_variants", techniques);
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerProductionBenchmarks);
}
