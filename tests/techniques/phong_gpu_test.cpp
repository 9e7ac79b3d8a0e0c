// phong on the GPU and its `edge` variant (seed 003's per-edge extension). Oracles: the
// CPU float model evaluateFloat at the captured gl_TessCoord bits (within 4 ulp), the
// definition of Phong tessellation (α = 0 is the flat triangle, corners interpolate) and,
// for `edge`, that with the vertex normals on every edge the edge curves are the paper's.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "core/mesh/obj_loader.h"
#include "techniques/phong/phong_edge_eval.h"
#include "techniques/phong/phong_eval.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/techniques/pn_gpu_support.h"

namespace tb::phong {
namespace {

const techniques::Technique& phong() {
  return *techniques::TechniqueRegistry::instance().find("phong");
}

techniques::VariantInfo variant(const std::string& name) {
  for (const techniques::VariantInfo& v : phong().variants()) {
    if (v.name == name) return v;
  }
  ADD_FAILURE() << "no variant " << name;
  return {};
}

template <class T>
PhongEdgeTriangle<T> randomEdgeTriangle(std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1, 1);
  PhongEdgeTriangle<T> tri;
  for (int i = 0; i < 3; ++i) {
    tri.position[i] = {T(coord(rng)), T(coord(rng)), T(coord(rng))};
    tri.normal[i] = normalize(mesh::Vec3T<T>{T(coord(rng)), T(coord(rng)), T(coord(rng))});
  }
  for (int e = 0; e < 3; ++e) {
    for (int end = 0; end < 2; ++end) tri.edge_normal[e][end] = tri.normal[kPhongEdgeEnds[e][end]];
  }
  return tri;
}

TEST(PhongEdge, AlphaZeroIsLinearAndCornersInterpolate) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const auto tri = randomEdgeTriangle<double>(rng);
    const double u = unit(rng), v = unit(rng) * (1 - u);
    const std::array<double, 3> w{u, v, 1 - u - v};
    const mesh::Vec3d flat =
        tri.position[0] * w[0] + tri.position[1] * w[1] + tri.position[2] * w[2];
    EXPECT_EQ(evaluatePhongEdge(tri, w, 0.0).position, flat);
    for (int corner = 0; corner < 3; ++corner) {
      std::array<double, 3> c{0, 0, 0};
      c[corner] = 1;
      EXPECT_EQ(evaluatePhongEdge(tri, c, 0.75).position, tri.position[corner]);
    }
  }
}

TEST(PhongEdge, OnEdgesItIsThePapersPhongCurve) {
  // Oracle: Boubekeur & Alexa eq. 3-4 on an edge involve only that edge's two corners,
  // so with vertex normals on every edge the edge variant must agree there.
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const auto tri = randomEdgeTriangle<double>(rng);
    PhongTriangle<double> plain;
    plain.position = tri.position;
    plain.normal = tri.normal;
    const double t = unit(rng);
    for (int e = 0; e < 3; ++e) {
      std::array<double, 3> w{0, 0, 0};
      w[kPhongEdgeEnds[e][0]] = t;
      w[kPhongEdgeEnds[e][1]] = 1 - t;
      const mesh::Vec3d a = evaluatePhongEdge(tri, w, 0.75).position;
      const mesh::Vec3d b = evaluatePhongInOrder(plain, w, 0.75).position;
      EXPECT_LT(length(a - b), 1e-14);
    }
  }
}

TEST(PhongEdge, TechniqueVariantAlphaZeroMatchesLinearInterpolation) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("tessbench/cylinder_seam.obj"));
  techniques::VariantInfo flat = variant("edge");
  flat.parameters["alpha"] = 0.0;
  const auto patches = techniques::buildSurface(phong(), mesh, flat);
  for (size_t p = 0; p < patches->patchCount(); p += 7) {
    const auto corners = patches->patchCorners(p);
    const mesh::Vec3d expected =
        (mesh.positions[corners[0]] * 0.2 + mesh.positions[corners[1]] * 0.3) +
        mesh.positions[corners[2]] * 0.5;
    EXPECT_LT(length(patches->evaluate(p, {0.2, 0.3, 0.5}).position - expected), 1e-14);
  }
}

class PhongGpu : public ::testing::TestWithParam<std::string> {};

