// The adaptivity measure's algorithm (docs/derivations/adaptivity.md): a factor policy
// (factor_policy.h) run along a camera path, frame by frame, on the CPU twin and in the
// technique's own TCS on the device: counts against the device's statistics, crack safety
// of the factors, screen-space figures (screen_metrics.h), and the triangles per frame each
// policy needs to keep the tessellation error under 1 px against uniform levels and the
// ideal. Every figure and the ideal's definition: docs/derivations/adaptivity.md.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/gpu/context.h"
#include "core/view/view.h"
#include "harness/lod/factor_policy.h"
#include "harness/lod/screen_metrics.h"
#include "harness/measures/common/cracks/cracks.h"
#include "techniques/technique.h"

namespace tb::ref {
class LimitSurface;
}  // namespace tb::ref

namespace tb::measures {

struct AdaptivityFrame {
  uint32_t frame = 0;
  // CPU tessellator under the twin's levels, over every patch (no culling).
  uint64_t patches = 0, triangles = 0, domain_points = 0;
  // Shared edges whose sides' outer factors differ bitwise, from the twin's levels (best 0;
  // > 0 means the policy is not crack-safe).
  uint64_t factor_mismatches_cpu = 0;
  CrackFigures cracks_cpu;  // shared points under the frame's levels, CPU float
  lod::FrameScreenFigures screen;
  // Largest screen movement of the tessellated surface since the previous frame due to the
  // factor change alone (px; 0 on frame 0).
  lod::ScreenErrorFigures pop;

  // The device (absent without one, or without a GPU program).
  bool gpu_measured = false;
  uint64_t gpu_tcs_patches = 0, gpu_tes_invocations = 0, gpu_triangles = 0;
  bool gpu_triangles_counted = false;
  uint64_t twin_level_mismatches = 0;  // patches whose TCS levels differ from the twin's
  uint64_t factor_mismatches_gpu = 0;  // as factor_mismatches_cpu, from the TCS's levels
  CrackFigures cracks_gpu;             // device capture under the TCS's levels
  double gpu_host_s = 0;               // submit-to-fence seconds of the counting run

  // The compute path (AdaptivityParts::compute): the same policy's levels computed in compute
  // (core/gpu/compute_levels.h) and tessellated by the compute tessellator, counts only.
  bool compute_measured = false;
  uint64_t compute_level_mismatches = 0;  // patches whose compute levels differ from the TCS's
  uint64_t compute_triangles = 0, compute_domain_points = 0;
};

struct AdaptivitySummary {
  double error_target_px = 1;
  bool reached = false;  // some target of the policy keeps the error under error_target_px
  double target = 0;     // the coarsest such target (FactorPolicy::targetUnit())
  double triangles_per_frame = 0;  // mean over the path's frames at that target
  double max_error_px = 0;         // the path's largest tessellation error there
  // error_bound only: frames on which some patch's bound stays above the target even with
  // every level at the tessellator's top (lod::ErrorBoundUnmet::beyond_top), so no level the
  // hardware offers is certain to meet it there. Best 0; where it is above 0, max_error_px
  // may exceed the target on those frames (the asset is too close for the pixel target).
  uint32_t beyond_top_frames = 0;
  bool error_bound = false;  // the policy is error_bound (beyond_top_frames is measured)
  bool uniform_reached = false;
  uint32_t uniform_level = 0;  // the lowest uniform level reaching the error target
  double uniform_triangles_per_frame = 0;
  double uniform_max_error_px = 0;
  // triangles_per_frame / uniform_triangles_per_frame (best near 0; 1 = no saving).
  double triangle_ratio_vs_uniform = 0;
  // The ideal (AdaptivityRun::ideal): the fewest triangles per frame any one-level-per-edge
  // assignment of integer levels needs for the error target, per patch, mean over the path.
  double ideal_triangles_per_frame = 0;
  double ideal_max_error_px = 0;  // the path's largest tessellation error under the ideal
  // Frames on which the ideal took the uniform level (AdaptivityIdeal::uniform_frames):
  // best 0 (the per-patch search beat uniform on every frame), worst every frame.
  uint32_t ideal_uniform_frames = 0;
  // triangles_per_frame / ideal_triangles_per_frame: 1 (best, as few as the ideal), above 1
  // the policy's excess (2: twice the ideal's triangles); 0 when not reached.
  double triangle_ratio_vs_ideal = 0;
  uint32_t evaluations = 0;  // path passes the search took (the cached uniform and ideal once)
};

// The per-patch ideal along a path (AdaptivityRun::ideal).
struct AdaptivityIdeal {
  double triangles_per_frame = 0;
  double max_error_px = 0;
  uint32_t passes = 0;  // tessellation-error passes the search took over the path
  // Frames that took the uniform level (the per-patch search missed the target there, or
  // needed more triangles); best 0, worst every frame.
  uint32_t uniform_frames = 0;
};

// Which parts of a frame to measure (all by default; crack-safety checks need only the
// factors and cracks).
struct AdaptivityParts {
  bool screen = true;    // FrameScreenFigures and pops (counts then come from the tessellator)
  bool cracks = true;    // crack_* on both backends
  bool compute = false;  // compute_* (the compute path's levels and counts), with a device
};

// One technique instance along camera paths. Not thread-safe; parallel inside.
class AdaptivityRun {
 public:
  // context: null when no device is usable (gpu_unavailable says why); limit: the
  // reference limit of patches.controlMesh(), or null.
  AdaptivityRun(const techniques::SurfacePatches& patches, gpu::Context* context,
                std::string gpu_unavailable, const ref::LimitSurface* limit);
  ~AdaptivityRun();

