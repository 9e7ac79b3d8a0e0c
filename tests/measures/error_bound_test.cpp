// The error_bound factor policy (harness/lod/factor_policy.h, error_bound.h) along the bundled
// camera paths: its levels keep the tessellation error within the pixel target on every frame
// with no search (acceptance 3), the loosened control (eps doubled) breaks it (acceptance 7),
// and the per-patch ideal is never above the best uniform level's triangles. The twin and
// crack checks run with the other policies in adaptivity_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "harness/lod/screen_metrics.h"
#include "harness/measures/adaptivity/adaptivity.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kTargetPx = 1.0;
constexpr const char* kPaths[] = {"orbit", "dolly", "flyby"};
constexpr const char* kSurfaceTechniques[] = {"acc", "gregory_acc", "osd_adaptive", "pn_triangles",
                                              "phong"};

std::vector<view::View> boundPathViews(const char* name, const techniques::SurfacePatches& patches,
                                       uint32_t frames = 0) {
  return suite::sampleCameraPath(suite::resolveCameraPath(name),
                                 mesh::boundsOf(patches.controlMesh()), frames)
      .views;
}

// A policy's largest tessellation error over `views` (CPU tessellator), overall and over the
// frames where error_bound met its bound on every patch (lod::errorBoundUnmetPatches).
struct PathBound {
  double worst = 0;      // px, every frame
  double worst_met = 0;  // px, the frames with no unmet patch
  size_t unmet_frames = 0, unmet_patches = 0;
  size_t below_top = 0;  // unmet patches that every level at the top would have met
  // Frames over the target, and of those the ones every patch at the top level (the finest
  // tessellation there is) keeps within it: best 0, where error_bound misses only where no
  // level can reach the target.
  size_t over_frames = 0, over_frames_top_meets = 0;
  double top_worst = 0;  // px, the top level's largest error on the frames over the target
};

PathBound boundPath(measures::AdaptivityRun& run, const lod::FactorCorners& corners,
                    const char* policy, const std::vector<view::View>& views,
                    tess::Spacing spacing) {
  PathBound out;
  const std::vector<measures::AdaptivityFrame> frames =
      run.frames(*lod::parseFactorPolicy(policy), spacing, views, {.cracks = false});
  for (size_t f = 0; f < frames.size(); ++f) {
    const double error = frames[f].screen.tessellation_error.max_px;
    if (error > kTargetPx) {  // the same frame with every patch at the top level
      lod::FactorPolicy uniform = *lod::parseFactorPolicy("uniform");
      uniform.target = 64;  // clamped to the spacing's top
      const double top_error = run.frames(uniform, spacing, {views[f]}, {.cracks = false})[0]
                                   .screen.tessellation_error.max_px;
      ++out.over_frames;
      out.over_frames_top_meets += top_error <= kTargetPx ? 1 : 0;
      out.top_worst = std::max(out.top_worst, top_error);
    }
    const lod::ErrorBoundUnmet unmet = lod::errorBoundUnmetPatches(
        lod::factorParams(*lod::parseFactorPolicy(policy), views[f], spacing, 1), corners);
    out.worst = std::max(out.worst, error);
    if (unmet.patches == 0) out.worst_met = std::max(out.worst_met, error);
    out.unmet_frames += unmet.patches > 0 ? 1 : 0;
    out.unmet_patches += unmet.patches;
    out.below_top += unmet.patches - unmet.beyond_top;
  }
  return out;
}

struct BoundSweep {
  size_t records = 0, frames = 0;
  std::vector<double> strict_max;  // per record x path x spacing: error_bound's largest error
  std::map<std::string, double> worst_by_path;  // path -> the largest of strict_max
  double worst_met = 0;      // the largest error on frames where every patch met the bound
  size_t unmet_frames = 0;   // frames (record x path x spacing) with an unmet patch
  size_t unmet_patches = 0;  // their unmet patches, summed over those frames
  size_t beyond_top = 0;     // of those, the patches even every level at the top leaves unmet
  size_t loose_over = 0;     // record x paths where the loose control exceeds the target
  size_t strict_over = 0;    // record x paths where error_bound (fractional_odd) exceeds it
  size_t caught = 0;         // record x paths where error_bound holds and the loose control fails
  std::vector<const char*> paths = {std::begin(kPaths), std::end(kPaths)};
};

