// Acceptance 4 against the issue's own prescription: the fewest triangles any policy built as
// the issue prescribes can use, whatever bound it proves, against the best uniform level.
//
// The prescription (issue 37, "Deliver"): each edge's level n = sqrt(sup|C''| / (8 eps)) from
// its boundary curve (Wang), the inside's n = sqrt((M_uu + 2 M_uv + M_vv) / (8 eps)) (Filip,
// Magedson & Markot; the same on a triangle), eps = target_px z_near / f_px with z_near the
// nearest depth of the patch's control hull, f_px = H / (2 tan(fov_y / 2)). Any bound M is at
// least the supremum it bounds, and the supremum at least any sample of it taken with the
// exact identities of tests/curvature_samples.h. So this floor takes every choice in the
// policy's favour:
//  - M: the sampled second derivatives (at most the true suprema, so at most any bound);
//  - eps: the patch hull's nearest clip w, at least the near plane's (the prescription gives a
//    hull crossing the near plane the top level); an edge's eps from its own curve's control
//    points (at least the patch's), so both sides agree without taking the larger;
//  - a patch whose hull lies wholly outside one side of the view takes level 1 (its samples
//    are not visible; the prescription does not allow even that);
//  - levels exactly the formula's real values, no rounding to a family or to whole levels,
//    no transition rings; the tessellator's triangle count only rises with a level.
// Where this floor needs more triangles than the best uniform level, no policy that follows
// the prescription can reach acceptance 4's ratio at most 1 there, however tight its bound.
// The quad inside's anisotropic variant (n_u, n_v from (M_uu + M_uv) / (8 n_u^2) +
// (M_vv + M_uv) / (8 n_v^2) <= eps, the form error_bound uses) is computed beside it, and the
// floor is the smaller of the two.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "harness/measures/adaptivity/adaptivity.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/curvature_samples.h"
#include "tests/test_support.h"

