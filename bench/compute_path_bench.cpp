// Tessellation without the tessellator (core/gpu/compute_path.h) against the hardware path
// (core/gpu/patch_program.h runPatchProgram, the technique's own TCS + TES on lavapipe's
// tessellator), per surface technique's default variant on one bundled asset, at uniform
// integer levels 4, 16 and 64: evaluated vertices per second. Compute: the whole submission
// (tessellator passes, build, evaluate, indirect draw) with its pipelines built once
// outside the timing, no read-back. Hardware: the capture of every vertex (64 patches a
// draw, no statistics query), read back and sorted, as the crack measure uses it. Host
// seconds, submit to fence in both. Counters: vertices_per_s, vertices (per run), patches.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "core/gpu/compute_path.h"
#include "core/gpu/context.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/registry.h"

namespace {

struct BenchCase {
  const char* technique;
  const char* asset;
};
constexpr BenchCase kCases[] = {
    {"acc", "catmark_cube_creases1"}, {"gregory_acc", "catmark_nonquads"},
    {"osd_adaptive", "catmark_cube"}, {"pn_triangles", "cylinder_seam"},
    {"phong", "cylinder_seam"},
};

// The case's first GPU program and its uniform levels; null when the technique is absent.
std::unique_ptr<tb::gpu::GpuPatchProgram> program(benchmark::State& state) {
  const BenchCase& c = kCases[state.range(0)];
  const tb::techniques::Technique* technique =
      tb::techniques::TechniqueRegistry::instance().find(c.technique);
  if (technique == nullptr) {
    state.SkipWithError((std::string("no technique ") + c.technique).c_str());
    return nullptr;
  }
  const tb::mesh::Mesh mesh = tb::suite::loadAsset(tb::suite::resolveAsset(c.asset));
  const auto surface = tb::techniques::buildSurface(*technique, mesh, technique->variants()[0]);
  state.SetLabel(std::string(c.technique) + " " + c.asset);
  return std::make_unique<tb::gpu::GpuPatchProgram>(surface->gpuPrograms()[0]);
}

tb::tess::Levels uniformLevels(const benchmark::State& state) {
  const auto level = static_cast<float>(state.range(1));
  return {{level, level, level, level}, {level, level}};
}

void counters(benchmark::State& state, uint64_t vertices, uint32_t patches) {
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["vertices_per_s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * vertices), benchmark::Counter::kIsRate);
}

void BM_ComputePath(benchmark::State& state) {
  tb::gpu::Context* context = tb::bench::benchContext(state);
  const auto p = context ? program(state) : nullptr;
  if (!p) return;
  const std::vector<tb::tess::Levels> levels(p->patch_count, uniformLevels(state));
  tb::gpu::ComputePath path(*context, *p, levels);
  for (auto _ : state) state.SetIterationTime(path.run());
  counters(state, path.read().points, p->patch_count);
}

void BM_HardwarePath(benchmark::State& state) {
  tb::gpu::Context* context = tb::bench::benchContext(state);
  const auto p = context ? program(state) : nullptr;
  if (!p) return;
  const std::vector<tb::tess::Levels> levels(p->patch_count, uniformLevels(state));
  tb::gpu::PatchProgramOptions options;
  options.patches_per_draw = 64;
  options.statistics = false;
  uint64_t vertices = 0;
  for (auto _ : state) {
    const tb::gpu::PatchProgramCapture capture =
        tb::gpu::runPatchProgram(*context, *p, levels, options);
    state.SetIterationTime(capture.submit_to_fence_s);
    vertices = capture.vertices.size();
  }
  counters(state, vertices, p->patch_count);
}

void cases(benchmark::internal::Benchmark* b) {
  b->ArgNames({"case", "level"})
      ->ArgsProduct({{0, 1, 2, 3, 4}, {4, 16, 64}})
      ->Unit(benchmark::kMillisecond)
      ->UseManualTime();
}

BENCHMARK(BM_ComputePath)->Apply(cases);
BENCHMARK(BM_HardwarePath)->Apply(cases);

}  // namespace

TB_BENCHMARK_MAIN()
