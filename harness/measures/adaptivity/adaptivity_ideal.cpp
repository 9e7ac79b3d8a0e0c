// AdaptivityRun::ideal: the fewest triangles a per-patch choice of integer levels needs for
// the error target, what every factor policy is held against (triangle_ratio_vs_ideal).
#include <algorithm>
#include <utility>

#include "harness/measures/adaptivity/adaptivity.h"

namespace tb::measures {
namespace {

// Every edge and the inside of a patch at `level` (a triangle leaves outer[3], inner[1] 0).
tess::Levels patchAt(techniques::PatchDomain domain, float level) {
  tess::Levels levels;
  if (domain == techniques::PatchDomain::kQuad) {
    levels.outer = {level, level, level, level};
    levels.inner = {level, level};
  } else {
    levels.outer = {level, level, level, 0};
    levels.inner = {level, 0};
  }
  return levels;
}

// Rounds of raising the patches the shared edges' levels put over the target.
constexpr int kIdealRepairRounds = 2;

}  // namespace

std::vector<tess::Levels> AdaptivityRun::idealFrame(tess::Spacing spacing, const view::View& view,
                                                    double error_target_px, uint32_t highest,
                                                    uint32_t* passes) {
  const size_t count = patches_.patchCount();
  // Per patch: the highest level known to fail (0: none yet) and the lowest known to pass
  // (`highest`: the uniform level that passes every patch on every frame, or the most there
  // is when none does).
  std::vector<uint32_t> fails(count, 0), passes_at(count, highest);
  std::vector<tess::Levels> trial(count);
  std::vector<double> patch_max;
  // Settled patches are culled (level 0) in the passes that follow, so they cost nothing.
  auto evaluate = [&](auto levelOf) {
    for (size_t p = 0; p < count; ++p)
      trial[p] = patchAt(patches_.patchDomain(p), float(levelOf(p)));
    screen_->tessellationError(spacing, trial, view, nullptr, &patch_max);
    ++*passes;
  };
  // Level 1 first (most patches off screen or flat pass there), then bisection.
  evaluate([&](size_t) { return highest > 1 ? 1u : 0u; });
  for (size_t p = 0; p < count && highest > 1; ++p) {
    if (patch_max[p] <= error_target_px)
      passes_at[p] = 1;
    else
      fails[p] = 1;
  }
  for (;;) {
    bool open = false;
    for (size_t p = 0; p < count; ++p) open = open || passes_at[p] - fails[p] > 1;
    if (!open) break;
    auto mid = [&](size_t p) {
      return passes_at[p] - fails[p] > 1 ? (fails[p] + passes_at[p]) / 2 : 0u;
    };
    evaluate(mid);
    for (size_t p = 0; p < count; ++p) {
      if (passes_at[p] - fails[p] <= 1) continue;
      (patch_max[p] <= error_target_px ? passes_at[p] : fails[p]) = mid(p);
    }
  }
  // A shared edge takes the larger need of its patches, so both sides get one level. The
  // transition between unequal levels, and samples that a coarse level left off screen, can
  // put a patch over the target again: such patches need more (half again, up to the most
  // there is), a few rounds.
  std::vector<tess::Levels> levels(count);
  const uint32_t most = spacing == tess::Spacing::kFractionalOdd ? 63 : 64;
  for (int round = 0;; ++round) {
    for (size_t p = 0; p < count; ++p)
      levels[p] = patchAt(patches_.patchDomain(p), float(passes_at[p]));
    for (const SharedEdge& edge : shared_.edges) {
      float level = 0;
      for (const PatchSide& side : edge.sides)
        level = std::max(level, float(passes_at[side.patch]));
      for (const PatchSide& side : edge.sides) {
        levels[side.patch].outer[outerIndex(patches_.patchDomain(side.patch), side.local)] = level;
      }
    }
    if (round == kIdealRepairRounds) break;
    screen_->tessellationError(spacing, levels, view, nullptr, &patch_max);
    ++*passes;
    bool raised = false;
    for (size_t p = 0; p < count; ++p) {
      if (patch_max[p] <= error_target_px || passes_at[p] >= most) continue;
      passes_at[p] = std::min(most, std::max(passes_at[p] + 1, passes_at[p] * 3 / 2));
      raised = true;
    }
    if (!raised) break;
  }
  return levels;
}

const AdaptivityIdeal& AdaptivityRun::ideal(tess::Spacing spacing,
                                            const std::vector<view::View>& views,
                                            double error_target_px, uint32_t uniform_level,
                                            double uniform_triangles) {
  const auto key = std::make_tuple(int(spacing), error_target_px, viewsKey(views));
  if (const auto it = ideal_cache_.find(key); it != ideal_cache_.end()) return it->second;
  const uint32_t highest =
      uniform_level > 0 ? uniform_level : (spacing == tess::Spacing::kFractionalOdd ? 63 : 64);
  AdaptivityIdeal out;
  uint64_t triangles = 0;
  std::vector<tess::Levels> uniform;
  if (uniform_level > 0) {
    for (size_t p = 0; p < patches_.patchCount(); ++p) {
      uniform.push_back(patchAt(patches_.patchDomain(p), float(uniform_level)));
    }
  }
  for (const view::View& view : views) {
    const std::vector<tess::Levels> levels =
        idealFrame(spacing, view, error_target_px, highest, &out.passes);
    uint64_t frame_triangles = 0;
    lod::ScreenErrorFigures e = screen_->tessellationError(spacing, levels, view, &frame_triangles);
    ++out.passes;
    const bool more = uniform_triangles > 0 && double(frame_triangles) > uniform_triangles;
    if (!uniform.empty() && (e.max_px > error_target_px || more)) {
      uint64_t uniform_frame = 0;
      const lod::ScreenErrorFigures u =
          screen_->tessellationError(spacing, uniform, view, &uniform_frame);
      ++out.passes;
      if (u.max_px <= error_target_px) {  // always, as the uniform search found it
        e = u;
        frame_triangles = uniform_frame;
        ++out.uniform_frames;
      }
    }
    out.max_error_px = std::max(out.max_error_px, e.max_px);
    triangles += frame_triangles;
  }
  out.triangles_per_frame = views.empty() ? 0 : double(triangles) / double(views.size());
  return ideal_cache_.emplace(key, out).first->second;
}

}  // namespace tb::measures
