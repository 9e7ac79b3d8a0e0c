// GPU throughput of every registered surface technique's own TCS + TES on the Vulkan
// device (lavapipe by default), in TES invocations per second, default variant, uniform
// integer level. Every program of the asset is drawn (quad and triangle programs on mixed
// meshes), without capture, so the time is the shaders' and the tessellator's. Host clock
// from submit to fence (UseManualTime), as in gpu_bench. On lavapipe the figures rank
// techniques against each other; they are not GPU figures.
//
// cracks_gpu/... rows run the crack measure's GPU half (captureBoundaryPositions, the
// function measureCracks calls, on the same patches and levels) and, in the same
// iterations, the shaders without capture, so the two rates come from one run. Their
// time is the crack half's whole host wall clock (uploads, submissions, reading back and
// storing the boundary points), stricter than the no-capture rows' submit-to-fence.
// cracks_gpu_full_inner/... rows run it under the patches' own inner levels (every
// interior point too): the capture's own cost against the same TES invocations.
// cracks_row_gpu/... rows time a whole GPU row of the measure (measureCracks, kGpu: shared
// edges, the CPU twin at the boundary points, the capture, pairing).
#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench/technique_bench_support.h"
#include "core/gpu/context.h"
#include "core/gpu/patch_program.h"
#include "harness/measures/common/cracks/crack_capture.h"
#include "harness/measures/common/cracks/cracks.h"
#include "techniques/registry.h"

