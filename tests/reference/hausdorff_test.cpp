// Oracles: distances known in closed form.
//  - A mesh against itself: 0.
//  - A triangulated sphere A (vertices on radius r) against B = 1.01 A. Every point
//    1.01 p of B is 0.01 |p| <= 0.01 r from p in A, so B -> A is at most 0.01 r; at a
//    vertex 1.01 v it is exactly 0.01 r, because A lies inside the ball of radius r,
//    whose nearest point to 1.01 v is v itself, which is in A. The lattice samples
//    include the vertices, so the sampled B -> A maximum is 0.01 r up to round-off,
//    and A -> B <= 0.01 r by the same scaling argument.
//  - Skipping lattice points bounded below the largest centroid distance (MaxSearch) gives
//    the figures of measuring every sample, bit for bit, on the bundled shapes; its control
//    halves the bound and must move a maximum.
//  - A flat square against a pyramid on it: the vertices of the square lie on the
//    pyramid, so vertex-only sampling would report 0 from square to pyramid; the true
//    value, at the centre, is the distance from the base centre to a slanted face.
#include "reference/hausdorff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <map>

#include "reference/limit_surface.h"
#include "reference/limit_tessellation.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

struct Soup {
  std::vector<mesh::Vec3d> positions;
  std::vector<Triangle> triangles;
  TriangleMeshRef view() const { return {positions, triangles}; }
};

// Icosahedron subdivided `levels` times, vertices pushed onto the sphere of radius r.
Soup icosphere(int levels, double radius) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  Soup s;
  s.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto mid = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, uint32_t(s.positions.size()));
      if (inserted) s.positions.push_back((s.positions[a] + s.positions[b]) * 0.5);
      return it->second;
    };
    std::vector<Triangle> finer;
    for (const Triangle& tri : s.triangles) {
      const uint32_t ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      finer.insert(finer.end(),
                   {{tri[0], ab, ca}, {tri[1], bc, ab}, {tri[2], ca, bc}, {ab, bc, ca}});
    }
    s.triangles = std::move(finer);
  }
  for (mesh::Vec3d& p : s.positions) p = normalize(p) * radius;
  return s;
}

TEST(Hausdorff, MeshAgainstItselfIsZero) {
  const LimitSurface surface(testing::loadShape("catmark_pawn.obj"), osd::Scheme::kCatmullClark);
  const LimitTessellation tessellation = tessellateLimit(surface, 2);
  const HausdorffResult result = hausdorff(tessellation.view(), tessellation.view());
  const double diagonal = boundingBoxDiagonal(tessellation.positions);
  // Interior samples are re-projected onto their own triangle: round-off only.
  EXPECT_LT(result.hausdorff, 1e-14 * diagonal);
  EXPECT_LT(result.rms, 1e-14 * diagonal);
  EXPECT_EQ(result.a_to_b.samples,
            tessellation.triangles.size() * size_t(15 + 16));  // level 4: 15 + 16 samples
}

TEST(Hausdorff, SphereAgainstScaledSphereIsOnePercentOfRadius) {
  constexpr double kRadius = 2.0;
  const Soup a = icosphere(3, kRadius);  // 1280 triangles
  Soup b = a;
  for (mesh::Vec3d& p : b.positions) p = p * 1.01;
  const HausdorffResult result = hausdorff(a.view(), b.view());
  const double known = 0.01 * kRadius;
  // Round-off of a few operations on coordinates of size ~2: 1e-12 relative is ample.
  EXPECT_NEAR(result.b_to_a.max, known, 1e-12 * known);
  EXPECT_NEAR(result.hausdorff, known, 1e-12 * known);
  EXPECT_LE(result.a_to_b.max, known * (1 + 1e-12));
  EXPECT_GT(result.a_to_b.max, 0.5 * known);
  // Every sample is within (0, 0.01 r], so are the means.
  EXPECT_GT(result.b_to_a.rms, 0.5 * known);
  EXPECT_LE(result.b_to_a.rms, known);
  EXPECT_LE(result.b_to_a.mean, result.b_to_a.rms);
  EXPECT_NEAR(result.b_to_a.area / result.a_to_b.area, 1.01 * 1.01, 1e-12);
  std::cout << "sphere r = 2 vs 1.01x: B->A max " << result.b_to_a.max << " (known " << known
            << "), A->B max " << result.a_to_b.max << ", RMS " << result.rms << "\n";
}

TEST(Hausdorff, SamplesInsideTrianglesNotOnlyVertices) {
  constexpr double kHalf = 1.0, kHeight = 0.5;
  Soup square;
  square.positions = {
      {-kHalf, -kHalf, 0}, {kHalf, -kHalf, 0}, {kHalf, kHalf, 0}, {-kHalf, kHalf, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  Soup pyramid = square;
  pyramid.positions.push_back({0, 0, kHeight});
  pyramid.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const HausdorffResult result = hausdorff(square.view(), pyramid.view());
  // The square's centre (a lattice point of the diagonal at even levels) to the plane
  // through the apex and a base edge.
  const double centre_to_face = kHeight * kHalf / std::sqrt(kHalf * kHalf + kHeight * kHeight);
  EXPECT_NEAR(result.a_to_b.max, centre_to_face, 1e-14);
  EXPECT_NEAR(result.b_to_a.max, kHeight, 1e-14);  // the apex
  EXPECT_NEAR(result.a_to_b.max_at.x, 0.0, 1e-14);
  EXPECT_NEAR(result.a_to_b.max_at.y, 0.0, 1e-14);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameFigures(const DirectedDistance& a, const DirectedDistance& b) {
  for (int k = 0; k < 3; ++k) {
    if (!sameBits(a.max_at[k], b.max_at[k])) return false;
  }
  return sameBits(a.max, b.max) && sameBits(a.rms, b.rms) && sameBits(a.mean, b.mean) &&
         sameBits(a.area, b.area) && a.samples == b.samples;
}

TEST(Hausdorff, SkippingBoundedLatticePointsKeepsEveryFigureBitForBit) {
  size_t cases = 0, control_moved = 0;
  for (const std::string& name : testing::bundledShapes("catmark_")) {
    const mesh::Mesh shape = testing::loadShape(name);
    if (shape.faceCount() > 200) continue;  // the pawn and the helmet: the same code, slower
    const LimitSurface surface(shape, osd::Scheme::kCatmullClark);
    const LimitTessellation coarse = tessellateLimit(surface, 2);
    const LimitTessellation fine = tessellateLimit(surface, 5);
    for (const auto& [source, target] : {std::pair{&coarse, &fine}, std::pair{&fine, &coarse}}) {
      const TriangleDistanceField field(target->view());
      for (int level : {2, 3}) {
        const DirectedDistance every =
            directedDistance(source->view(), field, level, MaxSearch::kEverySample);
        const DirectedDistance skipped =
            directedDistance(source->view(), field, level, MaxSearch::kBoundedSkip);
        EXPECT_TRUE(sameFigures(every, skipped)) << name << " level " << level;
        const DirectedDistance broken =
            directedDistance(source->view(), field, level, MaxSearch::kBrokenSkip);
        control_moved += !sameFigures(every, broken);
        ++cases;
      }
    }
  }
  EXPECT_GE(cases, 40u);
  EXPECT_GT(control_moved, 0u);
  std::cout << cases << " cases; the halved bound moved the maximum in " << control_moved << "\n";
}

}  // namespace
}  // namespace tb::ref
