// Displaced surfaces (techniques/common/displaced_patches.h): watertight sampling keeps every
// shared boundary point bitwise equal on the CPU float twin and on lavapipe's capture of the
// technique's own "#displaced" TES; naive sampling opens gaps at tile borders; the capture
// equals the twin bit for bit. Oracle: the crack measure's pairing
// (harness/measures/common/cracks/cracks.h, tested against hand counts) and lavapipe. Maps are
// random (a fixed LCG): independent tile borders are the adversary watertight sampling must beat.
#include "techniques/common/displaced_patches.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// A tile atlas for `patches` patches, `resolution` interior texels a side, 1-texel border,
// texels uniform in [-amplitude, amplitude] (exact halves when `half`).
std::shared_ptr<displacement::DisplacementMap> randomMap(size_t patches, uint32_t resolution,
                                                         double amplitude,
                                                         displacement::DisplacementKind kind,
                                                         bool half, uint32_t seed) {
  auto map = std::make_shared<displacement::DisplacementMap>();
  map->kind = kind;
  map->pixel_type = half ? displacement::DisplacementPixelType::kHalf
                         : displacement::DisplacementPixelType::kFloat;
  map->layout = displacement::DisplacementLayout::kTiles;
  const uint32_t tile = resolution + 2;
  const auto per_row = uint32_t(std::ceil(std::sqrt(double(patches))));
  map->tiles = {tile, 1, per_row, uint32_t(patches)};
  map->width = per_row * tile;
  map->height = uint32_t((patches + per_row - 1) / per_row) * tile;
  map->texels.resize(size_t(map->width) * map->height * displacement::channelCount(kind));
  uint64_t state = seed * 2654435761ull + 1;
  for (float& texel : map->texels) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const double unit = double(state >> 11) / double(1ull << 53);
    texel = float((2 * unit - 1) * amplitude);
  }
  if (half) displacement::roundTexelsToHalf(*map);
  return map;
}

struct Case {
  const char* technique;
  const char* variant;
  const char* asset;
};

// Undisplaced, these variants are bitwise watertight on these welded-normal assets (the
// crack tests of each technique), so any gap below comes from the displacement.
const Case kCases[] = {
    {"acc", "", "opensubdiv/catmark_torus.obj"},
    {"gregory_acc", "", "opensubdiv/catmark_gregory_test5.obj"},
    {"pn_triangles", "pn", "tessbench/tri_torus.obj"},
    {"phong", "alpha0.75", "tessbench/tri_torus.obj"},
};

techniques::BuiltSurface build(const Case& c) {
  const techniques::Technique& technique =
      *techniques::TechniqueRegistry::instance().find(c.technique);
  techniques::VariantInfo variant = technique.variants().front();
  for (const techniques::VariantInfo& v : technique.variants()) {
    if (v.name == c.variant) variant = v;
  }
  return techniques::buildSurface(technique, mesh::loadObjFile(testing::assetPath(c.asset)),
                                  variant);
}

using testing::diagonalOf;

measures::CrackFigures cracks(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                              float level, measures::CrackBackend backend, gpu::Context* context,
                              const char* label) {
  const measures::CrackFigures f =
      measures::measureCracks(patches, spacing, level, backend, context);
  std::printf(
      "[displaced cracks] %s %s level %.1f %s: points %llu, not bitwise %llu, max gap "
      "%.3g, device differing %llu\n",
      label, std::string(tess::toString(spacing)).c_str(), level, toString(backend),
      (unsigned long long)f.points_compared, (unsigned long long)f.points_not_equal,
      f.max_gap_world, (unsigned long long)f.device_points_differing);
  return f;
}

TEST(DisplacedPatches, WatertightSamplingIsBitwiseWatertightOnTheCpuTwin) {
  for (const Case& c : kCases) {
    const techniques::BuiltSurface surface = build(c);
    const double amplitude = 0.02 * diagonalOf(surface->controlMesh());
    for (displacement::DisplacementKind kind :
         {displacement::DisplacementKind::kScalar, displacement::DisplacementKind::kVector}) {
      const auto map = randomMap(surface->patchCount(), 6, amplitude, kind, true, 7);
      const techniques::DisplacedPatches watertight(
          *surface, map, techniques::DisplacementSampling::kWatertight, "random");
      const techniques::DisplacedPatches naive(*surface, map,
                                               techniques::DisplacementSampling::kNaive, "random");
      const std::string label =
          std::string(c.technique) + " " + std::string(displacement::kindName(kind));
      for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
        for (float level : {1.0f, 5.0f, 7.3f, 16.0f}) {
          const measures::CrackFigures w =
              cracks(watertight, spacing, level, measures::CrackBackend::kCpuFloat, nullptr,
                     (label + " watertight").c_str());
          ASSERT_TRUE(w.measured);
          EXPECT_GT(w.points_compared, 0u);
          EXPECT_EQ(w.unpaired_points, 0u);
          EXPECT_EQ(w.points_not_equal, 0u) << label;
        }
        const measures::CrackFigures n =
            cracks(naive, spacing, 7.3f, measures::CrackBackend::kCpuFloat, nullptr,
                   (label + " naive").c_str());
        // Independent tile borders: the two sides read different texels.
        EXPECT_GT(n.points_not_equal, n.points_compared / 4) << label;
        EXPECT_GT(n.max_gap_world, 0.01 * amplitude) << label;
      }
    }
  }
}

