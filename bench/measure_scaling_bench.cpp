// Linear growth: the harness time per patch of every registered measure, on 1, 4 and 16
// disjoint translated copies of one asset (core/mesh/mesh_copies.h), so the patch mix is
// constant while the patch count grows. Counter seconds_per_patch: best case constant in
// the copy count; at 16 copies it should stay within ±25% of 4 copies (1 copy is
// dominated by fixed costs: shader compilation, device set-up). Single worker thread,
// so the figure is the algorithm's growth, not the scheduler's. Wall clock.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <memory>
#include <string>

#include "bench/technique_bench_support.h"
#include "core/gpu/context.h"
#include "core/mesh/mesh_copies.h"
#include "harness/measures/measure.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"

namespace {

// Quad techniques on a quad mesh with extraordinary vertices and a triangle technique on
// a triangle mesh with them: between them every measure has a technique it runs on (acc
// for published_figures, which needs the technique's probe shader).
struct Case {
  const char* technique;
  const char* asset;
};
constexpr Case kCases[] = {{"acc", "catmark_xord_interior"},
                           {"gregory_acc", "catmark_xord_interior"},
                           {"pn_triangles", "loop_xord_interior"}};

void measureOnCopies(benchmark::State& state, const tb::measures::Measure* measure,
                     const tb::techniques::Technique* technique, const std::string& asset) {
  const int copies = int(state.range(0));
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  static auto context = tb::gpu::Context::create();
  const tb::mesh::Mesh mesh = tb::mesh::translatedCopies(
      tb::suite::loadAsset(tb::suite::resolveAsset(asset)), copies);
  const tb::techniques::VariantInfo variant = technique->variants()[0];
  tb::techniques::BuiltSurface patches;
  try {
    patches = tb::techniques::buildSurface(*technique, mesh, variant);
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
    return;
  }
  const tb::view::CameraPath path = tb::suite::testOrbitPath(tb::mesh::boundsOf(mesh));
  const std::string asset_name = asset + " x" + std::to_string(copies);
  tb::measures::MeasureInput input{*technique,
                                   variant,
                                   asset_name,
                                   mesh,
                                   patches.get(),
                                   context ? context.value().get() : nullptr,
                                   context ? std::string() : context.error()};
  input.view = &path.views[0];
  input.camera_path = &path;
  for (auto _ : state) {
    benchmark::DoNotOptimize(measure->run(input));
  }
  const double patch_count = double(patches->patchCount());
  state.counters["patches"] = patch_count;
  state.counters["seconds_per_patch"] = benchmark::Counter(
      patch_count, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Registered from the registries in main, so a new measure is benchmarked without
// touching this file. Surface measures only: simulations scale with their scenario.
void registerScalingBenchmarks() {
  for (const tb::measures::Measure* measure : tb::measures::MeasureRegistry::instance().all()) {
    const tb::measures::MeasureRequirements requirements = measure->requirements();
    if (!requirements.has(tb::measures::MeasureNeed::kSurface)) continue;
    for (const Case& c : kCases) {
      const tb::techniques::Technique* technique =
          tb::techniques::TechniqueRegistry::instance().find(c.technique);
      if (technique == nullptr) continue;
      if (requirements.technique_filter && !requirements.technique_filter(*technique)) continue;
      const std::string asset = c.asset;
      benchmark::RegisterBenchmark(
          ("scaling/" + measure->info().id + "/" + c.technique + "/" + asset).c_str(),
          [measure, technique, asset](benchmark::State& state) {
            measureOnCopies(state, measure, technique, asset);
          })
          ->Arg(1)
          ->Arg(4)
          ->Arg(16)
          ->ArgName("copies")
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond)
          ->MinTime(0.2);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerScalingBenchmarks);
}
