// pn_triangles against its oracles: the definition of curved PN triangles (Vlachos et al.
// 2001: corners and corner normals interpolate; a flat triangle with equal normals is the
// plane), the canonical order (rotation gives bitwise-equal points), hand counts, and on
// the GPU the CPU float model (evaluateFloat) at the captured gl_TessCoord.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "core/mesh/obj_loader.h"
#include "techniques/pn_triangles/pn_build.h"
#include "techniques/pn_triangles/pn_eval.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/techniques/pn_gpu_support.h"

namespace tb::pn_triangles {
namespace {

const techniques::Technique& pn() {
  return *techniques::TechniqueRegistry::instance().find("pn_triangles");
}

techniques::VariantInfo variant(const std::string& name) {
  for (const techniques::VariantInfo& v : pn().variants()) {
    if (v.name == name) return v;
  }
  ADD_FAILURE() << "no variant " << name;
  return {};
}

const char* kCurved =
    "v 0 0 0\nv 1 0 0.2\nv 0 1 0.1\nvn 0 0 1\nvn 0.3 0 1\nvn 0 0.4 1\nf 1//1 2//2 3//3\n";

TEST(PnTriangles, VariantsInTheIssueOrder) {
  std::vector<std::string> names;
  for (const techniques::VariantInfo& v : pn().variants()) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"pn", "geometry_normals", "boundary_flags", "aen",
                                             "rounding"}));
}

TEST(PnTriangles, InterpolatesCornersAndCornerNormalsExactly) {
  // Oracle: paper §3, b300 = P1 and n200 = N1.
  const mesh::Mesh mesh = mesh::loadObjText(kCurved, "curved.obj");
  for (const techniques::VariantInfo& v : pn().variants()) {
    const auto patches = techniques::buildSurface(pn(), mesh, v);
    for (int corner = 0; corner < 3; ++corner) {
      techniques::DomainCoord coord{0, 0, 0};
      coord[corner] = 1;
      tess::DomainPoint coord_f{0, 0, 0};
      coord_f[corner] = 1;
      const techniques::SurfacePoint p = patches->evaluate(0, coord);
      const techniques::SurfacePointF pf = patches->evaluateFloat(0, coord_f);
      const mesh::Vec3d expected = mesh.positions[mesh.corner_positions[corner]];
      const mesh::Vec3d normal = normalize(mesh.normals[mesh.corner_normals[corner]]);
      EXPECT_EQ(p.position, expected) << v.name;
      EXPECT_EQ(pf.position, vecCast<float>(expected)) << v.name;
      EXPECT_LT(length(p.normal - normal), 1e-15) << v.name;
      EXPECT_LT(length(vecCast<double>(pf.normal) - normal), 1e-6) << v.name;
    }
  }
}

TEST(PnTriangles, FlatTriangleWithEqualNormalsStaysFlat) {
  // Oracle: w_ij = 0 when every normal is the plane's, so all control points lie in it
  // (paper §3.1) and the patch is a reparametrisation of the flat triangle.
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0.5\nv 2 0 0.5\nv 0.25 1.75 0.5\nvn 0 0 1\nf 1//1 2//1 3//1\n", "flat.obj");
  for (const techniques::VariantInfo& v : pn().variants()) {
    const auto patches = techniques::buildSurface(pn(), mesh, v);
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; i + j <= 8; ++j) {
        const double u = i / 8.0, w = j / 8.0;
        const techniques::SurfacePoint p = patches->evaluate(0, {u, w, 1 - u - w});
        EXPECT_NEAR(p.position.z, 0.5, 1e-15) << v.name;
        EXPECT_NEAR(length(p.normal - mesh::Vec3d{0, 0, 1}), 0, 1e-15) << v.name;
        // Inside the triangle: barycentric coordinates of the point are all >= 0.
        const double y = p.position.y, x = p.position.x;
        EXPECT_GE(y, -1e-12);
        EXPECT_GE(1.75 * (2 - x) - (2 - 0.25) * y, -1e-12) << v.name;
        EXPECT_GE(1.75 * x - 0.25 * y, -1e-12) << v.name;
      }
    }
  }
}