TEST(DisplacedPatches, LavapipeCaptureEqualsTheTwinAndStaysWatertight) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const Case& c : kCases) {
    const techniques::BuiltSurface surface = build(c);
    const double amplitude = 0.02 * diagonalOf(surface->controlMesh());
    for (bool half : {true, false}) {
      for (displacement::DisplacementKind kind :
           {displacement::DisplacementKind::kScalar, displacement::DisplacementKind::kVector}) {
        const auto map = randomMap(surface->patchCount(), 5, amplitude, kind, half, 11);
        for (techniques::DisplacementSampling sampling :
             {techniques::DisplacementSampling::kWatertight,
              techniques::DisplacementSampling::kNaive}) {
          const techniques::DisplacedPatches displaced(*surface, map, sampling, "random");
          const std::string label =
              std::string(c.technique) + " " + std::string(displacement::kindName(kind)) +
              (half ? " half " : " float ") + techniques::samplingName(sampling);
          const measures::CrackFigures f =
              cracks(displaced, tess::Spacing::kFractionalEven, 6.6f, measures::CrackBackend::kGpu,
                     &context, label.c_str());
          ASSERT_TRUE(f.measured) << f.skipped_reason;
          EXPECT_GT(f.device_points, 0u);
          EXPECT_EQ(f.device_points_differing, 0u) << label;
          if (sampling == techniques::DisplacementSampling::kWatertight) {
            EXPECT_EQ(f.points_not_equal, 0u) << label;
          } else {
            EXPECT_GT(f.points_not_equal, 0u) << label;
          }
        }
      }
    }
  }
}

// The cull bound (the culling measure's per-patch input): every displaced point of a patch
// lies in the convex hull of its grown bound; checked on the hull's bounding box, which the
// hull's cube corners span exactly, and the bound must not be loose by more than 2 r.
TEST(DisplacedPatches, CullBoundsContainEveryDisplacedPoint) {
  for (const Case& c : kCases) {
    const techniques::BuiltSurface surface = build(c);
    const double amplitude = 0.05 * diagonalOf(surface->controlMesh());
    const auto map = randomMap(surface->patchCount(), 6, amplitude,
                               displacement::DisplacementKind::kVector, false, 3);
    const techniques::DisplacedPatches displaced(
        *surface, map, techniques::DisplacementSampling::kWatertight, "random");
    for (size_t p = 0; p < displaced.patchCount(); ++p) {
      const std::optional<techniques::PatchCullBounds> bounds = displaced.cullBounds(p);
      if (!surface->cullBounds(p)) {
        EXPECT_FALSE(bounds);
        continue;
      }
      ASSERT_TRUE(bounds);
      EXPECT_TRUE(bounds->normal_generators.empty());
      mesh::Vec3d lo = bounds->hull.front(), hi = lo;
      for (const mesh::Vec3d& q : bounds->hull) {
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
      }
      for (int i = 0; i <= 8; ++i) {
        for (int j = 0; j <= 8; ++j) {
          techniques::DomainCoord coord{i / 8.0, j / 8.0, 0};
          if (displaced.patchDomain(p) == techniques::PatchDomain::kTriangle) {
            if (i + j > 8) continue;
            coord[2] = 1 - coord[0] - coord[1];
          }
          const mesh::Vec3d q = displaced.evaluate(p, coord).position;
          for (int k = 0; k < 3; ++k) {
            EXPECT_GE(q[k], lo[k] - 1e-12) << c.technique << " patch " << p;
            EXPECT_LE(q[k], hi[k] + 1e-12) << c.technique << " patch " << p;
          }
        }
      }
    }
  }
}

TEST(DisplacedPatches, RefusesAMapWithAnotherTileCount) {
  const techniques::BuiltSurface surface = build(kCases[0]);
  const auto map = randomMap(surface->patchCount() + 1, 4, 0.1,
                             displacement::DisplacementKind::kScalar, false, 1);
  try {
    techniques::DisplacedPatches displaced(*surface, map, techniques::DisplacementSampling::kNaive,
                                           "wrong.exr");
    FAIL() << "accepted a map of another tile count";
  } catch (const mesh::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("wrong.exr"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("tiles"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace tb
