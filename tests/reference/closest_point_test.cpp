// Oracles:
//  - closestPointOnTriangle (Ericson's region method) against a different
//    construction written here: project onto the plane and keep the projection when
//    its barycentrics are all >= 0, else take the nearest of the three clamped
//    segment projections;
//  - TriangleDistanceField (Embree BVH + that callback) against brute force over
//    every triangle; on slivers (whose computed plane normals tilt) bit for bit, the
//    lowest index on ties.
#include "reference/closest_point.h"

#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "core/mesh/input_error.h"
#include "reference/limit_surface.h"
#include "reference/limit_tessellation.h"
#include "reference/triangle_distance_field.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

mesh::Vec3d segmentClosest(const mesh::Vec3d& p, const mesh::Vec3d& a, const mesh::Vec3d& b) {
  const mesh::Vec3d d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return a + d * t;
}

double oracleDistance(const mesh::Vec3d& p, const mesh::Vec3d& a, const mesh::Vec3d& b,
                      const mesh::Vec3d& c) {
  const mesh::Vec3d n = cross(b - a, c - a);
  const mesh::Vec3d q = p - n * (dot(p - a, n) / dot(n, n));
  const double wa = dot(cross(c - b, q - b), n), wb = dot(cross(a - c, q - c), n),
               wc = dot(cross(b - a, q - a), n);
  if (wa >= 0 && wb >= 0 && wc >= 0) return length(p - q);
  return std::min({length(p - segmentClosest(p, a, b)), length(p - segmentClosest(p, b, c)),
                   length(p - segmentClosest(p, c, a))});
}

mesh::Vec3d randomPoint(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

TEST(ClosestPoint, EricsonMatchesProjectionOracle) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20000; ++trial) {
    // Every fourth triangle is a sliver, to reach the edge regions from inside.
    const mesh::Vec3d a = randomPoint(rng, 1), b = randomPoint(rng, 1);
    const mesh::Vec3d c =
        trial % 4 ? randomPoint(rng, 1) : a + (b - a) * 0.3 + randomPoint(rng, 1e-3);
    const mesh::Vec3d p = randomPoint(rng, 2);
    const TrianglePoint hit = closestPointOnTriangle(p, a, b, c);
    const double expected = oracleDistance(p, a, b, c);
    EXPECT_NEAR(length(hit.point - p), expected, 1e-12 * (1 + expected)) << trial;
    // The barycentrics reproduce the point and lie in the triangle.
    const mesh::Vec3d from_weights =
        a * hit.barycentric.x + b * hit.barycentric.y + c * hit.barycentric.z;
    EXPECT_LT(length(from_weights - hit.point), 1e-12) << trial;
    for (int k = 0; k < 3; ++k) EXPECT_GE(hit.barycentric[k], -1e-12) << trial;
    EXPECT_NEAR(hit.barycentric.x + hit.barycentric.y + hit.barycentric.z, 1.0, 1e-12);
  }
}

TEST(ClosestPoint, DegenerateTriangleIsItsLongestEdge) {
  const mesh::Vec3d a{0, 0, 0}, b{2, 0, 0}, c{1, 0, 0};  // collinear
  const TrianglePoint hit = closestPointOnTriangle({1.5, 1, 0}, a, b, c);
  EXPECT_NEAR(hit.point.x, 1.5, 1e-15);
  EXPECT_NEAR(hit.point.y, 0.0, 1e-15);
  const TrianglePoint point = closestPointOnTriangle({3, 0, 4}, a, a, a);
  EXPECT_EQ(length(point.point - a), 0.0);
}