TEST(PnTriangles, CurvedEdgeBulgesByTheHandComputedControlPoints) {
  // Oracle: the edge midpoint of a cubic Bézier is (b300 + 3 b210 + 3 b120 + b030) / 8, with
  // b210 = (2 P1 + P2 - w12 N1) / 3 computed by hand: P1 = 0, P2 = (1,0,0), N1 = (0,0,1),
  // N2 = (3, 0, 4) / 5 => w12 = 0, w21 = -3/5 => b120 = (2 P2 + P1 - w21 N2) / 3.
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 3 0 4\nf 1//1 2//2 3//1\n", "edge.obj");
  const auto patches = techniques::buildSurface(pn(), mesh, pn().variants()[0]);
  const mesh::Vec3d b210{1.0 / 3, 0, 0};
  const mesh::Vec3d n2 = normalize(mesh::Vec3d{3, 0, 4});
  const double w21 = dot(mesh::Vec3d{-1, 0, 0}, n2);
  const mesh::Vec3d b120 = (mesh::Vec3d{2, 0, 0} - n2 * w21) * (1.0 / 3);
  const mesh::Vec3d expected = (b210 * 3.0 + b120 * 3.0 + mesh::Vec3d{1, 0, 0}) * (1.0 / 8);
  const techniques::SurfacePoint p = patches->evaluate(0, {0.5, 0.5, 0});
  EXPECT_LT(length(p.position - expected), 1e-15);
  EXPECT_GT(p.position.z, 0.01);
}

TEST(PnTriangles, RotatingTheFaceGivesBitwiseEqualFloatPoints) {
  // Oracle: the canonical corner order makes the float result a function of the corner
  // set; the same face written from another corner must give the same bits.
  const char* kB =
      "v 0 0 0\nv 1 0 0.2\nv 0 1 0.1\nvn 0 0 1\nvn 0.3 0 1\nvn 0 0.4 1\nf 2//2 3//3 1//1\n";
  const auto a =
      techniques::buildSurface(pn(), mesh::loadObjText(kCurved, "a.obj"), pn().variants()[0]);
  const auto b = techniques::buildSurface(pn(), mesh::loadObjText(kB, "b.obj"), pn().variants()[0]);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0, 1);
  for (int trial = 0; trial < 500; ++trial) {
    const float u = unit(rng), v = unit(rng) * (1 - u), w = 1 - u - v;
    EXPECT_EQ(a->evaluateFloat(0, {u, v, w}).position, b->evaluateFloat(0, {v, w, u}).position);
  }
}

TEST(PnTriangles, FloatFollowsDouble) {
  // Oracle: the double evaluation of the same records; float differs by rounding only.
  const auto patches =
      techniques::buildSurface(pn(), mesh::loadObjText(kCurved, "c.obj"), variant("aen"));
  for (int i = 0; i <= 10; ++i) {
    const float u = i / 10.0f, v = (1 - u) / 2, w = 1 - u - v;
    const techniques::SurfacePoint d = patches->evaluate(0, {u, v, w});
    const techniques::SurfacePointF f = patches->evaluateFloat(0, {u, v, w});
    EXPECT_LT(length(vecCast<double>(f.position) - d.position), 1e-6);
    EXPECT_LT(length(vecCast<double>(f.normal) - d.normal), 1e-6);
  }
}

TEST(PnTriangles, FlatCubeFlagsEverySplitEdgeAndMergesNormals) {
  // Hand count: a cube has 12 hard edges (split normals) and 6 face diagonals (normals
  // agree); every corner's geometry normal is (±1, ±1, ±1)/√3.
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("tessbench/flat_cube.obj"));
  techniques::TriangleRecordOptions options;
  options.geometry_normals = true;
  const techniques::TriangleRecords build = techniques::buildTriangleRecords(mesh, options);
  EXPECT_EQ(build.split_edges, 12u);
  EXPECT_EQ(build.boundary_edges, 0u);
  EXPECT_EQ(build.geometry_normal_count, 8u);
  for (size_t i = mesh.normals.size(); i < build.normals.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(std::fabs(build.normals[i][k]), 1 / std::sqrt(3.0), 1e-15);
  }
  size_t flagged_edges = 0;
  for (const techniques::TriangleRecord& r : build.records) {
    for (int e = 0; e < 3; ++e) {
      flagged_edges +=
          ((r.flags[techniques::kEdgeEnds[e][0]] & r.flags[techniques::kEdgeEnds[e][1]]) >> e) & 1u;
    }
  }
  EXPECT_EQ(flagged_edges, 24u);  // 12 edges, seen from both faces
}

TEST(PnTriangles, BoundaryFlagsStraightenUnsharedEdges) {
  // Oracle: seed 003, an unshared edge with boundary flags is the straight segment.
  const auto patches = techniques::buildSurface(pn(), mesh::loadObjText(kCurved, "b.obj"),
                                                variant("boundary_flags"));
  const auto plain =
      techniques::buildSurface(pn(), mesh::loadObjText(kCurved, "b.obj"), variant("pn"));
  const techniques::SurfacePoint p = patches->evaluate(0, {0.25, 0.75, 0});
  const mesh::Mesh mesh = mesh::loadObjText(kCurved, "b.obj");
  const mesh::Vec3d linear = mesh.positions[0] * 0.25 + mesh.positions[1] * 0.75;
  EXPECT_LT(length(p.position - linear), 1e-15);
  EXPECT_GT(length(plain->evaluate(0, {0.25, 0.75, 0}).position - linear), 1e-3);
}

