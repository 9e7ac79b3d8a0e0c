// Issue 41: a factor policy's levels and the tessellation they make, on the compute path
// (core/gpu/compute_levels.h: shaders/gpu/policy_levels.comp chained into the compute
// tessellator's count, scan and write passes, one submission, built once outside the
// timing, no read-back) against the hardware path (runPatchProgram with the policy in each
// technique's own TCS, capture off: TCS, tessellator and the technique's TES). Every surface
// technique's default variant on one bundled asset, sphere_diameter (8 px per edge) on
// frame 0 of the default camera path (orbit), fractional_odd spacing.
//
// Both timed by the host from submit to fence (lavapipe has no timestamps for tessellation
// draws); the compute path also by its GPU timestamps. Counters: points (domain points per
// run: TES invocations on the hardware path, points written on the compute path; equal),
// compute_points_per_s, tcs_points_per_s, compute_over_tcs (the rate ratio, one run),
// compute_gpu_points_per_s (timestamps), patches. The hardware path also evaluates the
// surface at every point (its TES); the compute path only tessellates.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench/technique_bench_support.h"
#include "core/gpu/compute_levels.h"
#include "core/gpu/context.h"
#include "core/gpu/patch_program.h"
#include "core/mesh/bounds.h"
#include "harness/lod/factor_policy.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"

namespace {

constexpr uint32_t kPolicyPatchesPerDraw = 8;  // technique_gpu_bench's batch
constexpr tb::tess::Spacing kPolicySpacing = tb::tess::Spacing::kFractionalOdd;

// The policy's device words and the jobs of every program of one surface.
struct PolicyBenchCase {
  std::vector<tb::gpu::GpuPatchProgram> programs;
  std::vector<tb::gpu::TcsFactorPolicy> policies;    // per program
  std::vector<std::vector<tb::tess::Levels>> twins;  // per program: the CPU twin's levels
  std::vector<tb::gpu::PolicyLevelsJob> jobs;        // per program
};

PolicyBenchCase policyCase(const tb::techniques::SurfacePatches& patches) {
  PolicyBenchCase c;
  c.programs = patches.gpuPrograms();
  const tb::mesh::Aabb box = tb::mesh::boundsOf(patches.controlMesh());
  const tb::view::CameraPath path =
      tb::suite::sampleCameraPath(tb::suite::resolveCameraPath("orbit"), box, 1);
  const tb::lod::FactorCorners corners = tb::lod::factorCorners(patches);
  const tb::lod::FactorParams params =
      tb::lod::factorParams(*tb::lod::parseFactorPolicy("sphere_diameter"), path.views[0],
                            kPolicySpacing, length(box.max - box.min));
  const std::vector<tb::tess::Levels> twin = tb::lod::policyLevels(params, corners);
  for (const tb::gpu::GpuPatchProgram& program : c.programs) {
    c.policies.push_back(tb::lod::tcsFactorPolicy(params, corners, program));
    std::vector<tb::tess::Levels>& levels = c.twins.emplace_back();
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      levels.push_back(twin[program.patch_ids.empty() ? i : program.patch_ids[i]]);
    }
  }
  for (size_t p = 0; p < c.programs.size(); ++p) {
    tb::gpu::PolicyLevelsJob job;
    job.domain = c.programs[p].domain;
    job.spacing = kPolicySpacing;
    job.patch_count = c.programs[p].patch_count;
    job.factor_policy = &c.policies[p];
    c.jobs.push_back(job);
  }
  return c;
}

// Every program through its TCS with the policy: {TES invocations, submit-to-fence s}.
std::pair<double, double> runOnTcs(tb::gpu::Context& context, const PolicyBenchCase& c) {
  double points = 0, seconds = 0;
  for (size_t p = 0; p < c.programs.size(); ++p) {
    tb::gpu::PatchProgramOptions options;
    options.spacing = kPolicySpacing;
    options.capture = false;
    options.patches_per_draw = kPolicyPatchesPerDraw;
    options.factor_policy = &c.policies[p];
    const tb::gpu::PatchProgramCapture run =
        tb::gpu::runPatchProgram(context, c.programs[p], c.twins[p], options);
    points += double(run.stats.tes_invocations);
    seconds += run.submit_to_fence_s;
  }
  return {points, seconds};
}

void policyLevelsAndTessellation(benchmark::State& state,
                                 const tb::techniques::Technique* technique,
                                 const std::string& asset) {
  static auto context = tb::gpu::Context::create();
  if (!context) {
    state.SkipWithError(("no usable Vulkan device: " + context.error()).c_str());
    return;
  }
  const tb::techniques::BuiltSurface patches =
      tb::bench::defaultVariantPatches(state, *technique, asset);
  if (!patches) return;
  const PolicyBenchCase c = policyCase(*patches);
  tb::gpu::PolicyTessellator compute(*context.value(), c.jobs);
  compute.run();  // pipelines warm, as runPatchProgram's are after its first call
  runOnTcs(*context.value(), c);
  double tcs_points = 0, tcs_s = 0, compute_s = 0, compute_gpu_s = 0;
  for (auto _ : state) {
    const tb::gpu::ComputeRunTiming timing = compute.run();
    compute_s += timing.submit_to_fence_s;
    compute_gpu_s += std::isnan(timing.gpu_ns) ? timing.submit_to_fence_s : timing.gpu_ns * 1e-9;
    const auto [points, seconds] = runOnTcs(*context.value(), c);
    tcs_points += points;
    tcs_s += seconds;
    state.SetIterationTime(timing.submit_to_fence_s + seconds);
  }
  const tb::gpu::PolicyTessellation out = compute.read();
  const double points = double(out.tessellation.points.size());
  const double runs = double(state.iterations());
  state.counters["points"] = points;
  state.counters["tcs_points"] = runs > 0 ? tcs_points / runs : 0;
  state.counters["compute_points_per_s"] = compute_s > 0 ? points * runs / compute_s : 0;
  state.counters["compute_gpu_points_per_s"] =
      compute_gpu_s > 0 ? points * runs / compute_gpu_s : 0;
  state.counters["tcs_points_per_s"] = tcs_s > 0 ? tcs_points / tcs_s : 0;
  state.counters["compute_over_tcs"] =
      compute_s > 0 && tcs_points > 0 ? (points * runs / compute_s) / (tcs_points / tcs_s) : 0;
  state.counters["patches"] = double(patches->patchCount());
}

void registerPolicyLevelsBenchmarks() {
  const std::pair<const char*, const char*> cases[] = {{"acc", "catmark_xord_interior"},
                                                       {"gregory_acc", "catmark_nonquads"},
                                                       {"osd_adaptive", "catmark_xord_interior"},
                                                       {"pn_triangles", "tri_torus"},
                                                       {"phong", "cylinder_seam"}};
  for (const auto& [id, asset] : cases) {
    const tb::techniques::Technique* technique =
        tb::techniques::TechniqueRegistry::instance().find(id);
    if (technique == nullptr) continue;
    const std::string name = std::string("policy_levels/sphere_diameter/") + id + "/" + asset;
    benchmark::RegisterBenchmark(name.c_str(),
                                 [technique, asset](benchmark::State& state) {
                                   policyLevelsAndTessellation(state, technique, asset);
                                 })
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  return tb::bench::runAfterRegistering(argc, argv, registerPolicyLevelsBenchmarks);
}
