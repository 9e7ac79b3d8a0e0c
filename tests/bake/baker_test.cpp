// The baker against its oracle (harness/bake/analytic_target.h): the target is the exact
// limit surface (OpenSubdiv Bfr) displaced along its normal by the analytic h, so on a
// technique that equals the limit (acc on regular quads, to ~1e-12) every scalar texel must
// be h at the texel's surface point, up to the target's tessellation error.
#include "harness/bake/baker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/displacement/exr_io.h"
#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "harness/bake/analytic_target.h"
#include "harness/measures/error/error.h"
#include "reference/limit_surface.h"
#include "techniques/registry.h"
#include "tests/bake/bake_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

struct Fixture {
  mesh::Mesh mesh;
  techniques::BuiltSurface patches;
};

Fixture build(const std::string& technique_id, const std::string& asset) {
  Fixture f;
  f.mesh = mesh::loadObjFile(testing::assetPath(asset));
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  EXPECT_NE(technique, nullptr);
  f.patches = techniques::buildSurface(*technique, f.mesh, technique->variants().front());
  return f;
}

osd::Scheme schemeOf(const techniques::SurfacePatches& patches) {
  return lod::referenceScheme(patches.approximates());
}

// Max |texel - h(S(u, v))| over the interior texels of every tile.
double maxOracleError(const techniques::SurfacePatches& patches, const bake::BakeResult& result,
                      const bake::BakeSettings& settings, const bake::AnalyticDisplacement& h) {
  const displacement::DisplacementMap& map = result.map;
  double worst = 0;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const uint32_t x0 = uint32_t(p % map.tiles.tiles_per_row) * map.tiles.tile_size;
    const uint32_t y0 = uint32_t(p / map.tiles.tiles_per_row) * map.tiles.tile_size;
    for (uint32_t y = settings.border; y < settings.border + settings.resolution; ++y) {
      for (uint32_t x = settings.border; x < settings.border + settings.resolution; ++x) {
        const bake::TexelParameter t = bake::texelParameter(x, y, settings);
        const techniques::SurfacePoint s = patches.evaluate(p, {t.u, t.v, 0});
        worst = std::max(worst, std::abs(map.at(x0 + x, y0 + y, 0) - h.height(s.position)));
      }
    }
  }
  return worst;
}

TEST(BakerOracle, AccScalarTexelsEqualTheAnalyticHeightWithinTheTessellationBound) {
  // Oracle: Bfr's limit of catmark_torus (all regular quads, acc = limit to ~1e-12). The
  // target is a piecewise-linear interpolant of S_d over right triangles with legs 1/n in
  // (u, v); linear interpolation on a triangle errs by at most M R^2 / 2, R its smallest
  // enclosing radius (sqrt 2 / (2n)), so by M / (4 n^2). A ray along the normal meets that
  // error divided by the cosine between the ray and S_d's normal (slope <= 0.08, cos > 0.99);
  // bound = 1.5 M / (4 n^2) leaves room for the sampled M and the cosine.
  const Fixture f = build("acc", "opensubdiv/catmark_torus.obj");
  const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(f.patches->controlMesh());
  const osd::Scheme scheme = schemeOf(*f.patches);
  const double m = testing::secondDerivativeBound(f.patches->controlMesh(), scheme, h);
  // Texel centres k / 7 fall on the target's grid vertices (multiples of 1/8), where the
  // interpolant is exact and the check could not fail, only at k = 0 and 7.
  bake::BakeSettings settings;
  settings.resolution = 8;
  double previous = 0;
  for (int rate : {8, 16, 32}) {
    const ref::LimitTessellation target =
        bake::analyticTargetMesh(f.patches->controlMesh(), scheme, rate, h);
    const bake::BakeResult result = bake::bakeDisplacement(*f.patches, target.view(), settings);
    EXPECT_EQ(result.rays_missed, 0u);
    const double error = maxOracleError(*f.patches, result, settings, h);
    const double bound = 1.5 * m / (4.0 * rate * rate);
    std::printf("rate %d: max |texel - h| = %.3e, bound %.3e (A = %.3e)\n", rate, error, bound,
                h.amplitude);
    EXPECT_LE(error, bound) << "rate " << rate;
    if (previous > 0) {
      EXPECT_LT(error, 0.5 * previous) << "rate " << rate;  // ~1/4 per doubling
    }
    previous = error;
  }
}

