// The compute tessellator (core/gpu/compute_tessellator.h: count pass, prefix sum, write
// pass in one submission) against the CPU tessellator (core/tess) on the same batches:
// domain points per second, per domain x spacing x uniform level (4, 16, 64), each batch
// about 2^18 points (e.g. 64 quads at level 64, 10,000 at level 4). Compute: the three
// passes timed by GPU timestamps (submit to fence without them), the pipelines built once
// outside the timing, no read-back. CPU: tess::tessellate() per patch on one thread,
// output vectors included. Counters: points_per_s, points (per batch), patches.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "core/gpu/compute_tessellator.h"
#include "core/gpu/context.h"
#include "core/tess/tessellator.h"

namespace {

using tb::tess::Domain;
using tb::tess::Spacing;

constexpr uint64_t kPointsPerBatch = uint64_t{1} << 18;

std::vector<tb::gpu::TessPatch> batch(const benchmark::State& state) {
  tb::gpu::TessPatch patch;
  patch.domain = static_cast<Domain>(state.range(0));
  patch.spacing = static_cast<Spacing>(state.range(1));
  const auto level = static_cast<float>(state.range(2));
  patch.levels.outer = {level, level, level, level};
  patch.levels.inner = {level, level};
  const size_t points =
      tb::tess::tessellate(patch.domain, patch.spacing, patch.levels).points.size();
  return std::vector<tb::gpu::TessPatch>(std::max<size_t>(1, kPointsPerBatch / points), patch);
}

void label(benchmark::State& state, const std::vector<tb::gpu::TessPatch>& patches,
           uint64_t points) {
  state.SetLabel(std::string(tb::tess::toString(patches[0].domain)) + " " +
                 std::string(tb::tess::toString(patches[0].spacing)));
  state.counters["points"] = static_cast<double>(points);
  state.counters["patches"] = static_cast<double>(patches.size());
}

void BM_CpuTessellator(benchmark::State& state) {
  const std::vector<tb::gpu::TessPatch> patches = batch(state);
  uint64_t points = 0;
  for (auto _ : state) {
    points = 0;
    for (const tb::gpu::TessPatch& p : patches) {
      const tb::tess::Tessellation t = tb::tess::tessellate(p.domain, p.spacing, p.levels);
      benchmark::DoNotOptimize(t.points.data());
      points += t.points.size();
    }
  }
  label(state, patches, points);
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * points), benchmark::Counter::kIsRate);
}

void BM_ComputeTessellator(benchmark::State& state) {
  static auto context = tb::gpu::Context::create();
  if (!context) {
    state.SkipWithError(("no usable Vulkan device: " + context.error()).c_str());
    return;
  }
  const std::vector<tb::gpu::TessPatch> patches = batch(state);
  tb::gpu::ComputeTessellator tessellator(*context.value(), patches);
  for (auto _ : state) {
    const tb::gpu::ComputeRunTiming timing = tessellator.run();
    state.SetIterationTime(std::isnan(timing.gpu_ns) ? timing.submit_to_fence_s
                                                     : timing.gpu_ns * 1e-9);
  }
  const tb::gpu::ComputeTessellation out = tessellator.read();
  label(state, patches, out.points.size());
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * out.points.size()), benchmark::Counter::kIsRate);
}

void cases(benchmark::internal::Benchmark* b) {
  b->ArgNames({"domain", "spacing", "level"})
      ->ArgsProduct(
          {{static_cast<int64_t>(Domain::kTriangle), static_cast<int64_t>(Domain::kQuad),
            static_cast<int64_t>(Domain::kIsoline)},
           {static_cast<int64_t>(Spacing::kInteger), static_cast<int64_t>(Spacing::kFractionalOdd)},
           {4, 16, 64}})
      ->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_CpuTessellator)->Apply(cases);
BENCHMARK(BM_ComputeTessellator)->Apply(cases)->UseManualTime();

}  // namespace

TB_BENCHMARK_MAIN()