TEST(PnTriangles, BoundaryFlagsPutTheTJunctionVertexOnTheLongEdge) {
  // Seed 003's T-junction: vertex 5 = (1, 0.5, 0) sits on the middle of the left half's edge
  // 2-3 but is a corner of the right half, which therefore passes through it exactly. With
  // boundary flags the unshared edge 2-3 is straight, so its midpoint is vertex 5 (no
  // crack); plain PN bulges it away from vertex 5 (a crack). Normals form a dome.
  const char* kTJunction =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 0.5 0\nv 2 0 0\nv 2 1 0\n"
      "vn -1 -0.5 2\nvn 0 -0.5 2\nvn 0 0.5 2\nvn -1 0.5 2\nvn 0 0 1\nvn 1 -0.5 2\nvn 1 0.5 2\n"
      "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\nf 2//2 6//6 5//5\nf 5//5 6//6 7//7\nf 5//5 7//7 3//3\n";
  const mesh::Mesh mesh = mesh::loadObjText(kTJunction, "tjunction.obj");
  const mesh::Vec3d t_vertex = mesh.positions[4];
  const auto flagged = techniques::buildSurface(pn(), mesh, variant("boundary_flags"));
  const auto plain = techniques::buildSurface(pn(), mesh, variant("pn"));
  // Face 0 = (v1, v2, v3): edge 2-3 is corners 1-2.
  EXPECT_LT(length(flagged->evaluate(0, {0, 0.5, 0.5}).position - t_vertex), 1e-15);
  EXPECT_GT(length(plain->evaluate(0, {0, 0.5, 0.5}).position - t_vertex), 0.01);
  // The right half's faces pass through the T vertex in both variants.
  EXPECT_EQ(flagged->evaluate(2, {0, 0, 1}).position, t_vertex);
}

TEST(PnTriangles, RoundingOnlyFlattensEdges) {
  // Seed 003's rounding scales w_ij by a factor in [0, 1]: every edge point moves toward
  // the straight edge, none away, and the nearly flat edges of this triangle move.
  const mesh::Mesh mesh = mesh::loadObjText(kCurved, "r.obj");
  const auto rounded = techniques::buildSurface(pn(), mesh, variant("rounding"));
  const auto full = techniques::buildSurface(pn(), mesh, variant("geometry_normals"));
  double moved = 0;
  for (int e = 0; e < 3; ++e) {
    for (int i = 1; i < 8; ++i) {
      techniques::DomainCoord c{0, 0, 0};
      c[e] = i / 8.0;
      c[(e + 1) % 3] = 1 - i / 8.0;
      const mesh::Vec3d linear =
          mesh.positions[e] * c[e] + mesh.positions[(e + 1) % 3] * c[(e + 1) % 3];
      const double d_rounded = length(rounded->evaluate(0, c).position - linear);
      const double d_full = length(full->evaluate(0, c).position - linear);
      EXPECT_LE(d_rounded, d_full + 1e-15);
      moved = std::max(moved, d_full - d_rounded);
    }
  }
  EXPECT_GT(moved, 1e-3);
}

TEST(PnTriangles, PolygonsAreFanTriangulatedAndMissingNormalsComputed) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const auto patches = techniques::buildSurface(pn(), mesh, pn().variants()[0]);
  EXPECT_EQ(patches->patchCount(), 12u);
  ASSERT_EQ(patches->warnings().size(), 1u);  // catmark_cube.obj has its own normals
  EXPECT_NE(patches->warnings()[0].find("fan-triangulated"), std::string::npos);
  const auto torus = techniques::buildSurface(
      pn(), mesh::loadObjFile(testing::assetPath("tessbench/tri_torus.obj")), pn().variants()[0]);
  ASSERT_EQ(torus->warnings().size(), 1u);
  EXPECT_NE(torus->warnings()[0].find("normals were computed"), std::string::npos);
}

TEST(PnTriangles, MeshWithoutNormalsIsRejectedWithAReason) {
  mesh::LoadOptions options;
  options.compute_missing_normals = false;
  const mesh::Mesh mesh =
      mesh::loadObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "bare.obj", options);
  EXPECT_THROW(techniques::buildSurface(pn(), mesh, pn().variants()[0]),
               techniques::UnsupportedInput);
}

