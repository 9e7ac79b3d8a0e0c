// Oracles: the definition of Phong tessellation (Boubekeur & Alexa 2008, eq. 3-4)
// — corners interpolate, α = 0 is linear interpolation — and the exact sphere.
#include "techniques/phong/phong.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "core/mesh/obj_loader.h"
#include "techniques/counting_scalar.h"
#include "techniques/phong/phong_eval.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb::phong {
namespace {

template <class T>
PhongTriangle<T> randomTriangle(std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(-1, 1);
  PhongTriangle<T> tri;
  for (int i = 0; i < 3; ++i) {
    tri.position[i] = {T(coord(rng)), T(coord(rng)), T(coord(rng))};
    tri.normal[i] = normalize(mesh::Vec3T<T>{T(coord(rng)), T(coord(rng)), T(coord(rng))});
  }
  return tri;
}

TEST(PhongEval, InterpolatesTheCornersExactly) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    const auto tri = randomTriangle<double>(rng);
    for (int corner = 0; corner < 3; ++corner) {
      std::array<double, 3> weight{0, 0, 0};
      weight[corner] = 1;
      for (double alpha : {0.0, 0.5, 0.75, 1.0}) {
        const auto p = evaluatePhong(tri, weight, alpha);
        EXPECT_EQ(p.position, tri.position[corner]);
        EXPECT_NEAR(length(p.normal - tri.normal[corner]), 0.0, 1e-15);
      }
    }
  }
}

TEST(PhongEval, AlphaZeroIsTheFlatTriangle) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const auto tri = randomTriangle<double>(rng);
    double u = unit(rng), v = unit(rng) * (1 - u);
    const std::array<double, 3> w{u, v, 1 - u - v};
    const auto p = evaluatePhong(tri, w, 0.0);
    const mesh::Vec3d flat =
        tri.position[0] * w[0] + tri.position[1] * w[1] + tri.position[2] * w[2];
    // Equal up to the rounding of a differently ordered three-term sum.
    EXPECT_LT(length(p.position - flat), 1e-15);
  }
}

TEST(PhongEval, RotatingTheCornersGivesBitwiseEqualFloatResults) {
  // Stronger than the 1-ulp bound asked for: the canonical corner order makes
  // the float result independent of the rotation (0 ulp).
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    const auto tri = randomTriangle<float>(rng);
    const float u = float(unit(rng)), v = float(unit(rng)) * (1 - u), w = 1 - u - v;
    for (int shift = 1; shift < 3; ++shift) {
      PhongTriangle<float> rotated;
      std::array<float, 3> weight, rotated_weight{u, v, w};
      for (int i = 0; i < 3; ++i) {
        rotated.position[i] = tri.position[(i + shift) % 3];
        rotated.normal[i] = tri.normal[(i + shift) % 3];
        weight[i] = rotated_weight[(i + shift) % 3];
      }
      const auto a = evaluatePhong(tri, {u, v, w}, 0.75f);
      const auto b = evaluatePhong(rotated, weight, 0.75f);
      EXPECT_EQ(a.position, b.position);
      EXPECT_EQ(a.normal, b.normal);
    }
  }
}

TEST(PhongEval, SummationOrderMattersWithoutTheCanonicalOrder) {
  // Guards the test above against passing trivially: the same rotation through
  // evaluatePhongInOrder changes some float results.
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0, 1);
  int differing = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto tri = randomTriangle<float>(rng);
    const float u = float(unit(rng)), v = float(unit(rng)) * (1 - u), w = 1 - u - v;
    PhongTriangle<float> rotated;
    for (int i = 0; i < 3; ++i) {
      rotated.position[i] = tri.position[(i + 1) % 3];
      rotated.normal[i] = tri.normal[(i + 1) % 3];
    }
    const auto a = evaluatePhongInOrder(tri, {u, v, w}, 0.75f);
    const auto b = evaluatePhongInOrder(rotated, {v, w, u}, 0.75f);
    differing += !(a.position == b.position);
  }
  EXPECT_GT(differing, 100);
}

