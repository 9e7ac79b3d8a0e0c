#include "harness/measures/adaptivity/adaptivity.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "core/gpu/compute_levels.h"
#include "core/gpu/patch_program.h"
#include "core/mesh/bounds.h"
#include "core/mesh/fnv1a.h"

namespace tb::measures {
namespace {

// lavapipe tessellates on one thread and slows with many patches per draw (ARCHITECTURE
// §6): about this many TES invocations a draw.
constexpr uint64_t kInvocationsPerDraw = 4096;
constexpr uint32_t kMaxPatchesPerDraw = 256;

// The target range a search covers, per policy kind: coarse (few triangles) to fine.
struct TargetRange {
  double coarse, fine;
};
TargetRange targetRange(lod::FactorPolicyKind kind) {
  switch (kind) {
    case lod::FactorPolicyKind::kDistance:
      return {0.25, 4096};  // level at one diagonal
    case lod::FactorPolicyKind::kSphereDiameter:
      return {128, 0.25};  // pixels per edge
    case lod::FactorPolicyKind::kLp2Edge:
      return {0.002, 20};  // C
    case lod::FactorPolicyKind::kUniform:
    case lod::FactorPolicyKind::kErrorBound:  // not searched: its target is the error
      break;
  }
  return {1, 64};
}

uint32_t patchesPerDraw(std::span<const tess::Levels> levels) {
  float highest = 1;
  for (const tess::Levels& l : levels) {
    for (float x : l.outer) highest = std::max(highest, x);
    for (float x : l.inner) highest = std::max(highest, x);
  }
  const uint64_t side = uint64_t(std::ceil(std::min(highest, 64.0f))) + 1;
  return uint32_t(std::clamp<uint64_t>(kInvocationsPerDraw / (side * side), 1, kMaxPatchesPerDraw));
}

tess::Levels levelsFromBits(const tess::LevelsBits& bits) {
  tess::Levels levels;
  for (int i = 0; i < 4; ++i) levels.outer[i] = std::bit_cast<float>(bits[i]);
  for (int i = 0; i < 2; ++i) levels.inner[i] = std::bit_cast<float>(bits[4 + i]);
  return levels;
}

}  // namespace

size_t outerIndex(techniques::PatchDomain domain, uint32_t local_edge) {
  return domain == techniques::PatchDomain::kQuad ? (local_edge + 1) % 4 : (local_edge + 2) % 3;
}

uint64_t viewsKey(const std::vector<view::View>& views) {
  uint64_t hash = mesh::kFnv1aOffsetBasis;
  const auto mix = [&hash](uint64_t word) { hash = mesh::fnv1aWord(hash, word); };
  for (const view::View& view : views) {
    for (const auto& column : view.view_projection.m) {
      for (double x : column) mix(std::bit_cast<uint64_t>(x));
    }
    mix(view.viewport_width_px);
    mix(view.viewport_height_px);
    mix(std::bit_cast<uint64_t>(view.near_plane));
  }
  return hash;
}

uint64_t factorMismatches(const techniques::SurfacePatches& patches, const SharedBoundaries& shared,
                          const std::vector<tess::Levels>& levels) {
  uint64_t mismatches = 0;
  for (const SharedEdge& edge : shared.edges) {
    auto factorBits = [&](const PatchSide& side) {
      const size_t j = outerIndex(patches.patchDomain(side.patch), side.local);
      return std::bit_cast<uint32_t>(levels[side.patch].outer[j]);
    };
    const uint32_t first = factorBits(edge.sides.front());
    const bool differs =
        std::any_of(edge.sides.begin() + 1, edge.sides.end(),
                    [&](const PatchSide& side) { return factorBits(side) != first; });
    mismatches += differs ? 1 : 0;
  }
  return mismatches;
}

AdaptivityRun::AdaptivityRun(const techniques::SurfacePatches& patches, gpu::Context* context,
                             std::string gpu_unavailable, const ref::LimitSurface* limit)
    : patches_(patches),
      context_(context),
      programs_(patches.gpuPrograms()),
      corners_(lod::factorCorners(patches)),
      shared_(findSharedBoundaries(patches)),
      cracks_(std::make_unique<CrackSession>(patches)),
      screen_(std::make_unique<lod::ScreenMetrics>(patches, limit)) {
  if (programs_.empty()) {
    gpu_skip_ = "the technique has no GPU program";
  } else if (context_ == nullptr) {
    gpu_skip_ = "no Vulkan device (" + gpu_unavailable + ")";
  }
  if (!patches.controlMesh().positions.empty()) {
    diagonal_ = mesh::diagonalOf(mesh::boundsOf(patches.controlMesh()));
  }
}

AdaptivityRun::~AdaptivityRun() = default;

std::vector<tess::Levels> AdaptivityRun::twinLevels(const lod::FactorPolicy& policy,
                                                    tess::Spacing spacing,
                                                    const view::View& view) const {
  return lod::policyLevels(lod::factorParams(policy, view, spacing, diagonal_), corners_);
}

void AdaptivityRun::runDevice(const lod::FactorPolicy& policy, tess::Spacing spacing,
                              const view::View& view, const std::vector<tess::Levels>& twin,
                              const AdaptivityParts& parts, AdaptivityFrame* frame) {
  if (!gpu_skip_.empty()) return;
  const lod::FactorParams params = lod::factorParams(policy, view, spacing, diagonal_);
  std::vector<tess::Levels> device(twin.size());
  for (const gpu::GpuPatchProgram& program : programs_) {
    std::vector<tess::Levels> expected(program.patch_count);
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      expected[i] = twin[program.patch_ids.empty() ? i : program.patch_ids[i]];
    }
    const gpu::TcsFactorPolicy device_policy = lod::tcsFactorPolicy(params, corners_, program);
    gpu::PatchProgramOptions options;
    options.spacing = spacing;
    options.capture = false;
    options.statistics = true;
    options.patches_per_draw = patchesPerDraw(expected);
    options.factor_policy = &device_policy;
    const gpu::PatchProgramCapture run =
        gpu::runPatchProgram(*context_, program, expected, options);
    frame->gpu_tcs_patches += run.stats.tcs_patches;
    frame->gpu_tes_invocations += run.stats.tes_invocations;
    frame->gpu_triangles += run.stats.primitives_generated;
    frame->gpu_triangles_counted = run.stats.primitives_counted;
    frame->gpu_host_s += run.submit_to_fence_s;
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      const uint32_t patch = program.patch_ids.empty() ? i : program.patch_ids[i];
      device[patch] = levelsFromBits(run.tcs_levels[i]);
      if (run.tcs_levels[i] != tess::levelsBits(expected[i])) ++frame->twin_level_mismatches;
    }
    if (parts.compute) runCompute(program, spacing, device_policy, run.tcs_levels, frame);
  }
  frame->factor_mismatches_gpu = factorMismatches(patches_, shared_, device);
  if (parts.cracks) {
    frame->cracks_gpu = cracks_->measure(spacing, device, CrackBackend::kGpu, context_);
  }
  frame->gpu_measured = true;
}