  // Every frame of `views` under `policy` and `spacing`.
  std::vector<AdaptivityFrame> frames(const lod::FactorPolicy& policy, tess::Spacing spacing,
                                      const std::vector<view::View>& views,
                                      const AdaptivityParts& parts = {});

  // Searches the policy's target for the coarsest one whose tessellation error stays under
  // error_target_px on every frame, and the lowest uniform level that does.
  // search_steps: bisection steps on the log-scale target range (7: targets within ~5%
  // of the coarsest that passes for sphere_diameter's 0.25..128 px; 5: within ~20%).
  AdaptivitySummary summarise(const lod::FactorPolicy& policy, tess::Spacing spacing,
                              const std::vector<view::View>& views, double error_target_px,
                              int search_steps = 7);

  // The per-patch ideal for error_target_px under `spacing`, each frame: every patch's lowest
  // integer level within the target, by bisection on all patches at once between 1 and
  // `uniform_level` (0: none reaches it, then the top level); shared edges at the larger of
  // their patches' levels. A frame that misses the target or needs more triangles than
  // uniform takes the uniform level, so the ideal never does either. Cached per spacing and
  // target. Why this is a valid floor: docs/derivations/adaptivity.md ("The ideal").
  const AdaptivityIdeal& ideal(tess::Spacing spacing, const std::vector<view::View>& views,
                               double error_target_px, uint32_t uniform_level,
                               double uniform_triangles = 0);

  // Why `policy` cannot run on these patches (error_bound without the technique's
  // second-derivative bounds); empty when it can. Computes error_bound's inputs once.
  const std::string& policyUnavailable(const lod::FactorPolicy& policy);

  // Why the device parts are absent; empty when they ran.
  const std::string& gpuSkipReason() const { return gpu_skip_; }
  double diagonal() const { return diagonal_; }

 private:
  std::vector<tess::Levels> twinLevels(const lod::FactorPolicy& policy, tess::Spacing spacing,
                                       const view::View& view) const;
  // The max tessellation error over the path and the mean triangles per frame.
  struct PathError {
    double max_px = 0;
    double triangles_per_frame = 0;
    uint32_t beyond_top_frames = 0;  // error_bound: AdaptivitySummary::beyond_top_frames
  };
  // stop_above_px: a search step whose figures are kept only when it passes stops at the
  // first frame over it (the frame that failed last is tried first), so a failing step costs
  // a frame, not the path; its max_px is then that frame's (> stop_above_px) and nothing else
  // is set. Infinity: every frame (the figures a summary reports).
  PathError pathError(const lod::FactorPolicy& policy, tess::Spacing spacing,
                      const std::vector<view::View>& views,
                      double stop_above_px = std::numeric_limits<double>::infinity());
  // The lowest uniform level within the target (summarise's uniform part), cached per
  // spacing and views.
  struct UniformBest {
    uint32_t level = 1;
    bool reached = false;
    PathError error;
    uint32_t passes = 0;
  };
  const UniformBest& uniformBest(lod::InnerReduction reduction, tess::Spacing spacing,
                                 const std::vector<view::View>& views, double error_target_px);
  std::vector<tess::Levels> idealFrame(tess::Spacing spacing, const view::View& view,
                                       double error_target_px, uint32_t highest, uint32_t* passes);
  void runDevice(const lod::FactorPolicy& policy, tess::Spacing spacing, const view::View& view,
                 const std::vector<tess::Levels>& twin, const AdaptivityParts& parts,
                 AdaptivityFrame* frame);
  // The compute path's levels and counts for one program under `policy`'s words, against
  // the TCS's levels `tcs` (one per program patch).
  void runCompute(const gpu::GpuPatchProgram& program, tess::Spacing spacing,
                  const gpu::TcsFactorPolicy& policy, std::span<const tess::LevelsBits> tcs,
                  AdaptivityFrame* frame);
  void countTessellations(tess::Spacing spacing, const std::vector<tess::Levels>& levels,
                          AdaptivityFrame* frame) const;

  const techniques::SurfacePatches& patches_;
  gpu::Context* context_;
  std::string gpu_skip_;
  std::vector<gpu::GpuPatchProgram> programs_;
  lod::FactorCorners corners_;
  std::string error_bound_unavailable_;
  bool error_bounds_tried_ = false;
  // Keyed by the views too (viewsKey): one run may be summarised on several camera paths.
  std::map<std::tuple<int, int, double, uint64_t>, UniformBest> uniform_cache_;
  std::map<std::tuple<int, double, uint64_t>, AdaptivityIdeal> ideal_cache_;
  SharedBoundaries shared_;
  double diagonal_ = 0;
  size_t failing_frame_ = 0;  // pathError's first frame: the last one over stop_above_px
  std::unique_ptr<CrackSession> cracks_;
  std::unique_ptr<lod::ScreenMetrics> screen_;
};

// gl_TessLevelOuter index of local edge k (corner k to k + 1, techniques/technique.h).
size_t outerIndex(techniques::PatchDomain domain, uint32_t local_edge);

// A fingerprint of `views` (FNV-1a over their matrices, viewports and near planes): the
// summary caches' key, so a run summarised on two camera paths never mixes them.
uint64_t viewsKey(const std::vector<view::View>& views);

// Shared edges (of `shared`) whose sides' outer levels differ bitwise under `levels`.
uint64_t factorMismatches(const techniques::SurfacePatches& patches, const SharedBoundaries& shared,
                          const std::vector<tess::Levels>& levels);

}  // namespace tb::measures