// `technique`'s default variant on `asset`; empty where the technique refuses the mesh.
techniques::BuiltSurface defaultSurface(const techniques::Technique& technique,
                                        const std::string& asset) {
  const mesh::Mesh mesh = mesh::loadObjFile(::tb::testing::assetPath(asset));
  if (!technique.checkSupport(mesh).empty()) return nullptr;
  try {
    return techniques::buildSurface(technique, mesh, technique.variants().front());
  } catch (const techniques::UnsupportedInput&) {
    return nullptr;
  }
}

// error_bound and its loose control on `technique`'s default variant over `asset`, every path;
// `frames`: 0 for each path's own frame count. Wherever every patch met the bound, the error
// is within the target (acceptance 3); the loose control must exceed it somewhere (7).
void boundSweepOne(const char* technique_id, const std::string& asset, uint32_t frames,
                   BoundSweep* sweep) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  ASSERT_NE(technique, nullptr) << technique_id;
  const techniques::BuiltSurface surface = defaultSurface(*technique, asset);
  if (!surface) return;
  measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
  const std::string why = run.policyUnavailable(*lod::parseFactorPolicy("error_bound"));
  ASSERT_TRUE(why.empty()) << technique_id << " " << asset << ": " << why;
  lod::FactorCorners corners = lod::factorCorners(*surface);
  corners.error_bounds = lod::errorBounds(*surface).patches;
  ++sweep->records;
  for (const char* path : sweep->paths) {
    const std::vector<view::View> views = boundPathViews(path, *surface, frames);
    sweep->frames += views.size();
    const std::string where = std::string(technique_id) + " " + asset + " " + path;
    PathBound strict;
    for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
      strict = boundPath(run, corners, "error_bound", views, spacing);
      EXPECT_LE(strict.worst_met, kTargetPx) << where << " " << tess::toString(spacing);
      EXPECT_EQ(strict.below_top, 0u) << where << " " << tess::toString(spacing)
                                      << ": unmet patches the top level would have met";
      EXPECT_EQ(strict.over_frames_top_meets, 0u) << where << " " << tess::toString(spacing)
                                                  << ": over the target where the top level is not";
      if (strict.over_frames > 0) {
        std::printf(
            "[error_bound]   %s %s: %.3f px on %zu frames; every patch at the top level: "
            "%.3f px there\n",
            where.c_str(), std::string(tess::toString(spacing)).c_str(), strict.worst,
            strict.over_frames, strict.top_worst);
      }
      sweep->strict_max.push_back(strict.worst);
      sweep->worst_by_path[path] = std::max(sweep->worst_by_path[path], strict.worst);
      sweep->worst_met = std::max(sweep->worst_met, strict.worst_met);
      sweep->unmet_frames += strict.unmet_frames;
      sweep->unmet_patches += strict.unmet_patches;
      sweep->beyond_top += strict.unmet_patches - strict.below_top;
    }
    // fractional_odd (the measure's spacing) last: strict is its figures.
    const double loose =
        boundPath(run, corners, "error_bound_loose", views, tess::Spacing::kFractionalOdd).worst;
    sweep->strict_over += strict.worst > kTargetPx ? 1 : 0;
    sweep->loose_over += loose > kTargetPx ? 1 : 0;
    sweep->caught += strict.worst <= kTargetPx && loose > kTargetPx ? 1 : 0;
    if (strict.unmet_frames == 0) {
      EXPECT_GE(loose, strict.worst) << where << ": a looser bound gave a smaller error";
    }
  }
}

void boundReport(const char* name, BoundSweep sweep) {
  std::sort(sweep.strict_max.begin(), sweep.strict_max.end());
  const double median =
      sweep.strict_max.empty() ? 0 : sweep.strict_max[sweep.strict_max.size() / 2];
  std::printf(
      "[error_bound] %s: %zu records, %zu frames, median path max %.3f px; largest where "
      "every patch met the bound %.3f px; %zu frames with unmet patches (%zu patches, %zu "
      "beyond the top level); "
      "over %.0f px on %zu of %zu record x path (loose control: %zu, caught where "
      "error_bound holds: %zu); worst:",
      name, sweep.records, sweep.frames, median, sweep.worst_met, sweep.unmet_frames,
      sweep.unmet_patches, sweep.beyond_top, kTargetPx, sweep.strict_over,
      sweep.records * sweep.paths.size(), sweep.loose_over, sweep.caught);
  for (const auto& [path, worst] : sweep.worst_by_path)
    std::printf(" %s %.3f px", path.c_str(), worst);
  std::printf("\n");
}

