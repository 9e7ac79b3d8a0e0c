// Issue 12, acceptance 3: the crack measure under per-patch, non-uniform levels. The
// pattern (harness/lod/edge_pattern_levels.h) gives every edge its own level and
// both sides of a shared edge the same one, so the symmetric (`precise`) variants must
// leave 0 shared points that are not bitwise equal, on the CPU float model and in
// lavapipe's capture, and the capture must equal the CPU twin; the asymmetric variant
// must still open gaps (so the test can fail).
// Oracles: bitwise equality of mirrored shared points (the CPU tessellator's domain
// points equal lavapipe's bit for bit); for the pattern itself, the levels of the two
// sides of each shared edge read back through the gl_TessLevelOuter edge order.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "core/mesh/obj_loader.h"
#include "harness/lod/edge_pattern_levels.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/measures/measure.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/measures/bundled_surfaces.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr float kBase = 7.0f;

struct Case {
  const char* technique;
  const char* variant;
  const char* asset;
};

techniques::BuiltSurface build(const Case& c) {
  return testing::builtSurface(c.technique, c.variant, c.asset);
}

std::string name(const Case& c, tess::Spacing spacing) {
  return std::string(c.technique) + "/" + c.variant + " " + c.asset + " " +
         std::string(tess::toString(spacing));
}

void print(const Case& c, tess::Spacing spacing, const measures::CrackFigures& f) {
  std::printf(
      "[edge_pattern] %s %s: points %llu, not equal %llu, unpaired %llu, device points "
      "%llu differing %llu max ulp %llu\n",
      name(c, spacing).c_str(), toString(f.backend), (unsigned long long)f.points_compared,
      (unsigned long long)f.points_not_equal, (unsigned long long)f.unpaired_points,
      (unsigned long long)f.device_points, (unsigned long long)f.device_points_differing,
      (unsigned long long)f.device_max_ulp);
}

// gl_TessLevelOuter index of local edge k (corner k to k + 1).
size_t outerIndex(techniques::PatchDomain domain, uint32_t k) {
  return domain == techniques::PatchDomain::kQuad ? (k + 1) % 4 : (k + 2) % 3;
}

TEST(EdgePatternLevels, SharedEdgesGetOneLevelAndEdgesDiffer) {
  // catmark_pyramid under gregory_acc: quads and triangles share edges.
  const auto patches = build({"gregory_acc", "edge_symmetric", "opensubdiv/catmark_pyramid.obj"});
  for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
    const std::vector<tess::Levels> levels = lod::edgePatternLevels(*patches, spacing, kBase);
    ASSERT_EQ(levels.size(), patches->patchCount());
    const measures::SharedBoundaries shared = measures::findSharedBoundaries(*patches);
    ASSERT_FALSE(shared.edges.empty());
    std::set<float> distinct;
    for (const measures::SharedEdge& edge : shared.edges) {
      const measures::PatchSide& a = edge.sides[0];
      const float level_a =
          levels[a.patch].outer[outerIndex(patches->patchDomain(a.patch), a.local)];
      distinct.insert(level_a);
      for (const measures::PatchSide& b : edge.sides) {
        EXPECT_EQ(level_a,
                  levels[b.patch].outer[outerIndex(patches->patchDomain(b.patch), b.local)])
            << "edge " << edge.v0 << "-" << edge.v1;
      }
    }
    EXPECT_GE(distinct.size(), 2u) << "the pattern should not be uniform";
  }
  // Fractional spacing keeps the fractional edge levels.
  bool fractional = false;
  for (const tess::Levels& l :
       lod::edgePatternLevels(*patches, tess::Spacing::kFractionalOdd, kBase)) {
    for (float o : l.outer) fractional |= o != float(int(o));
  }
  EXPECT_TRUE(fractional);
}

TEST(EdgePatternLevels, ScaleIndexIgnoresVertexOrder) {
  for (uint32_t a = 0; a < 50; ++a) {
    for (uint32_t b = 0; b < 50; ++b) {
      EXPECT_EQ(lod::edgePatternScaleIndex(a, b), lod::edgePatternScaleIndex(b, a));
    }
  }
}

