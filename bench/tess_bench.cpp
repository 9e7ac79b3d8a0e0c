// CPU tessellator throughput: patches/s for one patch at uniform levels 4, 16 and 64 per
// domain, with integer and fractional_odd spacing (fractional_odd clamps 64 to 63).
// Each iteration is one full tessellate() call: level processing, points and
// primitives, including the output vectors' allocation.
#include <benchmark/benchmark.h>

#include <string>

#include "bench/bench_main.h"
#include "core/tess/tessellator.h"

namespace {

using tb::tess::Domain;
using tb::tess::Spacing;

void BM_Tessellate(benchmark::State& state) {
  const auto domain = static_cast<Domain>(state.range(0));
  const auto spacing = static_cast<Spacing>(state.range(1));
  const auto level = static_cast<float>(state.range(2));
  tb::tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};

  size_t points = 0;
  size_t primitives = 0;
  for (auto _ : state) {
    const tb::tess::Tessellation t = tb::tess::tessellate(domain, spacing, levels);
    benchmark::DoNotOptimize(t.points.data());
    points = t.points.size();
    primitives = t.triangles.size() + t.lines.size();
  }
  state.SetLabel(std::string(tb::tess::toString(domain)) + " " +
                 std::string(tb::tess::toString(spacing)));
  state.counters["patches_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * points), benchmark::Counter::kIsRate);
  state.counters["points"] = static_cast<double>(points);
  state.counters["primitives"] = static_cast<double>(primitives);
}

BENCHMARK(BM_Tessellate)
    ->ArgNames({"domain", "spacing", "level"})
    ->ArgsProduct({{static_cast<int64_t>(Domain::kTriangle), static_cast<int64_t>(Domain::kQuad),
                    static_cast<int64_t>(Domain::kIsoline)},
                   {static_cast<int64_t>(Spacing::kInteger),
                    static_cast<int64_t>(Spacing::kFractionalOdd)},
                   {4, 16, 64}});

}  // namespace

TB_BENCHMARK_MAIN()
