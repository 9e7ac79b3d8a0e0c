// CPU evaluation throughput of every registered surface technique (docs/ARCHITECTURE.md
// measure 8): points per second on a bundled asset, in double.
#include <benchmark/benchmark.h>

#include "bench/technique_bench_support.h"
#include "techniques/registry.h"

namespace {

// Evaluates a uniform 16x16 barycentric/parametric grid on every patch.
void evaluateAllPatches(benchmark::State& state, const tb::Technique* technique,
                        const std::string& asset) {
  const tb::BuiltSurface patches = tb::bench::defaultVariantPatches(state, *technique, asset);
  if (!patches) return;
  constexpr int kGrid = 16;
  int64_t points = 0;
  for (auto _ : state) {
    for (size_t p = 0; p < patches->patchCount(); ++p) {
      const tb::PatchDomain domain = patches->patchDomain(p);
      for (int i = 0; i <= kGrid; ++i) {
        const int j_end = domain == tb::PatchDomain::kQuad ? kGrid : kGrid - i;
        for (int j = 0; j <= j_end; ++j) {
          const double u = double(i) / kGrid, v = double(j) / kGrid;
          const tb::DomainCoord coord = domain == tb::PatchDomain::kTriangle
                                            ? tb::DomainCoord{u, v, 1 - u - v}
                                            : tb::DomainCoord{u, v, 0};
          benchmark::DoNotOptimize(patches->evaluate(p, coord));
          ++points;
        }
      }
    }
  }
  state.counters["points_per_second"] = benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}

// Registered from the technique registry in main (after every static
// registration has run), so new techniques are benchmarked without touching this file.
void registerTechniqueBenchmarks() {
  for (const tb::Technique* technique : tb::TechniqueRegistry::instance().all()) {
    if (technique->info().family != tb::TechniqueFamily::kSurface) continue;
    // catmark_pawn (creased: the triangle techniques), loop_icosahedron (triangles),
    // catmark_xord_interior (smooth quads with extraordinary vertices: every quad
    // technique, ACC included) and catmark_pyramid (quads and triangles in one mesh).
    for (const char* asset :
         {"catmark_pawn", "loop_icosahedron", "catmark_xord_interior", "catmark_pyramid"}) {
      benchmark::RegisterBenchmark(
          ("eval/" + technique->info().id + "/" + asset).c_str(),
          [technique, asset](benchmark::State& state) { evaluateAllPatches(state, technique, asset); });
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerTechniqueBenchmarks);
}