// The symmetric variants, each on assets it supports; catmark_pyramid under gregory_acc
// mixes quad and triangle patches.
const Case kSymmetric[] = {
    {"acc", "default", "opensubdiv/catmark_cube.obj"},
    {"acc", "default", "opensubdiv/catmark_torus.obj"},
    {"acc", "symmetric_nofma", "opensubdiv/catmark_xord_interior.obj"},
    {"acc", "symmetric_edges", "opensubdiv/catmark_cube.obj"},
    {"gregory_acc", "edge_symmetric", "opensubdiv/catmark_pyramid.obj"},
    {"gregory_acc", "edge_symmetric", "opensubdiv/catmark_cube.obj"},
    {"pn_triangles", "geometry_normals", "tessbench/tri_torus.obj"},
    {"pn_triangles", "aen", "tessbench/cylinder_seam.obj"},
    {"phong", "edge", "tessbench/tri_torus.obj"},
    {"phong", "edge", "opensubdiv/loop_icosahedron.obj"},
};
constexpr tess::Spacing kSpacings[] = {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                       tess::Spacing::kFractionalEven, tess::Spacing::kPow2};

TEST(EdgePatternCracks, SymmetricVariantsAreBitwiseWatertightOnCpuFloat) {
  for (const Case& c : kSymmetric) {
    const auto patches = build(c);
    for (tess::Spacing spacing : kSpacings) {
      const measures::CrackFigures f = measures::measureCracks(
          *patches, spacing, lod::edgePatternLevels(*patches, spacing, kBase),
          measures::CrackBackend::kCpuFloat);
      print(c, spacing, f);
      ASSERT_TRUE(f.measured) << f.skipped_reason;
      EXPECT_GT(f.points_compared, 0u) << name(c, spacing);
      EXPECT_EQ(f.points_not_equal, 0u) << name(c, spacing) << " max gap " << f.max_gap_world;
      EXPECT_EQ(f.unpaired_points, 0u) << name(c, spacing);
    }
  }
}

TEST(EdgePatternCracks, SymmetricVariantsAreBitwiseWatertightInTheLavapipeCapture) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const Case& c : kSymmetric) {
    const auto patches = build(c);
    for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
      const measures::CrackFigures f = measures::measureCracks(
          *patches, spacing, lod::edgePatternLevels(*patches, spacing, kBase),
          measures::CrackBackend::kGpu, &context);
      print(c, spacing, f);
      ASSERT_TRUE(f.measured) << f.skipped_reason;
      EXPECT_GT(f.points_compared, 0u) << name(c, spacing);
      EXPECT_EQ(f.points_not_equal, 0u) << name(c, spacing);
      EXPECT_EQ(f.unpaired_points, 0u) << name(c, spacing);
      EXPECT_GT(f.device_points, 0u) << name(c, spacing);
      EXPECT_EQ(f.device_points_differing, 0u) << name(c, spacing) << ": capture vs evaluateFloat";
      EXPECT_EQ(f.device_max_ulp, 0u) << name(c, spacing);
    }
  }
}

// Cases that must open gaps: acc's asymmetric evaluation order, and plain PN on split
// normals (the cylinder's hard cap rims).
const Case kCracking[] = {
    {"acc", "asymmetric", "opensubdiv/catmark_cube.obj"},
    {"acc", "asymmetric", "opensubdiv/catmark_toroidal_tet.obj"},
    {"pn_triangles", "pn", "tessbench/cylinder_seam.obj"},
};

TEST(EdgePatternCracks, CrackingVariantsStillOpenGapsOnCpuFloat) {
  for (const Case& c : kCracking) {
    const auto patches = build(c);
    const tess::Spacing spacing = tess::Spacing::kFractionalOdd;
    const measures::CrackFigures f =
        measures::measureCracks(*patches, spacing, lod::edgePatternLevels(*patches, spacing, kBase),
                                measures::CrackBackend::kCpuFloat);
    print(c, spacing, f);
    EXPECT_GT(f.points_not_equal, 0u) << name(c, spacing);
    EXPECT_EQ(f.unpaired_points, 0u) << name(c, spacing);
  }
}