// One curved asset per technique (CI), the paths at 12 frames each.
constexpr std::pair<const char*, const char*> kCiCases[] = {
    {"acc", "opensubdiv/catmark_torus.obj"},
    {"gregory_acc", "opensubdiv/catmark_nonquads.obj"},
    {"osd_adaptive", "opensubdiv/catmark_xord_interior.obj"},
    {"pn_triangles", "tessbench/tri_torus.obj"},
    {"phong", "tessbench/tri_pawn.obj"}};

// Acceptance 3 and 7, measured: error_bound's largest error per path, asserted within the
// target on every frame where every patch met the bound (the frames with unmet patches, where
// no inside level stitches narrowly to the patch's edges, are counted and reported), and the
// loosened control (eps doubled), which must fail where error_bound holds.
TEST(ErrorBound, LooseControlIsCaughtWhereTheBoundHolds) {
  BoundSweep sweep;
  // Under a sanitizer: acc alone, three frames a path (the same code, a sliver of the work;
  // at two the loose control stays within the target on acc's torus).
  const uint32_t frames = ::tb::testing::kUnderSanitizer ? 3 : 12;
  for (size_t c = 0; c < std::size(kCiCases);
       c += ::tb::testing::sweepStride(std::size(kCiCases))) {
    boundSweepOne(kCiCases[c].first, kCiCases[c].second, frames, &sweep);
  }
  EXPECT_GT(sweep.caught, 0u) << "the loosened bound was never caught where the bound holds";
  EXPECT_GT(sweep.loose_over, sweep.strict_over);
  boundReport("CI cases", sweep);
}

// The edge family is what makes the bound reachable: with error_bound's edges (narrow
// pairwise, transition_extents.h) every unmet patch needs more than the tessellator's top
// level, on every CI case, path and spacing; the control error_bound_dense, the same bound
// with edges at every equal-segment level, leaves patches unmet that the top level would
// have met (edges such as 33 and 45 that no inside level stitches to narrowly).
TEST(ErrorBound, OnlyTheTopLevelLeavesAPatchUnmet) {
  size_t strict_below = 0, strict_unmet = 0, dense_below = 0, dense_frames = 0;
  double dense_worst = 0, strict_worst = 0;
  const uint32_t frames = ::tb::testing::kUnderSanitizer ? 2 : 12;
  for (size_t c = 0; c < std::size(kCiCases);
       c += ::tb::testing::sweepStride(std::size(kCiCases))) {
    const techniques::BuiltSurface surface = defaultSurface(
        *techniques::TechniqueRegistry::instance().find(kCiCases[c].first), kCiCases[c].second);
    lod::FactorCorners corners = lod::factorCorners(*surface);
    corners.error_bounds = lod::errorBounds(*surface).patches;
    measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
    for (const char* path : {"dolly", "flyby"}) {
      const std::vector<view::View> views = boundPathViews(path, *surface, frames);
      const PathBound strict =
          boundPath(run, corners, "error_bound", views, tess::Spacing::kInteger);
      const PathBound dense =
          boundPath(run, corners, "error_bound_dense", views, tess::Spacing::kInteger);
      strict_below += strict.below_top;
      strict_unmet += strict.unmet_patches;
      strict_worst = std::max(strict_worst, strict.worst);
      dense_below += dense.below_top;
      dense_frames += dense.below_top > 0 ? 1 : 0;
      dense_worst = std::max(dense_worst, dense.worst);
    }
  }
  EXPECT_EQ(strict_below, 0u);
  EXPECT_GT(dense_below, 0u)
      << "the dense-edge control left no reachable patch unmet: the check shows nothing";
  std::printf(
      "[error_bound] CI cases, dolly and flyby, integer: error_bound %zu unmet patches, all "
      "beyond the top level, worst %.3f px; control error_bound_dense %zu unmet below the "
      "top (%zu paths), worst %.3f px\n",
      strict_unmet, strict_worst, dense_below, dense_frames, dense_worst);
}

// The whole of acceptance 3 on request (TB_ERROR_BOUND_EVERY_ASSET=1, not in CI): every surface
// technique on every bundled asset it accepts, every frame of every bundled path.
TEST(ErrorBound, EveryBundledAssetWhenAsked) {
  if (std::getenv("TB_ERROR_BOUND_EVERY_ASSET") == nullptr) {
    GTEST_SKIP() << "set TB_ERROR_BOUND_EVERY_ASSET=1 to sweep every bundled asset";
  }
  BoundSweep sweep;
  for (const char* technique : kSurfaceTechniques) {
    for (const std::string& asset : ::tb::testing::bundledObjs())
      boundSweepOne(technique, asset, 0, &sweep);
  }
  boundReport("every bundled asset", sweep);
}