TEST(BakerOracle, AccVectorTexelsHaveLengthHAndPointAlongTheNormal) {
  // The closest point of S_d to S = L lies off the normal by at most S_d's slope over the
  // limit (|grad h| / (1 - |h| k) < 0.082 rad here), so |d| = |h| to within |h|(1 - cos 0.082)
  // (< 0.004 A) plus the tessellation bound, and d is within 0.1 rad of +-n.
  const Fixture f = build("acc", "opensubdiv/catmark_torus.obj");
  const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(f.patches->controlMesh());
  const ref::LimitTessellation target =
      bake::analyticTargetMesh(f.patches->controlMesh(), schemeOf(*f.patches), 32, h);
  bake::BakeSettings settings;
  settings.kind = displacement::DisplacementKind::kVector;
  settings.resolution = 6;
  const bake::BakeResult result = bake::bakeDisplacement(*f.patches, target.view(), settings);
  EXPECT_EQ(result.rays_missed, 0u);
  const displacement::DisplacementMap& map = result.map;
  size_t checked_direction = 0;
  for (size_t p = 0; p < f.patches->patchCount(); ++p) {
    const uint32_t x0 = uint32_t(p % map.tiles.tiles_per_row) * map.tiles.tile_size;
    const uint32_t y0 = uint32_t(p / map.tiles.tiles_per_row) * map.tiles.tile_size;
    for (uint32_t y = 1; y <= settings.resolution; ++y) {
      for (uint32_t x = 1; x <= settings.resolution; ++x) {
        const bake::TexelParameter t = bake::texelParameter(x, y, settings);
        const techniques::SurfacePoint s = f.patches->evaluate(p, {t.u, t.v, 0});
        const double expected = h.height(s.position);
        const mesh::Vec3d d{map.at(x0 + x, y0 + y, 0), map.at(x0 + x, y0 + y, 1),
                            map.at(x0 + x, y0 + y, 2)};
        EXPECT_NEAR(length(d), std::abs(expected), 0.01 * h.amplitude) << "patch " << p;
        if (std::abs(expected) > 0.2 * h.amplitude) {
          ++checked_direction;
          const mesh::Vec3d along = normalize(d) * (expected > 0 ? 1.0 : -1.0);
          EXPECT_GT(dot(along, s.normal), std::cos(0.1)) << "patch " << p;
        }
      }
    }
  }
  EXPECT_GT(checked_direction, 100u);
}

TEST(BakerOracle, TriangleTechniqueOnALoopTargetBakesWithoutMisses) {
  const Fixture f = build("pn_triangles", "tessbench/tri_torus.obj");
  const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(f.patches->controlMesh());
  const osd::Scheme scheme = schemeOf(*f.patches);
  EXPECT_EQ(scheme, osd::Scheme::kLoop);
  const ref::LimitTessellation target =
      bake::analyticTargetMesh(f.patches->controlMesh(), scheme, 16, h);
  bake::BakeSettings settings;
  settings.resolution = 8;
  const bake::BakeResult result = bake::bakeDisplacement(*f.patches, target.view(), settings);
  EXPECT_EQ(result.rays_missed, 0u);
  // Texels with u + v <= 1 + 1/7 of a 10 x 10 tile (border 1, texel step 1/7).
  size_t per_tile = 0;
  for (uint32_t y = 0; y < 10; ++y) {
    for (uint32_t x = 0; x < 10; ++x) {
      const bake::TexelParameter t = bake::texelParameter(x, y, settings);
      per_tile += t.u + t.v <= 1 + 1.0 / 7;
    }
  }
  EXPECT_EQ(result.texels_baked, per_tile * f.patches->patchCount());
  // PN triangles are not the Loop limit, but stay within the control mesh's scale of it.
  EXPECT_LT(result.length_max, 0.1 * h.diagonal);
}

TEST(Baker, TwoBakesWriteByteIdenticalFiles) {
  const Fixture f = build("acc", "opensubdiv/catmark_torus.obj");
  const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(f.patches->controlMesh());
  const ref::LimitTessellation target =
      bake::analyticTargetMesh(f.patches->controlMesh(), schemeOf(*f.patches), 8, h);
  const auto dir = testing::scratchDirectory("bake_determinism");
  for (displacement::DisplacementKind kind :
       {displacement::DisplacementKind::kScalar, displacement::DisplacementKind::kVector}) {
    bake::BakeSettings settings;
    settings.kind = kind;
    settings.resolution = 5;
    std::string bytes[2];
    for (int i = 0; i < 2; ++i) {
      const std::string path =
          (dir / (std::string(displacement::kindName(kind)) + std::to_string(i) + ".exr"));
      displacement::writeDisplacementExr(
          path, bake::bakeDisplacement(*f.patches, target.view(), settings).map);
      std::ifstream file(path, std::ios::binary);
      bytes[i].assign(std::istreambuf_iterator<char>(file), {});
    }
    EXPECT_FALSE(bytes[0].empty());
    EXPECT_EQ(bytes[0], bytes[1]) << displacement::kindName(kind);
  }
  std::filesystem::remove_all(dir);
}

TEST(Baker, RefusesBadSettings) {
  const Fixture f = build("acc", "opensubdiv/catmark_torus.obj");
  const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(f.patches->controlMesh());
  const ref::LimitTessellation target =
      bake::analyticTargetMesh(f.patches->controlMesh(), schemeOf(*f.patches), 2, h);
  bake::BakeSettings settings;
  settings.resolution = 1;
  EXPECT_THROW(bake::bakeDisplacement(*f.patches, target.view(), settings), mesh::InputError);
  settings.resolution = bake::kMaxBakeResolution + 1;
  EXPECT_THROW(bake::bakeDisplacement(*f.patches, target.view(), settings), mesh::InputError);
  settings.resolution = 4;
  settings.layout = displacement::DisplacementLayout::kUv;
  EXPECT_THROW(bake::bakeDisplacement(*f.patches, target.view(), settings), mesh::InputError);
}

TEST(AnalyticTarget, HeightIsBoundedByTheAmplitudeAndNotConstant) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_torus.obj"));
  const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(mesh);
  EXPECT_NEAR(h.amplitude, bake::kAnalyticAmplitudeFraction * h.diagonal, 1e-15);
  double lo = 0, hi = 0;
  for (const mesh::Vec3d& p : mesh.positions) {
    lo = std::min(lo, h.height(p));
    hi = std::max(hi, h.height(p));
    EXPECT_LE(std::abs(h.height(p)), h.amplitude);
  }
  EXPECT_GT(hi - lo, 0.2 * h.amplitude);
}

}  // namespace
}  // namespace tb
