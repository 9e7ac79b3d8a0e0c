// pn_triangles and phong cracks on split normals, measured with
// harness/measures/common/cracks/cracks.h on CPU float (evaluateFloat) and on lavapipe's capture of
// the techniques' own shaders. Oracle: the crack measure's pairing of shared-edge points by welded
// position (its own tests check it against hand counts); plain PN must open gaps where the two
// faces' normals differ (flat_cube: every cube edge), geometry normals (seed 003) and PN-AEN must
// make the paired points bitwise equal. flat_cube.obj does not crack under plain PN: each cube edge
// is perpendicular to both face normals, so w_ij = 0 and both sides are the straight edge
// (paper §3.1); its split normals show the fixes' cost instead (geometry normals round it).
#include <gtest/gtest.h>

#include <cstdio>

#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::variantOf;

measures::CrackFigures measure(const std::string& technique_id, const std::string& variant,
                               const std::string& asset, tess::Spacing spacing, float level,
                               measures::CrackBackend backend, gpu::Context* context) {
  const techniques::Technique& technique =
      *techniques::TechniqueRegistry::instance().find(technique_id);
  const auto patches = techniques::buildSurface(
      technique, mesh::loadObjFile(testing::assetPath(asset)), variantOf(technique, variant));
  const measures::CrackFigures f =
      measures::measureCracks(*patches, spacing, level, backend, context);
  std::printf(
      "[cracks] %s/%s %s level %.1f %s: shared edges %llu, points %llu, not bitwise "
      "%llu, unpaired %llu, max gap %.3g world (%.3g scale ulp)\n",
      technique_id.c_str(), variant.c_str(), asset.c_str(), level, toString(backend),
      (unsigned long long)f.shared_edges, (unsigned long long)f.points_compared,
      (unsigned long long)f.points_not_equal, (unsigned long long)f.unpaired_points,
      f.max_gap_world, f.max_gap_scale_ulp);
  return f;
}

struct Level {
  tess::Spacing spacing;
  float level;
};
const Level kLevels[] = {{tess::Spacing::kInteger, 16.0f}, {tess::Spacing::kFractionalOdd, 7.3f}};

TEST(PnCracks, PlainPnOpensGapsAtTheCylindersHardCaps) {
  // The cap rim is straight from the cap (its normal is perpendicular to the rim edge) and
  // an arc from the side (radial normals): a gap of the order of the arc's sagitta.
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const Level& l : kLevels) {
    for (measures::CrackBackend backend :
         {measures::CrackBackend::kCpuFloat, measures::CrackBackend::kGpu}) {
      const measures::CrackFigures f = measure("pn_triangles", "pn", "tessbench/cylinder_seam.obj",
                                               l.spacing, l.level, backend, &context);
      ASSERT_TRUE(f.measured) << f.skipped_reason;
      EXPECT_EQ(f.unpaired_points, 0u);
      EXPECT_GT(f.max_gap_world, 1e-3);
      EXPECT_GT(f.points_not_equal, 0u);
    }
  }
}

TEST(PnCracks, FlatCubeIsWatertightAndFlatUnderPlainPn) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (measures::CrackBackend backend :
       {measures::CrackBackend::kCpuFloat, measures::CrackBackend::kGpu}) {
    const measures::CrackFigures f = measure("pn_triangles", "pn", "tessbench/flat_cube.obj",
                                             tess::Spacing::kInteger, 16.0f, backend, &context);
    ASSERT_TRUE(f.measured) << f.skipped_reason;
    EXPECT_EQ(f.shared_edges, 18u);  // 12 cube edges + 6 face diagonals
    EXPECT_EQ(f.points_not_equal, 0u);
  }
}

TEST(PnCracks, GeometryNormalsAndAenCloseThemBitwise) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const char* asset : {"tessbench/cylinder_seam.obj", "tessbench/flat_cube.obj"}) {
    for (const char* variant : {"geometry_normals", "aen", "boundary_flags", "rounding"}) {
      for (const Level& l : kLevels) {
        for (measures::CrackBackend backend :
             {measures::CrackBackend::kCpuFloat, measures::CrackBackend::kGpu}) {
          const measures::CrackFigures f =
              measure("pn_triangles", variant, asset, l.spacing, l.level, backend, &context);
          ASSERT_TRUE(f.measured) << f.skipped_reason;
          EXPECT_GT(f.points_compared, 0u);
          EXPECT_EQ(f.unpaired_points, 0u);
          EXPECT_EQ(f.points_not_equal, 0u) << variant << " " << toString(backend);
          EXPECT_EQ(f.max_gap_world, 0.0) << variant << " " << toString(backend);
          if (backend == measures::CrackBackend::kGpu) {
            EXPECT_EQ(f.device_points_differing, 0u);
          }
        }
      }
    }
  }
}

TEST(PnCracks, SmoothSharedNormalsAreWatertightInEveryVariant) {
  // Oracle: where both faces share the normals (tri_torus, computed smooth normals), the
  // canonical order alone must make the edges bitwise equal.
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::Technique& pn = *techniques::TechniqueRegistry::instance().find("pn_triangles");
  for (const techniques::VariantInfo& v : pn.variants()) {
    const measures::CrackFigures f =
        measure("pn_triangles", v.name, "tessbench/tri_torus.obj", tess::Spacing::kFractionalOdd,
                7.3f, measures::CrackBackend::kGpu, &context);
    ASSERT_TRUE(f.measured) << f.skipped_reason;
    EXPECT_EQ(f.points_not_equal, 0u) << v.name;
  }
}

TEST(PhongCracks, EdgeVariantClosesTheCapGapsOfPlainPhong) {
  // Oracle as above: plain Phong builds the cap rim from the cap's and the side's corner
  // normals; seed 003's per-edge variant uses the shared geometry normals on split edges.
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const Level& l : kLevels) {
    for (measures::CrackBackend backend :
         {measures::CrackBackend::kCpuFloat, measures::CrackBackend::kGpu}) {
      const measures::CrackFigures plain =
          measure("phong", "alpha0.75", "tessbench/cylinder_seam.obj", l.spacing, l.level, backend,
                  &context);
      ASSERT_TRUE(plain.measured) << plain.skipped_reason;
      EXPECT_GT(plain.max_gap_world, 1e-3);
      for (const char* asset :
           {"tessbench/cylinder_seam.obj", "tessbench/flat_cube.obj", "tessbench/tri_torus.obj"}) {
        const measures::CrackFigures edge =
            measure("phong", "edge", asset, l.spacing, l.level, backend, &context);
        ASSERT_TRUE(edge.measured) << edge.skipped_reason;
        EXPECT_GT(edge.points_compared, 0u);
        EXPECT_EQ(edge.unpaired_points, 0u);
        EXPECT_EQ(edge.points_not_equal, 0u) << asset << " " << toString(backend);
      }
    }
  }
}

}  // namespace
}  // namespace tb