TEST(EdgePatternCracks, CrackingVariantsStillOpenGapsInTheLavapipeCapture) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const Case& c : kCracking) {
    const auto patches = build(c);
    const tess::Spacing spacing = tess::Spacing::kFractionalOdd;
    const measures::CrackFigures f =
        measures::measureCracks(*patches, spacing, lod::edgePatternLevels(*patches, spacing, kBase),
                                measures::CrackBackend::kGpu, &context);
    print(c, spacing, f);
    EXPECT_GT(f.points_not_equal, 0u) << name(c, spacing);
    EXPECT_EQ(f.unpaired_points, 0u) << name(c, spacing);
    EXPECT_EQ(f.device_max_ulp, 0u) << name(c, spacing) << ": capture vs evaluateFloat";
  }
}

// The pattern's symmetry is what the pairing needs: give one side of a shared edge
// another level and its points no longer pair (so a broken pattern would show).
TEST(EdgePatternCracks, ALevelThatDiffersAcrossASharedEdgeLeavesUnpairedPoints) {
  const auto patches = build({"acc", "default", "opensubdiv/catmark_cube.obj"});
  std::vector<tess::Levels> levels =
      lod::edgePatternLevels(*patches, tess::Spacing::kInteger, kBase);
  const measures::SharedBoundaries shared = measures::findSharedBoundaries(*patches);
  ASSERT_FALSE(shared.edges.empty());
  const measures::PatchSide& side = shared.edges[0].sides[0];
  levels[side.patch].outer[outerIndex(techniques::PatchDomain::kQuad, side.local)] += 1;
  const measures::CrackFigures f = measures::measureCracks(
      *patches, tess::Spacing::kInteger, levels, measures::CrackBackend::kCpuFloat);
  EXPECT_GT(f.unpaired_points, 0u);
}

// The measure's pattern rows: keyed levels = edge_pattern (base level 7, every spacing, both
// backends), apart from the uniform rows, which keep their keys (no levels key), and no
// two rows share keys.
TEST(EdgePatternCracks, TheMeasureAddsPatternRowsUnderTheirOwnKey) {
  const techniques::Technique* acc = techniques::TechniqueRegistry::instance().find("acc");
  const measures::Measure* measure = measures::MeasureRegistry::instance().find("cracks");
  ASSERT_NE(acc, nullptr);
  ASSERT_NE(measure, nullptr);
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const techniques::VariantInfo variant = acc->variants()[0];
  const auto patches = techniques::buildSurface(*acc, mesh, variant);
  std::string reason;
  gpu::Context* context = gpu::testing::sharedContext(&reason);
  const results::MeasureResult result = measure->run(
      {*acc, variant, "catmark_cube", mesh, patches.get(), context, context ? "" : reason});
  std::set<std::map<std::string, std::string>> keys;
  size_t pattern_rows = 0, uniform_rows = 0, kind_rows = 0;
  for (const results::MetricRow& row : result.rows) {
    EXPECT_TRUE(keys.insert(row.keys).second) << "duplicate row keys";
    if (row.keys.contains("edge_kind")) {  // the cube's UV seams: CPU rows per edge kind
      ++kind_rows;
      continue;
    }
    if (!row.keys.contains("levels")) {
      uniform_rows += row.keys.contains("level") ? 1 : 0;
      continue;
    }
    ++pattern_rows;
    EXPECT_EQ(row.keys.at("levels"), "edge_pattern");
    EXPECT_EQ(row.keys.at("level"), "7");
    EXPECT_EQ(row.status, results::MeasureStatus::kOk) << row.reason;
    for (const results::Metric& metric : row.metrics) {
      if (metric.name == "points_not_equal" || metric.name == "unpaired_points") {
        EXPECT_EQ(metric.value, 0) << metric.name;
      }
    }
  }
  EXPECT_EQ(pattern_rows, context ? 8u : 4u);
  EXPECT_EQ(uniform_rows, context ? 32u : 16u);
  EXPECT_EQ(kind_rows, 3u * 16u) << "seam, interior, boundary x 4 spacings x 4 levels";
}

}  // namespace
}  // namespace tb
