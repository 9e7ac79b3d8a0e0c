// Linear growth: the harness time per patch of every registered measure, on 1, 4 and 16
// disjoint translated copies of one asset (core/mesh/mesh_copies.h), so the patch mix is
// constant while the patch count grows. Single worker thread, so the figures are the
// algorithm's growth, not the scheduler's. Wall clock. Counters:
//   seconds_per_patch: the measure's time over its patches; best case constant in the copy
//     count, but a measure's fixed costs (shader compilation, pipelines, device set-up) are
//     shared by more patches as the copies grow, so it falls from 1 to 4 to 16 copies.
//   marginal_seconds_per_patch: (time(N copies) - time(1 copy)) / (patches(N) - patches(1)),
//     the cost of one more patch with the fixed costs cancelled. The band: at 16 copies it
//     stays within +-25% of 4 copies (linear growth); superlinear work (a pairing, a search
//     over all patches) makes it grow. time(1 copy) is the best of 3 runs. Each case runs 5
//     times: read the medians (about 4 min in all, one thread).
// The work per patch must not change with the copy count, or the band measures the view and
// not the algorithm: the copies stand 1/8 of an extent apart (a viewport pixel per copy
// nearly constant: 1.16x as many at 16 copies as at 1) and the camera keeps every copy's
// on-screen size (copiesPath).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "bench/technique_bench_support.h"
#include "core/gpu/context.h"
#include "core/mesh/mesh_copies.h"
#include "core/view/camera.h"
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

struct Prepared {
  tb::mesh::Mesh mesh;
  tb::techniques::BuiltSurface patches;
  tb::view::CameraPath path;
  tb::techniques::VariantInfo variant;  // kept: MeasureInput holds a reference to it
};

// The test orbit's three views of the grid of copies, seen from 16 times as far with a
// field of view 16 times as narrow (nearly orthographic: the copies' depths differ by a few
// percent), on a viewport scaled by the grid's diagonal over one copy's. Every copy then
// spans about the pixels it spans alone on the test orbit, so the pixel-driven work per
// patch (factor levels, the level searches' steps, screen error, rasterised visibility)
// stays constant as the copies grow. Under the plain test orbit each copy shrinks with the
// grid, and the searches' power-of-two steps made the work per patch jump by up to 1.5x
// between 4 and 16 copies, up or down, which no algorithm caused.
tb::view::CameraPath copiesPath(const tb::mesh::Aabb& grid, const tb::mesh::Aabb& single) {
  constexpr double kTelephoto = 16, kDegree = std::numbers::pi / 180;
  const double scale = tb::mesh::diagonalOf(grid) / tb::mesh::diagonalOf(single);
  const tb::mesh::Vec3d centre = 0.5 * (grid.min + grid.max);
  const double radius = std::max(0.5 * tb::mesh::diagonalOf(grid), 1e-3);
  const double distance = 2.5 * radius * kTelephoto;
  const double fov_y = 2 * std::atan(std::tan(30 * kDegree) / kTelephoto);
  tb::view::CameraPath path{"scaling_orbit", {}};
  for (double azimuth_deg : {0.0, 120.0, 240.0}) {
    const double azimuth = azimuth_deg * kDegree, elevation = 20 * kDegree;
    const tb::mesh::Vec3d eye =
        centre + distance * tb::mesh::Vec3d{std::cos(elevation) * std::sin(azimuth),
                                            std::sin(elevation),
                                            std::cos(elevation) * std::cos(azimuth)};
    path.views.push_back(tb::view::perspectiveView({.eye = eye,
                                                    .target = centre,
                                                    .fov_y_rad = fov_y,
                                                    .width_px = uint32_t(std::lround(640 * scale)),
                                                    .height_px = uint32_t(std::lround(480 * scale)),
                                                    .near_plane = distance - 1.01 * radius,
                                                    .far_plane = distance + 1.01 * radius}));
  }
  return path;
}

// The grid step in the asset's largest extents: copies 1/8 extent apart, so the viewport,
// which grows with the grid, holds nearly the same pixels per copy at 1, 4 and 16 copies
// (area per copy 1, 1.13, 1.17 times one copy's alone, with twice-the-extent steps 1, 2.25,
// 3.06: per-pixel work such as the culling measure's visibility buffers then grew with it).
constexpr double kStepExtents = 1.125;

// The asset's `copies` translated copies, built by the technique's default variant; null
// patches (and the benchmark skipped) when the technique refuses it.
Prepared prepare(benchmark::State& state, const tb::techniques::Technique& technique,
                 const std::string& asset, int copies) {
  const tb::mesh::Mesh single = tb::suite::loadAsset(tb::suite::resolveAsset(asset));
  Prepared p{tb::mesh::translatedCopies(single, copies, kStepExtents),
             nullptr,
             {},
             technique.variants()[0]};
  try {
    p.patches = tb::techniques::buildSurface(technique, p.mesh, p.variant);
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
  }
  p.path = copiesPath(tb::mesh::boundsOf(p.mesh), tb::mesh::boundsOf(single));
  return p;
}

tb::measures::MeasureInput inputOf(
    const tb::techniques::Technique& technique, const Prepared& p, const std::string& name,
    const tb::gpu::Expected<std::unique_ptr<tb::gpu::Context>>& context) {
  tb::measures::MeasureInput input{technique,
                                   p.variant,
                                   name,
                                   p.mesh,
                                   p.patches.get(),
                                   context ? context.value().get() : nullptr,
                                   context ? std::string() : context.error()};
  input.view = &p.path.views[0];
  input.camera_path = &p.path;
  return input;
}

double secondsOf(const tb::measures::Measure& measure, const tb::measures::MeasureInput& input) {
  const auto start = std::chrono::steady_clock::now();
  benchmark::DoNotOptimize(measure.run(input));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void measureOnCopies(benchmark::State& state, const tb::measures::Measure* measure,
                     const tb::techniques::Technique* technique, const std::string& asset) {
  const int copies = int(state.range(0));
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  static auto context = tb::gpu::Context::create();
  const Prepared p = prepare(state, *technique, asset, copies);
  if (!p.patches) return;
  const tb::measures::MeasureInput input =
      inputOf(*technique, p, asset + " x" + std::to_string(copies), context);
  double seconds = 0;
  for (auto _ : state) seconds += secondsOf(*measure, input);
  const double patch_count = double(p.patches->patchCount());
  state.counters["patches"] = patch_count;
  state.counters["seconds_per_patch"] = benchmark::Counter(
      patch_count, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  if (copies == 1) return;
  const Prepared one = prepare(state, *technique, asset, 1);
  const tb::measures::MeasureInput one_input = inputOf(*technique, one, asset + " x1", context);
  double one_seconds = secondsOf(*measure, one_input);
  for (int run = 1; run < 3; ++run)
    one_seconds = std::min(one_seconds, secondsOf(*measure, one_input));
  const double per_run = seconds / double(state.iterations());
  state.counters["marginal_seconds_per_patch"] =
      (per_run - one_seconds) / (patch_count - double(one.patches->patchCount()));
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
          ->MinTime(0.2)
          ->Repetitions(5)  // the marginal cost is a difference of two times: read medians
          ->ReportAggregatesOnly(true);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerScalingBenchmarks);
}