TEST(TriangleDistanceField, MatchesBruteForceOnRandomQueries) {
  // ~10k triangles of the pawn's limit surface: curved, with thin features.
  const LimitSurface surface(testing::loadShape("catmark_pawn.obj"), osd::Scheme::kCatmullClark);
  const LimitTessellation tessellation = tessellateLimit(surface, 3);
  ASSERT_GT(tessellation.triangles.size(), 10000u);
  const TriangleDistanceField field(tessellation.view());
  const double diagonal = boundingBoxDiagonal(tessellation.positions);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<size_t> pick(0, tessellation.positions.size() - 1);
  double worst = 0;
  for (int q = 0; q < 1000; ++q) {
    // Half the queries far and wide, half just off the surface where triangles crowd.
    const mesh::Vec3d query =
        q % 2 ? randomPoint(rng, 0.8 * diagonal)
              : tessellation.positions[pick(rng)] + randomPoint(rng, 1e-3 * diagonal);
    double brute = std::numeric_limits<double>::infinity();
    for (const Triangle& t : tessellation.triangles) {
      const auto& p = tessellation.positions;
      brute = std::min(
          brute, length(closestPointOnTriangle(query, p[t[0]], p[t[1]], p[t[2]]).point - query));
    }
    const ClosestPoint hit = field.closest(query);
    EXPECT_NEAR(hit.distance, brute, 1e-6 * brute) << q;
    worst = std::max(worst, std::abs(hit.distance - brute) / brute);
    const Triangle& t = tessellation.triangles[hit.triangle];
    const mesh::Vec3d from_weights = tessellation.positions[t[0]] * hit.barycentric.x +
                                     tessellation.positions[t[1]] * hit.barycentric.y +
                                     tessellation.positions[t[2]] * hit.barycentric.z;
    EXPECT_LT(length(from_weights - hit.point), 1e-12 * diagonal);
    EXPECT_NEAR(length(hit.point - query), hit.distance, 1e-15 * diagonal);
  }
  std::cout << "max |field - brute force| / brute force over 1000 queries: " << worst << "\n";
}

// Fans of slivers around shared points: angles down to 1e-9 radians, where a cross
// product's direction is rounded by ~1e-7, beside flat triangles at small heights.
TEST(TriangleDistanceField, SliversGiveTheBruteForceMinimumBitForBit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<mesh::Vec3d> positions;
  std::vector<Triangle> triangles;
  for (int fan = 0; fan < 40; ++fan) {
    const mesh::Vec3d apex{unit(rng), unit(rng), unit(rng)};
    const mesh::Vec3d dir = normalize(mesh::Vec3d{unit(rng), unit(rng), unit(rng)});
    const mesh::Vec3d side = normalize(cross(dir, mesh::Vec3d{unit(rng), unit(rng), unit(rng)}));
    for (int k = 0; k < 12; ++k) {
      const double angle = std::pow(10.0, -1 - 0.7 * k), len = 0.3 + 0.2 * unit(rng);
      const uint32_t base = uint32_t(positions.size());
      positions.push_back(apex);
      positions.push_back(apex + dir * len);
      positions.push_back(apex + (dir + side * angle) * len * 0.9);
      triangles.push_back({base, base + 1, base + 2});
    }
  }
  const TriangleDistanceField field(positions, triangles);
  for (int q = 0; q < 2000; ++q) {
    const Triangle& near = triangles[size_t(q) % triangles.size()];
    const double w = 0.5 + 0.5 * unit(rng);
    const mesh::Vec3d query = positions[near[0]] * (1 - w) + positions[near[1]] * w +
                              mesh::Vec3d{unit(rng), unit(rng), unit(rng)} * 1e-4;
    double brute = std::numeric_limits<double>::infinity();
    uint32_t brute_triangle = kNoTriangle;
    for (uint32_t t = 0; t < triangles.size(); ++t) {
      const auto& tri = triangles[t];
      const double d = length(
          closestPointOnTriangle(query, positions[tri[0]], positions[tri[1]], positions[tri[2]])
              .point -
          query);
      if (d < brute) brute = d, brute_triangle = t;
    }
    const ClosestPoint hit = field.closest(query);
    ASSERT_EQ(hit.distance, brute) << q;
    ASSERT_EQ(hit.triangle, brute_triangle) << q;
  }
}

TEST(TriangleDistanceField, EmptyMeshIsInfinitelyFar) {
  const TriangleDistanceField field(std::span<const mesh::Vec3d>{}, std::span<const Triangle>{});
  EXPECT_EQ(field.closest({1, 2, 3}).distance, std::numeric_limits<double>::infinity());
  EXPECT_EQ(field.closest({1, 2, 3}).triangle, kNoTriangle);
}

TEST(TriangleDistanceField, RejectsOutOfRangeCorners) {
  const std::vector<mesh::Vec3d> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Triangle> triangles{{0, 1, 2}, {0, 2, 3}};
  try {
    TriangleDistanceField field(positions, triangles, "soup");
    FAIL() << "expected InputError";
  } catch (const mesh::InputError& error) {
    EXPECT_EQ(error.file(), "soup");
    EXPECT_EQ(error.element(), "triangle 1");
  }
}

}  // namespace
}  // namespace tb::ref
