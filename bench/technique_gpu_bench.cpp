// GPU throughput of every registered surface technique's own TCS + TES on the Vulkan
// device (lavapipe by default), in TES invocations per second, default variant, uniform
// integer level. Every program of the asset is drawn (quad and triangle programs on mixed
// meshes), without capture, so the time is the shaders' and the tessellator's. Host clock
// from submit to fence (UseManualTime), as in gpu_bench. On lavapipe the figures rank
// techniques against each other; they are not GPU figures.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "bench/technique_bench_support.h"
#include "core/gpu/context.h"
#include "core/gpu/patch_program.h"
#include "techniques/registry.h"

namespace {

// Patches per draw: lavapipe's tessellator slows super-linearly with many per draw
// (core/gpu/patch_program.h); the cracks measure's batch below level 32.
constexpr uint32_t kPatchesPerDraw = 8;

void drawAllPatches(benchmark::State& state, const tb::Technique* technique,
                    const std::string& asset, float level) {
  static auto context = tb::gpu::Context::create();
  if (!context) {
    state.SkipWithError(("no usable Vulkan device: " + context.error()).c_str());
    return;
  }
  const tb::BuiltSurface patches = tb::bench::defaultVariantPatches(state, *technique, asset);
  if (!patches) return;
  const std::vector<tb::gpu::GpuPatchProgram> programs = patches->gpuPrograms();
  if (programs.empty()) {
    state.SkipWithError("the technique has no GPU program");
    return;
  }
  const tb::tess::Levels levels{{level, level, level, level}, {level, level}};
  tb::gpu::PatchProgramOptions options;
  options.capture = false;
  options.patches_per_draw = kPatchesPerDraw;
  double invocations = 0, seconds = 0;
  for (auto _ : state) {
    double iteration_seconds = 0;
    for (const tb::gpu::GpuPatchProgram& program : programs) {
      const tb::gpu::PatchProgramCapture run =
          tb::gpu::runPatchProgram(*context.value(), program, levels, options);
      iteration_seconds += run.submit_to_fence_s;
      invocations += double(run.stats.tes_invocations);
    }
    state.SetIterationTime(iteration_seconds);
    seconds += iteration_seconds;
  }
  // Best case: the device's bare TES rate (gpu_bench BM_TesThroughput); worst case 0.
  state.counters["TES_invocations_per_s"] = seconds > 0 ? invocations / seconds : 0;
  state.counters["patches"] = double(patches->patchCount());
  state.counters["programs"] = double(programs.size());
}

// Registered from the technique registry in main, so a new technique is benchmarked
// without touching this file. Assets: smooth quads with extraordinary vertices (every
// quad technique, ACC included), triangles, and a mesh of both.
void registerTechniqueGpuBenchmarks() {
  for (const tb::Technique* technique : tb::TechniqueRegistry::instance().all()) {
    if (technique->info().family != tb::TechniqueFamily::kSurface) continue;
    for (const char* asset : {"catmark_xord_interior", "loop_icosahedron", "catmark_pyramid"}) {
      for (float level : {4.0f, 16.0f}) {
        benchmark::RegisterBenchmark(
            ("gpu/" + technique->info().id + "/" + asset + "/level:" + std::to_string(int(level)))
                .c_str(),
            [technique, asset, level](benchmark::State& state) {
              drawAllPatches(state, technique, asset, level);
            })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerTechniqueGpuBenchmarks);
}