namespace {

// Patches per draw: lavapipe's tessellator slows super-linearly with many per draw
// (core/gpu/patch_program.h); the cracks measure's batch below level 32.
constexpr uint32_t kPatchesPerDraw = 8;

// The device, the default variant's patches of `asset` and their GPU programs; a null
// context when the case is skipped (no device, the asset refused, no GPU program).
struct GpuCase {
  tb::gpu::Context* context = nullptr;
  tb::techniques::BuiltSurface patches;
  std::vector<tb::gpu::GpuPatchProgram> programs;
};

GpuCase prepareGpuCase(benchmark::State& state, const tb::techniques::Technique& technique,
                       const std::string& asset) {
  GpuCase gpu_case;
  tb::gpu::Context* context = tb::bench::benchContext(state);
  if (context == nullptr) return gpu_case;
  gpu_case.patches = tb::bench::defaultVariantPatches(state, technique, asset);
  if (!gpu_case.patches) return gpu_case;
  gpu_case.programs = gpu_case.patches->gpuPrograms();
  if (gpu_case.programs.empty()) {
    state.SkipWithError("the technique has no GPU program");
    return gpu_case;
  }
  gpu_case.context = context;
  return gpu_case;
}

// Every program of `patches` without capture: TES invocations, submit-to-fence seconds
// and host wall-clock seconds (the whole calls).
struct NoCaptureRun {
  double invocations = 0, seconds = 0, wall_seconds = 0;
};
NoCaptureRun runWithoutCapture(tb::gpu::Context& context,
                               const std::vector<tb::gpu::GpuPatchProgram>& programs,
                               const tb::tess::Levels& levels) {
  tb::gpu::PatchProgramOptions options;
  options.capture = false;
  options.patches_per_draw = kPatchesPerDraw;
  NoCaptureRun run;
  const auto start = std::chrono::steady_clock::now();
  for (const tb::gpu::GpuPatchProgram& program : programs) {
    const tb::gpu::PatchProgramCapture r =
        tb::gpu::runPatchProgram(context, program, levels, options);
    run.seconds += r.submit_to_fence_s;
    run.invocations += double(r.stats.tes_invocations);
  }
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void drawAllPatches(benchmark::State& state, const tb::techniques::Technique* technique,
                    const std::string& asset, float level) {
  GpuCase gpu_case = prepareGpuCase(state, *technique, asset);
  if (gpu_case.context == nullptr) return;
  tb::gpu::Context* context = gpu_case.context;
  const tb::techniques::BuiltSurface& patches = gpu_case.patches;
  const std::vector<tb::gpu::GpuPatchProgram>& programs = gpu_case.programs;
  const tb::tess::Levels levels{{level, level, level, level}, {level, level}};
  double invocations = 0, seconds = 0;
  for (auto _ : state) {
    const NoCaptureRun run = runWithoutCapture(*context, programs, levels);
    state.SetIterationTime(run.seconds);
    invocations += run.invocations;
    seconds += run.seconds;
  }
  // Best case: the device's bare TES rate (gpu_bench BM_TesThroughput); worst case 0.
  state.counters["TES_invocations_per_s"] = seconds > 0 ? invocations / seconds : 0;
  state.counters["patches"] = double(patches->patchCount());
  state.counters["programs"] = double(programs.size());
}

enum class CrackPath {
  kCapture,           // captureBoundaryPositions as the measure calls it (lowered inner levels)
  kCaptureFullInner,  // the same under the patches' own inner levels
  kWholeRow,          // measureCracks(kGpu): a whole GPU row (shared edges, CPU twin, pairing)
};

// The crack measure's GPU half against the same shaders without capture, in one run.
void crackCapture(benchmark::State& state, const tb::techniques::Technique* technique,
                  const std::string& asset, float level, CrackPath path) {
  GpuCase gpu_case = prepareGpuCase(state, *technique, asset);
  if (gpu_case.context == nullptr) return;
  tb::gpu::Context* context = gpu_case.context;
  const tb::techniques::BuiltSurface& patches = gpu_case.patches;
  const std::vector<tb::gpu::GpuPatchProgram>& programs = gpu_case.programs;
  const tb::tess::Levels uniform{{level, level, level, level}, {level, level}};
  const std::vector<tb::tess::Levels> levels(patches->patchCount(), uniform);
  const tb::tess::Spacing spacing = tb::tess::Spacing::kInteger;
  const tb::measures::PatchBoundaries boundaries =
      tb::measures::patchBoundaries(*patches, spacing, levels);
  tb::measures::CrackCaptureOptions options;
  options.lower_inner_levels = path != CrackPath::kCaptureFullInner;
  double crack_invocations = 0, crack_seconds = 0, crack_fence_seconds = 0;
  NoCaptureRun bare;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    if (path == CrackPath::kWholeRow) {
      const tb::measures::CrackFigures f = tb::measures::measureCracks(
          *patches, spacing, levels, tb::measures::CrackBackend::kGpu, context);
      if (!f.measured) state.SkipWithError(f.skipped_reason.c_str());
    } else {
      const tb::measures::BoundaryCapture capture = tb::measures::captureBoundaryPositions(
          *patches, programs, boundaries, spacing, levels, *context, options);
      benchmark::DoNotOptimize(capture.positions.data());
      crack_fence_seconds += capture.submit_to_fence_s;
      crack_invocations += double(capture.tes_invocations);
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(wall);
    crack_seconds += wall;
    const NoCaptureRun run = runWithoutCapture(*context, programs, uniform);
    bare.invocations += run.invocations;
    bare.seconds += run.seconds;
    bare.wall_seconds += run.wall_seconds;
  }
  const double bare_rate = bare.seconds > 0 ? bare.invocations / bare.seconds : 0;
  // The shaders without capture at the patches' own levels (submit to fence).
  state.counters["no_capture_TES_invocations_per_s"] = bare_rate;
  // Throughput over the same patches and levels: the no-capture time over this path's
  // (host wall clock); 1 = as fast as the bare shaders.
  state.counters["throughput_ratio"] = crack_seconds > 0 ? bare.seconds / crack_seconds : 0;
  // The same with the no-capture calls also timed by host wall clock (like for like: both
  // include uploads, recording and reading back; small workloads are dominated by them).
  state.counters["throughput_ratio_wall"] =
      crack_seconds > 0 ? bare.wall_seconds / crack_seconds : 0;
  state.counters["patches"] = double(patches->patchCount());
  if (path == CrackPath::kWholeRow) return;
  const double crack_rate = crack_seconds > 0 ? crack_invocations / crack_seconds : 0;
  // TES invocations the path ran per second (host wall clock) and that over the
  // no-capture rate; with lowered inner levels each patch's TCS is spread over fewer
  // invocations, so this ratio is below throughput_ratio.
  state.counters["TES_invocations_per_s"] = crack_rate;
  state.counters["ratio"] = bare_rate > 0 ? crack_rate / bare_rate : 0;
  // The path's rate by submit to fence alone, as the no-capture rows are timed.
  state.counters["fence_TES_invocations_per_s"] =
      crack_fence_seconds > 0 ? crack_invocations / crack_fence_seconds : 0;
}

// Registered from the technique registry in main, so a new technique is benchmarked
// without touching this file. Assets: smooth quads with extraordinary vertices (every
// quad technique, ACC included), triangles, and a mesh of both.
void registerTechniqueGpuBenchmarks() {
  for (const tb::techniques::Technique* technique :
       tb::techniques::TechniqueRegistry::instance().all()) {
    if (technique->info().family != tb::techniques::TechniqueFamily::kSurface) continue;
    for (const char* asset : {"catmark_xord_interior", "loop_icosahedron", "catmark_pyramid"}) {
      for (float level : {4.0f, 16.0f, 64.0f}) {
        const std::string suffix =
            technique->info().id + "/" + asset + "/level:" + std::to_string(int(level));
        benchmark::RegisterBenchmark(("gpu/" + suffix).c_str(),
                                     [technique, asset, level](benchmark::State& state) {
                                       drawAllPatches(state, technique, asset, level);
                                     })
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        for (const auto& [name, path] :
             {std::pair{"cracks_gpu/", CrackPath::kCapture},
              std::pair{"cracks_gpu_full_inner/", CrackPath::kCaptureFullInner},
              std::pair{"cracks_row_gpu/", CrackPath::kWholeRow}}) {
          benchmark::RegisterBenchmark((name + suffix).c_str(),
                                       [technique, asset, level, path](benchmark::State& state) {
                                         crackCapture(state, technique, asset, level, path);
                                       })
              ->UseManualTime()
              ->Unit(benchmark::kMillisecond);
        }
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerTechniqueGpuBenchmarks);
}