// Acceptance 4 and 5 on request (TB_ERROR_BOUND_RATIOS=1, not in CI): error_bound's summary on
// every surface technique x bundled asset x path (fractional_odd, 24 frames a path: the
// dolly's 120 would take an hour), the median triangle ratios against uniform and the ideal
// per technique and path.
TEST(ErrorBound, RatiosOnEveryBundledAssetWhenAsked) {
  if (std::getenv("TB_ERROR_BOUND_RATIOS") == nullptr) {
    GTEST_SKIP() << "set TB_ERROR_BOUND_RATIOS=1 to summarise every bundled asset on every path";
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  for (const char* technique_id : kSurfaceTechniques) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(technique_id);
    std::map<std::string, std::vector<double>> vs_uniform, vs_ideal, error, ideal_vs_uniform;
    std::map<std::string, size_t> below_one;
    for (const std::string& asset : ::tb::testing::bundledObjs()) {
      const techniques::BuiltSurface surface = defaultSurface(*technique, asset);
      if (!surface) continue;
      measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
      if (!run.policyUnavailable(*lod::parseFactorPolicy("error_bound")).empty()) continue;
      for (const char* path : kPaths) {
        const measures::AdaptivitySummary s =
            run.summarise(*lod::parseFactorPolicy("error_bound"), tess::Spacing::kFractionalOdd,
                          boundPathViews(path, *surface, 24), kTargetPx);
        if (!s.uniform_reached || s.uniform_triangles_per_frame <= 0) continue;
        vs_uniform[path].push_back(s.triangle_ratio_vs_uniform);
        if (s.ideal_triangles_per_frame > 0)
          vs_ideal[path].push_back(s.triangles_per_frame / s.ideal_triangles_per_frame);
        const double ideal_share = s.ideal_triangles_per_frame / s.uniform_triangles_per_frame;
        ideal_vs_uniform[path].push_back(ideal_share);
        if (s.triangle_ratio_vs_uniform >= 1) {
          std::printf(
              "[error_bound]   %s %s %s: %.2f x uniform (ideal %.2f x uniform), max %.3f px\n",
              technique_id, asset.c_str(), path, s.triangle_ratio_vs_uniform, ideal_share,
              s.max_error_px);
        }
        error[path].push_back(s.max_error_px);
        below_one[path] += s.triangle_ratio_vs_uniform < 1 ? 1 : 0;
      }
    }
    for (const char* path : kPaths) {
      std::printf(
          "[error_bound] %s %s: %zu assets, median vs uniform %.2f (below 1 on %zu), "
          "median vs ideal %.2f (ideal vs uniform %.2f), median path max %.3f px, largest %.3f "
          "px\n",
          technique_id, path, vs_uniform[path].size(), median(vs_uniform[path]), below_one[path],
          median(vs_ideal[path]), median(ideal_vs_uniform[path]), median(error[path]),
          error[path].empty() ? 0.0 : *std::max_element(error[path].begin(), error[path].end()));
    }
  }
}

// The ideal is one of the assignments the uniform search also tries (every patch at the
// uniform level), so it never needs more triangles; error_bound's summary needs no search.
TEST(ErrorBound, IdealNeedsNoMoreThanUniformAndTheSummaryIsOnePass) {
  const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find("acc");
  const techniques::BuiltSurface surface = techniques::buildSurface(
      *technique, mesh::loadObjFile(::tb::testing::assetPath("opensubdiv/catmark_torus.obj")),
      technique->variants().front());
  measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
  const std::vector<view::View> views = boundPathViews("dolly", *surface, 8);
  const measures::AdaptivitySummary s = run.summarise(
      *lod::parseFactorPolicy("error_bound"), tess::Spacing::kFractionalOdd, views, kTargetPx);
  ASSERT_TRUE(s.reached);
  ASSERT_TRUE(s.uniform_reached);
  EXPECT_LE(s.max_error_px, kTargetPx);
  EXPECT_GT(s.ideal_triangles_per_frame, 0.0);
  EXPECT_LE(s.ideal_triangles_per_frame, s.uniform_triangles_per_frame);
  EXPECT_GE(s.triangle_ratio_vs_ideal, 1.0);  // error_bound is one per-edge assignment, bounded
  EXPECT_NEAR(s.triangle_ratio_vs_ideal, s.triangles_per_frame / s.ideal_triangles_per_frame,
              1e-12);
  const measures::AdaptivitySummary again = run.summarise(
      *lod::parseFactorPolicy("error_bound"), tess::Spacing::kFractionalOdd, views, kTargetPx);
  EXPECT_EQ(again.evaluations, s.evaluations);  // the uniform and ideal caches do not leak in
  EXPECT_EQ(again.ideal_triangles_per_frame, s.ideal_triangles_per_frame);
  std::printf(
      "[error_bound] acc torus dolly: error_bound %.0f, ideal %.0f, uniform %.0f "
      "triangles per frame (ratio vs uniform %.3f, vs ideal %.3f)\n",
      s.triangles_per_frame, s.ideal_triangles_per_frame, s.uniform_triangles_per_frame,
      s.triangle_ratio_vs_uniform, s.triangle_ratio_vs_ideal);
}