void AdaptivityRun::runCompute(const gpu::GpuPatchProgram& program, tess::Spacing spacing,
                               const gpu::TcsFactorPolicy& policy,
                               std::span<const tess::LevelsBits> tcs, AdaptivityFrame* frame) {
  gpu::PolicyLevelsJob job;
  job.domain = program.domain;
  job.spacing = spacing;
  job.patch_count = program.patch_count;
  job.factor_policy = &policy;
  gpu::PolicyTessellator tessellator(*context_, std::span(&job, 1), /*counts_only=*/true);
  tessellator.run();
  const gpu::PolicyTessellation result = tessellator.read();
  for (uint32_t i = 0; i < program.patch_count; ++i) {
    if (result.levels[i] != tcs[i]) ++frame->compute_level_mismatches;
    const gpu::TessPatchRange& range = result.tessellation.patches[i];
    frame->compute_domain_points += range.point_count;
    frame->compute_triangles += range.index_count / 3;
  }
  frame->compute_measured = true;
}

void AdaptivityRun::countTessellations(tess::Spacing spacing,
                                       const std::vector<tess::Levels>& levels,
                                       AdaptivityFrame* frame) const {
  std::map<std::pair<techniques::PatchDomain, tess::LevelsBits>, std::pair<uint64_t, uint64_t>>
      counted;
  for (size_t p = 0; p < levels.size(); ++p) {
    const techniques::PatchDomain domain = patches_.patchDomain(p);
    auto [it, fresh] = counted.try_emplace({domain, tess::levelsBits(levels[p])});
    if (fresh) {
      const tess::Tessellation t = tess::tessellate(
          domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle,
          spacing, levels[p]);
      it->second = {t.points.size(), t.triangles.size()};
      if (t.culled) it->second = {0, 0};
    }
    if (it->second.first > 0) ++frame->patches;
    frame->domain_points += it->second.first;
    frame->triangles += it->second.second;
  }
}

