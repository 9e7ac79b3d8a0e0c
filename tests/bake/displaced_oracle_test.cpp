// The baker's oracle through the displaced technique (issue 17, acceptance 2): bake the
// analytic target (harness/bake/analytic_target.h: Bfr's limit displaced by a closed-form h),
// displace the technique by that map (DisplacedPatches, watertight), and measure the distance
// of the displaced surface to the target (Embree point queries) on a lattice of every patch.
//
// The bound, derived per asset: the map holds, at each texel centre, the distance along the
// displacement direction from the technique's surface to the target, so the displaced surface
// meets the target there up to the target's own tessellation error e_target; between texel
// centres it errs by the bilinear interpolation error of that distance over a texel of side
// 1/r in (u, v). Write the distance as g + d: g the displaced limit's offset (second
// derivative at most M, sampled as in baker_test.cpp) and d the technique's undisplaced
// deviation from the limit (at most e_tech, measured); bilinear interpolation errs on g by at
// most M (1/r)^2 / 4 (two directions, each M (1/r)^2 / 8) and on d by at most 2 e_tech. So
//   error <= 1.5 (M / (4 r^2) + 2 e_tech) + 2 e_target,
// the factor 1.5 for the sampled M and the cosine between direction and distance. The test
// also asks the error to fall as r doubles (4 -> 8 -> 16) while the map limits accuracy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/mesh/obj_loader.h"
#include "harness/bake/analytic_target.h"
#include "harness/bake/baker.h"
#include "harness/measures/error/error.h"
#include "reference/limit_surface.h"
#include "reference/triangle_distance_field.h"
#include "techniques/common/displaced_patches.h"
#include "techniques/registry.h"
#include "tests/bake/bake_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// Lattice points of a patch: a quad's (i/n, j/n), a triangle's barycentric (i/n, j/n, rest).
std::vector<techniques::DomainCoord> lattice(techniques::PatchDomain domain, int n) {
  std::vector<techniques::DomainCoord> points;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      if (domain == techniques::PatchDomain::kQuad) {
        points.push_back({u, v, 0});
      } else if (i + j <= n) {
        points.push_back({u, v, std::max(0.0, 1 - u - v)});
      }
    }
  }
  return points;
}

// Max distance from `patches` (sampled on lattice(13), off the texel centres of r = 4..16)
// to `target`.
double maxDistance(const techniques::SurfacePatches& patches,
                   const ref::TriangleDistanceField& target) {
  double worst = 0;
  uint32_t hint = ref::kNoTriangle;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    for (const techniques::DomainCoord& c : lattice(patches.patchDomain(p), 13)) {
      const mesh::Vec3d point = patches.evaluate(p, c).position;
      const ref::ClosestPoint hit = target.closest(point, hint);
      hint = hit.triangle;
      worst = std::max(worst, length(hit.point - point));
    }
  }
  return worst;
}

struct OracleCase {
  const char* technique;
  const char* asset;
};

TEST(DisplacedOracle, BakedAnalyticTargetIsReproducedWithinTheTexelBoundAndConverges) {
  const OracleCase cases[] = {
      {"acc", "opensubdiv/catmark_torus.obj"},
      {"gregory_acc", "opensubdiv/catmark_toroidal_tet.obj"},
      {"pn_triangles", "tessbench/tri_torus.obj"},
      {"phong", "tessbench/tri_torus.obj"},
  };
  constexpr int kTargetRate = 40;
  for (const OracleCase& c : cases) {
    SCOPED_TRACE(std::string(c.technique) + " on " + c.asset);
    const techniques::Technique& technique =
        *techniques::TechniqueRegistry::instance().find(c.technique);
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(c.asset));
    const techniques::BuiltSurface surface =
        techniques::buildSurface(technique, mesh, technique.variants().front());
    const osd::Scheme scheme = lod::referenceScheme(surface->approximates());
    const mesh::Mesh& control = surface->controlMesh();
    const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(control);
    const ref::LimitTessellation target = bake::analyticTargetMesh(control, scheme, kTargetRate, h);
    const ref::TriangleDistanceField target_field(target.view(), "analytic target");
    // e_target: the target's interpolation error, M_target / (4 n^2) (baker_test.cpp), and
    // e_tech: the undisplaced technique's distance to its undisplaced limit.
    const double m = testing::secondDerivativeBound(control, scheme, h);
    const double e_target = 1.5 * m / (4.0 * kTargetRate * kTargetRate);
    const ref::LimitTessellation limit = bake::analyticTargetMesh(
        control, scheme, kTargetRate, bake::AnalyticDisplacement{h.centre, h.diagonal, 0, 1});
    const double e_tech =
        maxDistance(*surface, ref::TriangleDistanceField(limit.view(), "limit")) + e_target;
    double previous = 0;
    for (uint32_t resolution : {4u, 8u, 16u}) {
      bake::BakeSettings settings;
      settings.resolution = resolution;
      const bake::BakeResult baked = bake::bakeDisplacement(*surface, target.view(), settings);
      EXPECT_EQ(baked.rays_missed, 0u);
      const auto map = std::make_shared<displacement::DisplacementMap>(baked.map);
      const techniques::DisplacedPatches displaced(
          *surface, map, techniques::DisplacementSampling::kWatertight, "baked");
      const double error = maxDistance(displaced, target_field);
      const double bound = 1.5 * (m / (4.0 * resolution * resolution) + 2 * e_tech) + 2 * e_target;
      std::printf(
          "[displaced oracle] %s %s r %u: max distance to target %.3e, bound %.3e "
          "(M %.3g, e_tech %.3e, e_target %.3e, A %.3e)\n",
          c.technique, c.asset, resolution, error, bound, m, e_tech, e_target, h.amplitude);
      EXPECT_LE(error, bound) << "r " << resolution;
      if (previous > 0) {
        EXPECT_LT(error, previous) << "r " << resolution;
      }
      previous = error;
    }
  }
}

}  // namespace
}  // namespace tb