TEST(PhongPatches, RotationOfTheFaceGivesBitwiseEqualPoints) {
  // The technique sums in ascending vertex order, so a rotated face is exact.
  const char* kA =
      "v 0 0 0\nv 1 0 0.2\nv 0 1 0.1\nvn 0 0 1\nvn 0.3 0 1\nvn 0 0.4 1\nf 1//1 2//2 3//3\n";
  const char* kB =
      "v 0 0 0\nv 1 0 0.2\nv 0 1 0.1\nvn 0 0 1\nvn 0.3 0 1\nvn 0 0.4 1\nf 2//2 3//3 1//1\n";
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const techniques::VariantInfo variant = phong->variants()[0];
  const auto a = techniques::buildSurface(*phong, mesh::loadObjText(kA, "a.obj"), variant);
  const auto b = techniques::buildSurface(*phong, mesh::loadObjText(kB, "b.obj"), variant);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 500; ++trial) {
    const double u = unit(rng), v = unit(rng) * (1 - u), w = 1 - u - v;
    const techniques::SurfacePoint pa = a->evaluate(0, {u, v, w});
    const techniques::SurfacePoint pb = b->evaluate(0, {v, w, u});
    EXPECT_EQ(pa.position, pb.position);
  }
}

TEST(PhongPatches, CurvesTowardTheSphereItApproximates) {
  // An octant triangle of the unit sphere with exact normals: Phong (α = 3/4)
  // must lie closer to the sphere than the flat triangle at every interior point.
  const char* kOctant =
      "v 1 0 0\nv 0 1 0\nv 0 0 1\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//3\n";
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const auto patches = techniques::buildSurface(*phong, mesh::loadObjText(kOctant, "octant.obj"),
                                                phong->variants()[0]);
  for (int i = 1; i < 10; ++i) {
    for (int j = 1; i + j < 10; ++j) {
      const double u = i / 10.0, v = j / 10.0, w = 1 - u - v;
      const double curved = std::fabs(length(patches->evaluate(0, {u, v, w}).position) - 1);
      const double flat = std::fabs(length(mesh::Vec3d{u, v, w}) - 1);
      EXPECT_LT(curved, flat) << u << " " << v;
    }
  }
}

TEST(PhongPatches, PolygonsAreFanTriangulatedWithAWarning) {
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const auto patches = techniques::buildSurface(*phong, mesh, phong->variants()[0]);
  EXPECT_EQ(patches->patchCount(), 12u);
  EXPECT_EQ(patches->patchDomain(0), techniques::PatchDomain::kTriangle);
  ASSERT_FALSE(patches->warnings().empty());
  EXPECT_NE(patches->warnings()[0].find("fan-triangulated"), std::string::npos);
  EXPECT_EQ(patches->sourceFace(11), 5u);
}

}  // namespace
}  // namespace tb::phong

namespace tb::phong {
namespace {

TEST(PhongEval, CountingScalarGivesTheSameResultAndExactOperationCounts) {
  // Hand count of evaluatePhongInOrder (paper eq. 3-4 in the p - α Σ w_i h_i n_i form):
  //   flat point: 3 vec3 scalings (9 mul) + 2 vec3 adds (6 add)
  //   per corner: vec3 sub (3 add), dot (3 mul, 2 add), w_i*h (1 mul),
  //               vec3 scale (3 mul), vec3 add (3 add)          -> ×3
  //   offset*α (3 mul), flat - offset (3 add)
  //   normal: 3 vec3 scalings (9 mul), 2 vec3 adds (6 add), normalize:
  //           dot (3 mul, 2 add), sqrt, 1 compare, 1 div, vec3 scale (3 mul)
  using C = techniques::CountingScalar<float>;
  PhongTriangle<C> tri;
  PhongTriangle<float> plain;
  const float pos[3][3] = {{0, 0, 0}, {1, 0, 0.2f}, {0, 1, 0.1f}};
  const float nrm[3][3] = {{0, 0, 1}, {0.3f, 0, 0.95f}, {0, 0.4f, 0.9f}};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      tri.position[i][k] = pos[i][k];
      tri.normal[i][k] = nrm[i][k];
      plain.position[i][k] = pos[i][k];
      plain.normal[i][k] = nrm[i][k];
    }
  }
  techniques::resetOperationCounts();
  const auto counted = evaluatePhongInOrder<C>(tri, {C(0.2f), C(0.3f), C(0.5f)}, C(0.75f));
  const techniques::OperationCounts ops = techniques::operationCounts();
  const auto reference = evaluatePhongInOrder<float>(plain, {0.2f, 0.3f, 0.5f}, 0.75f);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(counted.position[k].value(), reference.position[k]);
  EXPECT_EQ(ops.mul, 9u + 3 * 7 + 3 + 9 + 3 + 3);
  EXPECT_EQ(ops.add, 6u + 3 * 8 + 3 + 6 + 2);
  EXPECT_EQ(ops.sqrt, 1u);
  EXPECT_EQ(ops.div, 1u);
  EXPECT_EQ(ops.compare, 1u);
}

}  // namespace
}  // namespace tb::phong