TEST_P(PhongGpu, MatchesEvaluateFloatWithin4UlpOnEveryTriangleAsset) {
  // Oracle: evaluateFloat at the captured gl_TessCoord bits; the CPU tessellator's counts.
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const std::string& asset : testing::triangleAssets()) {
    const auto patches = techniques::buildSurface(
        phong(), mesh::loadObjFile(testing::assetPath(asset)), variant(GetParam()));
    for (const auto& [spacing, level] :
         {std::pair{tess::Spacing::kInteger, 1.0f}, std::pair{tess::Spacing::kFractionalOdd, 7.3f},
          std::pair{tess::Spacing::kInteger, 16.0f}}) {
      const testing::GpuAgreement a =
          testing::compareGpuWithFloat(context, *patches, spacing, level);
      EXPECT_EQ(a.vertices, a.expected_vertices) << asset << " level " << level;
      EXPECT_LE(a.max_position_ulp, 4u) << asset << " level " << level;
      EXPECT_LE(a.max_normal_ulp, 4u) << asset << " level " << level;
      std::printf(
          "[phong gpu] %s %s level %.1f: %zu vertices, max ulp position %llu normal "
          "%llu, %zu positions not bitwise\n",
          GetParam().c_str(), asset.c_str(), level, a.vertices,
          (unsigned long long)a.max_position_ulp, (unsigned long long)a.max_normal_ulp,
          a.positions_not_bitwise);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, PhongGpu,
                         ::testing::Values("alpha0.75", "alpha0", "alpha0.5", "alpha1", "edge"));

TEST(PhongOperations, PlainPhongCountsMatchAHandCount) {
  // Hand count of evaluatePhongInOrder: flat point 9 mul 6 add; per corner: p - p_i 3 add,
  // dot 3 mul 2 add, w·h 1 mul, n·s 3 mul, offset += 3 add => 3 × (7 mul, 8 add); result
  // 3 mul 3 add; normal 9 mul 6 add + normalise (3 mul 2 add, sqrt, div, 3 mul, compare).
  const auto patches = techniques::buildSurface(
      phong(), mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj")),
      variant("alpha0.75"));
  const auto profile = patches->operationProfile(0);
  ASSERT_TRUE(profile.has_value());
  EXPECT_EQ(profile->per_vertex.mul, 9u + 21u + 3u + 9u + 6u);
  EXPECT_EQ(profile->per_vertex.add, 6u + 24u + 3u + 6u + 2u);
  EXPECT_EQ(profile->per_vertex.div, 1u);
  EXPECT_EQ(profile->per_vertex.sqrt, 1u);
  // Set-up: 3 normalisations (3 + 3 mul, 2 add, sqrt, div, compare each).
  EXPECT_EQ(profile->per_patch_setup.mul, 18u);
  EXPECT_EQ(profile->per_patch_setup.sqrt, 3u);
}

TEST(PhongOperations, EdgeVariantCostsMorePerVertexThanPlainPhong) {
  // Oracle: seed 003 names the cost of the per-edge extension, more shader instructions;
  // the counts are printed for the report.
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("tessbench/cylinder_seam.obj"));
  const auto plain =
      techniques::buildSurface(phong(), mesh, variant("alpha0.75"))->operationProfile(0);
  const auto edge = techniques::buildSurface(phong(), mesh, variant("edge"))->operationProfile(0);
  ASSERT_TRUE(plain.has_value() && edge.has_value());
  for (const auto& [name, p] : {std::pair{"alpha0.75", *plain}, std::pair{"edge", *edge}}) {
    std::printf(
        "[phong ops] %s: set-up total %llu (sqrt %llu); per vertex add %llu mul %llu div "
        "%llu sqrt %llu cmp %llu (total %llu)\n",
        name, (unsigned long long)p.per_patch_setup.total(),
        (unsigned long long)p.per_patch_setup.sqrt, (unsigned long long)p.per_vertex.add,
        (unsigned long long)p.per_vertex.mul, (unsigned long long)p.per_vertex.div,
        (unsigned long long)p.per_vertex.sqrt, (unsigned long long)p.per_vertex.compare,
        (unsigned long long)p.per_vertex.total());
  }
  EXPECT_GT(edge->per_vertex.total(), plain->per_vertex.total());
  EXPECT_EQ(edge->per_patch_setup.sqrt, 9u);  // 3 corner + 6 edge-end normals
}

}  // namespace
}  // namespace tb::phong