std::vector<AdaptivityFrame> AdaptivityRun::frames(const lod::FactorPolicy& policy,
                                                   tess::Spacing spacing,
                                                   const std::vector<view::View>& views,
                                                   const AdaptivityParts& parts) {
  if (!policyUnavailable(policy).empty()) throw std::logic_error(policyUnavailable(policy));
  std::vector<AdaptivityFrame> frames;
  std::vector<tess::Levels> previous;
  for (size_t f = 0; f < views.size(); ++f) {
    AdaptivityFrame frame;
    frame.frame = uint32_t(f);
    const std::vector<tess::Levels> levels = twinLevels(policy, spacing, views[f]);
    if (parts.screen) {
      frame.screen = screen_->frame(spacing, levels, views[f]);
      frame.patches = frame.screen.patches;
      frame.triangles = frame.screen.triangles;
      frame.domain_points = frame.screen.domain_points;
      if (f > 0) frame.pop = screen_->pop(spacing, previous, levels, views[f]);
    } else {
      countTessellations(spacing, levels, &frame);
    }
    frame.factor_mismatches_cpu = factorMismatches(patches_, shared_, levels);
    if (parts.cracks) frame.cracks_cpu = cracks_->measure(spacing, levels, CrackBackend::kCpuFloat);
    runDevice(policy, spacing, views[f], levels, parts, &frame);
    frames.push_back(std::move(frame));
    previous = levels;
  }
  return frames;
}

AdaptivityRun::PathError AdaptivityRun::pathError(const lod::FactorPolicy& policy,
                                                  tess::Spacing spacing,
                                                  const std::vector<view::View>& views,
                                                  double stop_above_px) {
  PathError error;
  uint64_t triangles = 0;
  // The maximum, the triangle sum and the frame count do not depend on the frames' order.
  const bool stops = stop_above_px < std::numeric_limits<double>::infinity();
  const size_t first = stops && failing_frame_ < views.size() ? failing_frame_ : 0;
  for (size_t k = 0; k < views.size(); ++k) {
    const size_t f = (first + k) % views.size();
    uint64_t frame_triangles = 0;
    const lod::ScreenErrorFigures e = screen_->tessellationError(
        spacing, twinLevels(policy, spacing, views[f]), views[f], &frame_triangles);
    error.max_px = std::max(error.max_px, e.max_px);
    triangles += frame_triangles;
    if (policy.kind == lod::FactorPolicyKind::kErrorBound) {
      const lod::ErrorBoundUnmet unmet = lod::errorBoundUnmetPatches(
          lod::factorParams(policy, views[f], spacing, diagonal_), corners_);
      error.beyond_top_frames += unmet.beyond_top > 0 ? 1 : 0;
    }
    if (stops && e.max_px > stop_above_px) {
      failing_frame_ = f;
      return error;
    }
  }
  error.triangles_per_frame = views.empty() ? 0 : double(triangles) / double(views.size());
  return error;
}

const std::string& AdaptivityRun::policyUnavailable(const lod::FactorPolicy& policy) {
  static const std::string kNone;
  if (policy.kind != lod::FactorPolicyKind::kErrorBound) return kNone;
  if (!error_bounds_tried_) {
    error_bounds_tried_ = true;
    lod::ErrorBounds bounds = lod::errorBounds(patches_);
    corners_.error_bounds = std::move(bounds.patches);
    error_bound_unavailable_ = std::move(bounds.unavailable);
  }
  return error_bound_unavailable_;
}

