// Production size: every surface measure of every surface technique's default variant on the
// production assets (assets/production/assets.json: bundled shapes refined by OpenSubdiv to
// 9k-20k faces with their creases), one iteration each, on every core (the machine's 2), as
// the suite runs them (the default suite's grid and camera path). Counters: seconds (wall;
// best 0; the goal is that the five techniques' measures together stay within 10 minutes per
// input), peak_rss_mb (the process's resident high-water mark during the measure, reset
// before it: the memory a run of this measure needs; best 0, the goal at most 3 GB), patches.
// The technique's build (buildSurface, once per technique and asset) is not in the figures.
#include <benchmark/benchmark.h>

#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "bench/technique_bench_support.h"
#include "core/gpu/context.h"
#include "core/mesh/bounds.h"
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

// Loaded and built once per (technique, asset): the measures share them, as in a run.
struct Subject {
  tb::mesh::Mesh mesh;
  tb::techniques::BuiltSurface patches;
  std::string error;
};

const Subject& subject(const tb::techniques::Technique& technique, const std::string& asset) {
  static std::map<std::string, std::unique_ptr<Subject>> cache;
  std::unique_ptr<Subject>& slot = cache[technique.info().id + "/" + asset];
  if (!slot) {
    slot = std::make_unique<Subject>();
    try {
      slot->mesh = tb::suite::loadAsset(tb::suite::resolveAsset(asset));
      slot->patches = tb::techniques::buildSurface(technique, slot->mesh, technique.variants()[0]);
    } catch (const std::exception& error) {
      slot->error = error.what();
    }
  }
  return *slot;
}

tb::gpu::Context* device() {
  static auto context = tb::gpu::Context::create();
  return context ? context.value().get() : nullptr;
}

void measureOnAsset(benchmark::State& state, const tb::measures::Measure& measure,
                    const tb::techniques::Technique& technique, const std::string& asset) {
  const Subject& s = subject(technique, asset);
  if (!s.error.empty()) {
    state.SkipWithError(s.error.c_str());
    return;
  }
  const tb::view::CameraPath path = tb::suite::suiteCameraPaths(tb::measures::SuiteMode::kDefault)
                                        .front()(tb::mesh::boundsOf(s.mesh));
  tb::measures::MeasureInput input{
      technique, technique.variants()[0], asset, s.mesh, s.patches.get(), device(), {}};
  input.view = &path.views[0];
  input.camera_path = &path;
  double peak = 0;
  for (auto _ : state) {
    resetPeakRss();
    benchmark::DoNotOptimize(measure.run(input));
    peak = peakRssMiB();
  }
  state.counters["peak_rss_mb"] = peak;
  state.counters["patches"] = double(s.patches->patchCount());
}

void registerProductionBenchmarks() {
  for (const tb::suite::AssetRef& asset : tb::suite::productionAssets()) {
    for (const tb::techniques::Technique* technique :
         tb::techniques::TechniqueRegistry::instance().all()) {
      if (technique->info().family != tb::techniques::TechniqueFamily::kSurface) continue;
      for (const tb::measures::Measure* measure : tb::measures::MeasureRegistry::instance().all()) {
        const tb::measures::MeasureRequirements needs = measure->requirements();
        if (!needs.has(tb::measures::MeasureNeed::kSurface) &&
            !needs.has(tb::measures::MeasureNeed::kSurfaceOrSimulation)) {
          continue;
        }
        if (needs.technique_filter && !needs.technique_filter(*technique)) continue;
        const std::string name =
            "production/" + measure->info().id + "/" + technique->info().id + "/" + asset.name;
        benchmark::RegisterBenchmark(name.c_str(),
                                     [measure, technique, asset = asset.name](benchmark::State& s) {
                                       measureOnAsset(s, *measure, *technique, asset);
                                     })
            ->Iterations(1)
            ->UseRealTime()
            ->Unit(benchmark::kSecond);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerProductionBenchmarks);
}