TEST(PnTriangles, OperationCountsMatchAHandCount) {
  // Hand count of pn_eval.h evaluateControl (the TES).
  const auto patches =
      techniques::buildSurface(pn(), mesh::loadObjText(kCurved, "c.obj"), pn().variants()[0]);
  const auto profile = patches->operationProfile(0);
  ASSERT_TRUE(profile.has_value());
  // Position: 6 (weights) + corners (3 + 9 mul, 6 add) + edges 3 × (6 + 1 + 3 mul, 6 add)
  // + centre (2 + 3 mul, 3 add) => mul 6 + 12 + 30 + 5 = 53, add 6 + 18 + 3 = 27. Normal: 6 terms ×
  // 3 mul = 18 mul, 15 add; normalise: dot 3 mul 2 add, sqrt, 1 div, 3 mul, 1 compare.
  EXPECT_EQ(profile->per_vertex.mul, 53u + 18u + 6u);
  EXPECT_EQ(profile->per_vertex.add, 27u + 15u + 2u);
  EXPECT_EQ(profile->per_vertex.div, 1u);
  EXPECT_EQ(profile->per_vertex.sqrt, 1u);
  EXPECT_EQ(profile->per_vertex.compare, 1u);
  EXPECT_GT(profile->per_patch_setup.total(), profile->per_vertex.total());
}

TEST(PnTriangles, VariantsCostOnlyInTheSetUp) {
  // Oracle: the variants change how the control points are built (TCS), never the patch
  // evaluation (TES); PN-AEN builds every edge point twice, so its set-up costs more.
  // flat_cube face 0 has two hard (flagged) edges out of three.
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("tessbench/flat_cube.obj"));
  std::map<std::string, techniques::OperationProfile> profiles;
  for (const techniques::VariantInfo& v : pn().variants()) {
    const auto profile = techniques::buildSurface(pn(), mesh, v)->operationProfile(0);
    ASSERT_TRUE(profile.has_value());
    profiles[v.name] = *profile;
    std::printf(
        "[pn ops] %s: set-up add %llu mul %llu div %llu sqrt %llu cmp %llu (total %llu); "
        "per vertex add %llu mul %llu div %llu sqrt %llu (total %llu)\n",
        v.name.c_str(), (unsigned long long)profile->per_patch_setup.add,
        (unsigned long long)profile->per_patch_setup.mul,
        (unsigned long long)profile->per_patch_setup.div,
        (unsigned long long)profile->per_patch_setup.sqrt,
        (unsigned long long)profile->per_patch_setup.compare,
        (unsigned long long)profile->per_patch_setup.total(),
        (unsigned long long)profile->per_vertex.add, (unsigned long long)profile->per_vertex.mul,
        (unsigned long long)profile->per_vertex.div, (unsigned long long)profile->per_vertex.sqrt,
        (unsigned long long)profile->per_vertex.total());
  }
  for (const auto& [name, profile] : profiles) {
    EXPECT_EQ(profile.per_vertex.total(), profiles["pn"].per_vertex.total()) << name;
  }
  EXPECT_GT(profiles["aen"].per_patch_setup.total(), profiles["pn"].per_patch_setup.total());
  // Two flagged edges: 4 geometry normals normalised (3 + 3 mul, 2 add, sqrt, div, compare).
  EXPECT_EQ(profiles["geometry_normals"].per_patch_setup.sqrt,
            profiles["pn"].per_patch_setup.sqrt + 4);
}

struct GpuCase {
  std::string asset;
  std::string variant;
};

class PnGpu : public ::testing::TestWithParam<std::string> {};

TEST_P(PnGpu, MatchesEvaluateFloatWithin4UlpOnEveryTriangleAsset) {
  // Oracle: evaluateFloat at the captured gl_TessCoord bits, and the CPU tessellator's
  // point count.
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const std::string& asset : testing::triangleAssets()) {
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
    const auto patches = techniques::buildSurface(pn(), mesh, variant(GetParam()));
    for (const auto& [spacing, level] :
         {std::pair{tess::Spacing::kInteger, 1.0f}, std::pair{tess::Spacing::kFractionalOdd, 7.3f},
          std::pair{tess::Spacing::kInteger, 16.0f}}) {
      const testing::GpuAgreement a =
          testing::compareGpuWithFloat(context, *patches, spacing, level);
      EXPECT_EQ(a.vertices, a.expected_vertices) << asset << " level " << level;
      EXPECT_LE(a.max_position_ulp, 4u) << asset << " level " << level;
      EXPECT_LE(a.max_normal_ulp, 4u) << asset << " level " << level;
      std::printf(
          "[pn gpu] %s %s level %.1f: %zu vertices, max ulp position %llu normal %llu, "
          "%zu positions not bitwise\n",
          GetParam().c_str(), asset.c_str(), level, a.vertices,
          (unsigned long long)a.max_position_ulp, (unsigned long long)a.max_normal_ulp,
          a.positions_not_bitwise);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, PnGpu,
                         ::testing::Values("pn", "geometry_normals", "boundary_flags", "aen",
                                           "rounding"));

}  // namespace
}  // namespace tb::pn_triangles