// frames_beyond_top_level says why error_bound missed the target: on acc's toroidal_tet
// dolly the camera comes so close that even the top level is over 1 px, and the summary
// counts those frames; the loose control (eps doubled) misses the target on acc's pawn orbit
// with no such frame, so the count is not merely "the error was over".
TEST(ErrorBound, FramesBeyondTheTopLevelExplainTheMisses) {
  const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find("acc");
  const auto summary = [&](const char* asset, const char* policy, const char* path,
                           uint32_t frames) {
    const techniques::BuiltSurface surface = defaultSurface(*technique, asset);
    measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
    EXPECT_TRUE(run.policyUnavailable(*lod::parseFactorPolicy(policy)).empty());
    return run.summarise(*lod::parseFactorPolicy(policy), tess::Spacing::kFractionalOdd,
                         boundPathViews(path, *surface, frames), kTargetPx);
  };
  // Under a sanitizer the dolly's two ends (the near one is over) and three orbit frames.
  const bool few = ::tb::testing::kUnderSanitizer;
  const measures::AdaptivitySummary close =
      summary("opensubdiv/catmark_toroidal_tet.obj", "error_bound", "dolly", few ? 2 : 12);
  const measures::AdaptivitySummary loose =
      summary("opensubdiv/catmark_pawn.obj", "error_bound_loose", "orbit", few ? 3 : 8);
  std::printf(
      "[error_bound] toroidal_tet dolly: %.3f px, %u frames beyond the top level; loose "
      "control on the pawn's orbit: %.3f px, %u\n",
      close.max_error_px, close.beyond_top_frames, loose.max_error_px, loose.beyond_top_frames);
  EXPECT_GT(close.max_error_px, kTargetPx);
  EXPECT_GT(close.beyond_top_frames, 0u);
  EXPECT_TRUE(close.error_bound);
  EXPECT_GT(loose.max_error_px, kTargetPx);
  EXPECT_EQ(loose.beyond_top_frames, 0u);
}

// The ideal is a valid assignment and never above uniform: on osd_adaptive's
// catmark_cube_corner3 orbit the per-patch search alone needs more triangles than the
// uniform level or misses the target on some frames (the control: those frames are
// counted), and there the frame takes the uniform level.
TEST(ErrorBound, TheIdealMeetsTheTargetAndNeverExceedsUniform) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find("osd_adaptive");
  const techniques::BuiltSurface surface =
      defaultSurface(*technique, "opensubdiv/catmark_cube_corner3.obj");
  ASSERT_TRUE(surface);
  measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
  const uint32_t frames = ::tb::testing::kUnderSanitizer ? 4 : 24;
  const std::vector<view::View> views = boundPathViews("orbit", *surface, frames);
  const measures::AdaptivitySummary s = run.summarise(
      *lod::parseFactorPolicy("error_bound"), tess::Spacing::kFractionalOdd, views, kTargetPx);
  ASSERT_TRUE(s.uniform_reached);
  const measures::AdaptivityIdeal& ideal =
      run.ideal(tess::Spacing::kFractionalOdd, views, kTargetPx, s.uniform_level,
                s.uniform_triangles_per_frame);
  EXPECT_GT(ideal.uniform_frames, 0u)
      << "the per-patch search was never beaten: the check shows nothing";
  EXPECT_LE(s.ideal_max_error_px, kTargetPx);
  EXPECT_LE(s.ideal_triangles_per_frame, s.uniform_triangles_per_frame);
  std::printf(
      "[error_bound] osd_adaptive cube_corner3 orbit: ideal %.0f triangles per frame (%.3f px), "
      "uniform %.0f; %u of %zu frames took the uniform level\n",
      s.ideal_triangles_per_frame, s.ideal_max_error_px, s.uniform_triangles_per_frame,
      ideal.uniform_frames, views.size());
}

}  // namespace
}  // namespace tb