namespace tb::error_bound_floor_test {
namespace {

using techniques::PatchDomain;
namespace testing = ::tb::testing;

constexpr double kTargetPx = 1.0;

// One patch as the floor reads it: its sampled second derivatives (tests/curvature_samples.h)
// and the control points its and its edges' eps come from.
struct FloorPatch {
  PatchDomain domain = PatchDomain::kQuad;
  testing::Sampled m{};
  std::vector<mesh::Vec3d> hull;
  std::array<std::vector<mesh::Vec3d>, 4> edge_hull;
};

// The nearest clip w of `points` under `view`, at least the near plane's.
double nearestW(const view::View& view, const std::vector<mesh::Vec3d>& points) {
  double w = INFINITY;
  for (const mesh::Vec3d& p : points) {
    w = std::min(w, view.view_projection.transform({p[0], p[1], p[2], 1})[3]);
  }
  return std::max(w, view.near_plane);
}

// True when every point lies outside one side of the view (Vulkan clip: |x|, |y| <= w).
bool outsideView(const view::View& view, const std::vector<mesh::Vec3d>& points) {
  std::array<bool, 4> all_out{true, true, true, true};  // x > w, x < -w, y > w, y < -w
  for (const mesh::Vec3d& p : points) {
    const std::array<double, 4> c = view.view_projection.transform({p[0], p[1], p[2], 1});
    all_out[0] = all_out[0] && c[0] > c[3];
    all_out[1] = all_out[1] && c[0] < -c[3];
    all_out[2] = all_out[2] && c[1] > c[3];
    all_out[3] = all_out[3] && c[1] < -c[3];
  }
  return all_out[0] || all_out[1] || all_out[2] || all_out[3];
}

// The prescription's level for a second-derivative sum `m` at world error `eps`, clamped.
float prescribedLevel(double m, double eps, tess::Spacing spacing) {
  const double n = std::sqrt(m / (8 * eps));
  return float(std::clamp(n, 1.0, double(tess::maxLevel(spacing))));
}

// The floor's levels for one patch and view: {isotropic, anisotropic}, the latter with the
// quad inside per direction (the same edges; a triangle's two are equal).
std::array<tess::Levels, 2> floorLevels(const FloorPatch& patch, const view::View& view,
                                        tess::Spacing spacing) {
  tess::Levels levels;  // all 1
  if (outsideView(view, patch.hull)) return {levels, levels};
  const double f_px = 0.5 * view.viewport_height_px * view.projection_y_scale;
  const auto eps = [&](const std::vector<mesh::Vec3d>& points) {
    return kTargetPx * nearestW(view, points) / f_px;
  };
  const double e = eps(patch.hull);
  const double uu = patch.m[0], uv = patch.m[1], vv = patch.m[2];
  const bool quad = patch.domain == PatchDomain::kQuad;
  for (size_t j = 0; j < (quad ? 4u : 3u); ++j) {
    levels.outer[j] = prescribedLevel(patch.m[3 + j], eps(patch.edge_hull[j]), spacing);
  }
  const float inner = prescribedLevel(uu + 2 * uv + vv, e, spacing);
  levels.inner = {inner, inner};
  tess::Levels anisotropic = levels;
  if (quad) {  // a / n_u^2 = b / n_v^2 = eps / 2 minimises n_u n_v
    anisotropic.inner = {prescribedLevel(2 * (uu + uv), e, spacing),
                         prescribedLevel(2 * (vv + uv), e, spacing)};
  }
  return {levels, anisotropic};
}

struct FloorFigures {
  double isotropic = 0, anisotropic = 0;  // triangles per frame
  // The floor: either form is one a policy may take, so the smaller (the tessellator's
  // whole segments can make the anisotropic pair the larger).
  double least() const { return std::min(isotropic, anisotropic); }
};

FloorFigures floorTriangles(const std::vector<FloorPatch>& patches,
                            const std::vector<view::View>& views, tess::Spacing spacing) {
  FloorFigures out;
  std::map<std::pair<int, tess::LevelsBits>, size_t> counts;  // (domain, levels) -> triangles
  const auto count = [&](PatchDomain domain, const tess::Levels& levels) {
    const tess::Domain d =
        domain == PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle;
    const auto key = std::make_pair(int(d), tess::levelsBits(levels));
    auto it = counts.find(key);
    if (it == counts.end())
      it = counts.emplace(key, tess::tessellate(d, spacing, levels).triangles.size()).first;
    return double(it->second);
  };
  for (const view::View& view : views) {
    for (const FloorPatch& patch : patches) {
      const std::array<tess::Levels, 2> levels = floorLevels(patch, view, spacing);
      out.isotropic += count(patch.domain, levels[0]);
      out.anisotropic += count(patch.domain, levels[1]);
    }
  }
  out.isotropic /= double(views.size());
  out.anisotropic /= double(views.size());
  return out;
}

// Samples per direction (tests/curvature_samples.h): 24 comes within 1/72 of a triangle's
// corners, where Gregory's blends bend most (at 6 the sampled Gregory suprema are a fifth lower).
constexpr int kFloorSamples = 24;

std::vector<FloorPatch> floorPatches(const techniques::SurfacePatches& s) {
  std::vector<FloorPatch> out(s.patchCount());
  for (size_t p = 0; p < out.size(); ++p) {
    const techniques::CurvatureBounds b = s.curvatureBounds(p).value();
    out[p] = {s.patchDomain(p), testing::sampleSecondDerivatives(s, p, kFloorSamples), b.hull,
              b.edge_hull};
  }
  return out;
}

// One record: error_bound's summary (its uniform and ideal) and the floor, on `path`.
struct FloorRecord {
  measures::AdaptivitySummary summary;
  FloorFigures floor;
  // The control: the floor with the sampled second derivatives divided by 16, no longer below
  // every bound (kControlScale).
  FloorFigures control;
  bool ran = false;
};

constexpr double kControlScale = 1.0 / 16;

FloorRecord floorRecord(const char* technique_id, const std::string& asset, const char* path,
                        uint32_t frames, tess::Spacing spacing = tess::Spacing::kFractionalOdd) {
  FloorRecord out;
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
  if (technique == nullptr || !technique->checkSupport(mesh).empty()) return out;
  const techniques::BuiltSurface surface =
      techniques::buildSurface(*technique, mesh, technique->variants().front());
  measures::AdaptivityRun run(*surface, nullptr, "CPU only", nullptr);
  if (!run.policyUnavailable(*lod::parseFactorPolicy("error_bound")).empty()) return out;
  const std::vector<view::View> views =
      suite::sampleCameraPath(suite::resolveCameraPath(path),
                              mesh::boundsOf(surface->controlMesh()), frames)
          .views;
  out.summary = run.summarise(*lod::parseFactorPolicy("error_bound"), spacing, views, kTargetPx);
  std::vector<FloorPatch> patches = floorPatches(*surface);
  out.floor = floorTriangles(patches, views, spacing);
  for (FloorPatch& p : patches) {
    for (double& m : p.m) m *= kControlScale;
  }
  out.control = floorTriangles(patches, views, spacing);
  out.ran = out.summary.uniform_reached && out.summary.uniform_triangles_per_frame > 0;
  return out;
}

void printRecord(const char* technique, const std::string& asset, const char* path,
                 tess::Spacing spacing, const FloorRecord& r) {
  const double u = r.summary.uniform_triangles_per_frame;
  std::printf(
      "[floor] %s %s %s %s: uniform L%u %.0f; ideal %.2f x, error_bound %.2f x, prescription "
      "floor %.2f x (anisotropic %.2f x) uniform's triangles\n",
      technique, asset.c_str(), path, std::string(tess::toString(spacing)).c_str(),
      r.summary.uniform_level, u, r.summary.ideal_triangles_per_frame / u,
      r.summary.triangle_ratio_vs_uniform, r.floor.isotropic / u, r.floor.anisotropic / u);
}

// One record per surface technique (and gregory_acc on the flyby) where the prescription's
// floor needs more triangles than the best uniform level at the same spacing, integer and
// fractional_odd: there acceptance 4's ratio cannot be at most 1 for any policy built as the
// issue prescribes. The control: the same floor with the sampled second derivatives divided by
// 16 (no longer below every bound) falls below uniform on each, so the check rests on the
// sizes of the bounds and not on the count alone.
struct FloorCase {
  const char* technique;
  const char* asset;
  const char* path;
};
constexpr FloorCase kAboveUniform[] = {
    {"acc", "opensubdiv/catmark_cube.obj", "orbit"},
    {"gregory_acc", "opensubdiv/loop_icosahedron.obj", "orbit"},
    {"gregory_acc", "opensubdiv/catmark_pyramid.obj", "flyby"},
    {"osd_adaptive", "opensubdiv/catmark_cube.obj", "orbit"},
    {"pn_triangles", "opensubdiv/catmark_pyramid_creases1.obj", "orbit"},
    {"phong", "opensubdiv/loop_icosahedron.obj", "orbit"}};

TEST(ErrorBoundFloor, ThePrescriptionNeedsMoreThanUniformOnTheseRecords) {
  // Under a sanitizer every other case at fractional_odd over 8 frames (the same code, less of
  // the work).
  const bool few = testing::kUnderSanitizer;
  const uint32_t frames = few ? 8 : 24;
  for (size_t c = 0; c < std::size(kAboveUniform); c += few ? 2 : 1) {
    const FloorCase& fc = kAboveUniform[c];
    for (tess::Spacing spacing : {tess::Spacing::kFractionalOdd, tess::Spacing::kInteger}) {
      if (few && spacing == tess::Spacing::kInteger) continue;
      const std::string where = std::string(fc.technique) + " " + fc.asset + " " + fc.path + " " +
                                std::string(tess::toString(spacing));
      const FloorRecord r = floorRecord(fc.technique, fc.asset, fc.path, frames, spacing);
      ASSERT_TRUE(r.ran) << where;
      printRecord(fc.technique, fc.asset, fc.path, spacing, r);
      const double uniform = r.summary.uniform_triangles_per_frame;
      EXPECT_GT(r.floor.least(), uniform) << where;
      EXPECT_GT(r.summary.triangles_per_frame, r.floor.least())
          << where << ": error_bound below its floor";
      EXPECT_LT(r.control.least(), uniform) << where << ": the control stayed above uniform";
    }
  }
}

// Every surface technique x bundled asset x path on request (TB_ERROR_BOUND_FLOOR=1, not in
// CI; 24 frames a path, fractional_odd, as RatiosOnEveryBundledAssetWhenAsked): per record the
// floor against uniform, and per technique and path how many records the floor alone puts
// above uniform.
TEST(ErrorBoundFloor, EveryBundledAssetWhenAsked) {
  if (std::getenv("TB_ERROR_BOUND_FLOOR") == nullptr) {
    GTEST_SKIP() << "set TB_ERROR_BOUND_FLOOR=1 to compute the prescription's floor everywhere";
  }
  for (const char* technique : {"acc", "gregory_acc", "osd_adaptive", "pn_triangles", "phong"}) {
    for (const char* path : {"orbit", "dolly", "flyby"}) {
      size_t records = 0, floor_above = 0, bound_above = 0, both = 0;
      for (const std::string& asset : testing::bundledObjs()) {
        const FloorRecord r = floorRecord(technique, asset, path, 24);
        if (!r.ran) continue;
        ++records;
        const bool above = r.floor.least() > r.summary.uniform_triangles_per_frame;
        // Acceptance 4: at most 1 on the orbit, below 1 on the dolly and the flyby.
        const double ratio = r.summary.triangle_ratio_vs_uniform;
        const bool bound = std::string(path) == "orbit" ? ratio > 1 : ratio >= 1;
        floor_above += above ? 1 : 0;
        bound_above += bound ? 1 : 0;
        both += above && bound ? 1 : 0;
        if (above || bound) printRecord(technique, asset, path, tess::Spacing::kFractionalOdd, r);
      }
      std::printf(
          "[floor] %s %s: %zu records; error_bound misses acceptance 4 on %zu, the "
          "prescription's floor is above uniform on %zu (%zu of the misses)\n",
          technique, path, records, bound_above, floor_above, both);
    }
  }
}

}  // namespace
}  // namespace tb::error_bound_floor_test
