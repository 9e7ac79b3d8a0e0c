// Tessellation throughput of the Vulkan device (lavapipe by default), in TES invocations
// per second. Timed with the host clock from submit to fence (UseManualTime): timestamp
// queries are meaningless for tessellation draws on lavapipe (docs/ARCHITECTURE.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "core/gpu/context.h"
#include "core/gpu/tess_capture.h"

namespace {

using tb::tess::Domain;
using tb::tess::Levels;
using tb::tess::Spacing;

// TES invocations per submission: large enough that submission overhead is noise.
constexpr double kPlainInvocationsPerSubmit = 400'000;
// Capture is ~4x slower per invocation, and its host welding is not timed.
constexpr double kCaptureInvocationsPerSubmit = 100'000;

// Arguments: domain (0 = triangle, 1 = quad), uniform integer level.
struct Case {
  tb::gpu::Context* context;
  Domain domain;
  Levels levels;
};

std::optional<Case> setUp(benchmark::State& state) {
  static auto context = tb::gpu::Context::create();
  if (!context) {
    state.SkipWithError(("no usable Vulkan device: " + context.error()).c_str());
    return std::nullopt;
  }
  const float level = static_cast<float>(state.range(1));
  return Case{context.value().get(), state.range(0) == 0 ? Domain::kTriangle : Domain::kQuad,
              Levels{{level, level, level, level}, {level, level}}};
}

uint32_t drawsFor(double budget_invocations, uint64_t invocations_per_draw, double max_draws) {
  const double per_draw = static_cast<double>(std::max<uint64_t>(invocations_per_draw, 1));
  return static_cast<uint32_t>(std::clamp(budget_invocations / per_draw, 1.0, max_draws));
}

void reportRate(benchmark::State& state, double invocations, double seconds, uint32_t draws) {
  state.counters["TES_invocations_per_s"] = seconds > 0 ? invocations / seconds : 0;
  state.counters["draws_per_submit"] = draws;
}

// One patch per draw, many draws per submission, cheapest TES, no capture.
void BM_TesThroughput(benchmark::State& state) {
  const std::optional<Case> c = setUp(state);
  if (!c) return;
  const auto probe =
      tb::gpu::measureTessThroughput(*c->context, c->domain, Spacing::kInteger, c->levels, 1);
  const uint32_t draws = drawsFor(kPlainInvocationsPerSubmit, probe.stats.tes_invocations, 8192);
  double invocations = 0, seconds = 0;
  for (auto _ : state) {
    const auto run =
        tb::gpu::measureTessThroughput(*c->context, c->domain, Spacing::kInteger, c->levels, draws);
    state.SetIterationTime(run.submit_to_fence_s);
    invocations += static_cast<double>(run.stats.tes_invocations);
    seconds += run.submit_to_fence_s;
  }
  reportRate(state, invocations, seconds, draws);
}

// The same through transform-feedback capture (tessellateOnGpuBatch), one submission.
void BM_TesCapture(benchmark::State& state) {
  const std::optional<Case> c = setUp(state);
  if (!c) return;
  const auto probe = tb::gpu::tessellateOnGpu(*c->context, c->domain, Spacing::kInteger, c->levels);
  const uint32_t draws = drawsFor(kCaptureInvocationsPerSubmit, probe.stats.tes_invocations, 1024);
  const std::vector<Levels> levels(draws, c->levels);
  double invocations = 0, seconds = 0;
  for (auto _ : state) {
    const auto batch =
        tb::gpu::tessellateOnGpuBatch(*c->context, c->domain, Spacing::kInteger, levels);
    state.SetIterationTime(batch.submit_to_fence_s);
    for (const auto& patch : batch.patches) {
      invocations += static_cast<double>(patch.stats.tes_invocations);
    }
    seconds += batch.submit_to_fence_s;
  }
  reportRate(state, invocations, seconds, draws);
}

void levelsPerDomain(benchmark::internal::Benchmark* b) {
  b->ArgNames({"domain", "level"});
  for (int64_t domain : {0, 1}) {
    for (int64_t level : {4, 16, 64}) b->Args({domain, level});
  }
  b->UseManualTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_TesThroughput)->Apply(levelsPerDomain);
BENCHMARK(BM_TesCapture)->Apply(levelsPerDomain);

}  // namespace

TB_BENCHMARK_MAIN()