AdaptivitySummary AdaptivityRun::summarise(const lod::FactorPolicy& policy, tess::Spacing spacing,
                                           const std::vector<view::View>& views,
                                           double error_target_px, int search_steps) {
  AdaptivitySummary summary;
  summary.error_target_px = error_target_px;
  if (!policyUnavailable(policy).empty()) throw std::logic_error(policyUnavailable(policy));

  // The policy: the coarsest target on a log scale whose path error is within the target;
  // error_bound's target is the error itself (one pass).
  const TargetRange range = targetRange(policy.kind);
  auto targetAt = [&](double fineness) {
    if (policy.kind == lod::FactorPolicyKind::kErrorBound) return error_target_px;
    return std::exp(std::log(range.coarse) +
                    fineness * (std::log(range.fine) - std::log(range.coarse)));
  };
  // stop_above_px: a step's figures are kept only when it passes (pathError).
  auto errorAt = [&](double fineness, double stop_above_px) {
    lod::FactorPolicy p = policy;
    p.target = targetAt(fineness);
    ++summary.evaluations;
    return pathError(p, spacing, views, stop_above_px);
  };
  const double kEvery = std::numeric_limits<double>::infinity();
  const bool kept_anyway = policy.kind == lod::FactorPolicyKind::kErrorBound;
  // Coarse to fine, so the cheap (coarse) end is tried first and the fine end, whose
  // tessellations are the largest, only when nothing coarser reaches the target.
  PathError best;
  double best_fineness = -1;
  const PathError coarse = errorAt(0.0, kept_anyway ? kEvery : error_target_px);
  if (coarse.max_px <= error_target_px || kept_anyway) {
    best = coarse;
    best_fineness = 0.0;
  } else {
    double fails = 0.0, passes = 1.0;
    for (int step = 0; step < search_steps; ++step) {
      const double mid = 0.5 * (fails + passes);
      const PathError e = errorAt(mid, error_target_px);
      if (e.max_px <= error_target_px) {
        best = e;
        best_fineness = passes = mid;
      } else {
        fails = mid;
      }
    }
    if (best_fineness < 0) {  // nothing passed: only the fine end is left to try
      best = errorAt(1.0, kEvery);
      best_fineness = 1.0;
    }
  }
  summary.reached = best.max_px <= error_target_px;
  summary.target = targetAt(best_fineness);
  summary.triangles_per_frame = best.triangles_per_frame;
  summary.max_error_px = best.max_px;
  summary.beyond_top_frames = best.beyond_top_frames;
  summary.error_bound = policy.kind == lod::FactorPolicyKind::kErrorBound;

  const UniformBest& uniform = uniformBest(policy.reduction, spacing, views, error_target_px);
  summary.evaluations += uniform.passes;
  summary.uniform_reached = uniform.reached;
  summary.uniform_level = uniform.level;
  summary.uniform_triangles_per_frame = uniform.error.triangles_per_frame;
  summary.uniform_max_error_px = uniform.error.max_px;
  summary.triangle_ratio_vs_uniform =
      summary.uniform_triangles_per_frame > 0
          ? summary.triangles_per_frame / summary.uniform_triangles_per_frame
          : 0;
  const AdaptivityIdeal& best_possible =
      ideal(spacing, views, error_target_px, uniform.reached ? uniform.level : 0,
            uniform.error.triangles_per_frame);
  summary.ideal_triangles_per_frame = best_possible.triangles_per_frame;
  summary.ideal_max_error_px = best_possible.max_error_px;
  summary.ideal_uniform_frames = best_possible.uniform_frames;
  summary.triangle_ratio_vs_ideal =
      summary.reached && best_possible.triangles_per_frame > 0
          ? summary.triangles_per_frame / best_possible.triangles_per_frame
          : 0;
  return summary;
}

const AdaptivityRun::UniformBest& AdaptivityRun::uniformBest(lod::InnerReduction reduction,
                                                             tess::Spacing spacing,
                                                             const std::vector<view::View>& views,
                                                             double error_target_px) {
  const auto key = std::make_tuple(int(reduction), int(spacing), error_target_px, viewsKey(views));
  if (const auto it = uniform_cache_.find(key); it != uniform_cache_.end()) return it->second;
  // The lowest integer level within the target, by doubling from 1 and then bisecting
  // between the last level that failed and the first that passed.
  UniformBest best;
  lod::FactorPolicy uniform;
  uniform.kind = lod::FactorPolicyKind::kUniform;
  uniform.reduction = reduction;
  const uint32_t highest = spacing == tess::Spacing::kFractionalOdd ? 63 : 64;
  // A failing level's figures are kept only at the top level (nothing passed): below it
  // the step may stop at the first frame over the target (pathError).
  auto uniformAt = [&](uint32_t level) {
    uniform.target = level;
    ++best.passes;
    return pathError(uniform, spacing, views,
                     level < highest ? error_target_px : std::numeric_limits<double>::infinity());
  };
  uint32_t fails = 0;
  best.error = uniformAt(best.level);
  while (best.error.max_px > error_target_px && best.level < highest) {
    fails = best.level;
    best.level = std::min(2 * best.level, highest);
    best.error = uniformAt(best.level);
  }
  best.reached = best.error.max_px <= error_target_px;
  if (best.reached) {
    while (best.level - fails > 1) {
      const uint32_t mid = (fails + best.level) / 2;
      const PathError e = uniformAt(mid);
      if (e.max_px <= error_target_px) {
        best.error = e;
        best.level = mid;
      } else {
        fails = mid;
      }
    }
  }
  return uniform_cache_.emplace(key, best).first->second;
}

}  // namespace tb::measures
