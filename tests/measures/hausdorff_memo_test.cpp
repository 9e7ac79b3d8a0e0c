// The error measure's Hausdorff memo (harness/measures/error/hausdorff_memo.h). Oracle:
// ref::hausdorff on the same inputs, every figure bit for bit, first call and repeat; the
// control: a mesh one coordinate apart is a different key and gets its own figures.
#include "harness/measures/error/hausdorff_memo.h"

#include <gtest/gtest.h>

#include <vector>

namespace tb {
namespace {

struct Grid {
  std::vector<mesh::Vec3d> positions;
  std::vector<ref::Triangle> triangles;
  ref::TriangleMeshRef view() const { return {positions, triangles}; }
};

// An n x n grid of the unit square at height z(x, y), two triangles per cell.
template <class Height>
Grid grid(int n, Height z) {
  Grid g;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      g.positions.push_back({x, y, z(x, y)});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 1, d = c + 1;
      g.triangles.push_back({a, b, d});
      g.triangles.push_back({a, d, c});
    }
  }
  return g;
}

void expectSame(const ref::HausdorffResult& a, const ref::HausdorffResult& b) {
  EXPECT_EQ(a.hausdorff, b.hausdorff);
  EXPECT_EQ(a.rms, b.rms);
  EXPECT_EQ(a.a_to_b.max, b.a_to_b.max);
  EXPECT_EQ(a.b_to_a.max, b.b_to_a.max);
  EXPECT_EQ(a.a_to_b.rms, b.a_to_b.rms);
  EXPECT_EQ(a.b_to_a.samples, b.b_to_a.samples);
}

TEST(HausdorffMemo, EqualsTheDirectComputationAndKeysOnEveryCoordinate) {
  const Grid coarse = grid(6, [](double x, double y) { return 0.1 * x * y; });
  const Grid fine = grid(24, [](double x, double y) { return 0.1 * x * y + 0.01 * x * x; });
  const ref::HausdorffResult direct = ref::hausdorff(coarse.view(), fine.view(), 2);
  const ref::HausdorffResult first =
      measures::memoisedHausdorff(coarse.view(), coarse.view(), fine.view(), fine.view(), 2);
  const ref::HausdorffResult again =
      measures::memoisedHausdorff(coarse.view(), coarse.view(), fine.view(), fine.view(), 2);
  expectSame(first, direct);
  expectSame(again, direct);
  ASSERT_GT(direct.hausdorff, 0);

  // The control: one vertex moved is another key, with its own (larger) figures.
  Grid moved = coarse;
  moved.positions[10].z += 0.05;
  const ref::HausdorffResult other =
      measures::memoisedHausdorff(moved.view(), moved.view(), fine.view(), fine.view(), 2);
  expectSame(other, ref::hausdorff(moved.view(), fine.view(), 2));
  EXPECT_NE(other.hausdorff, direct.hausdorff);
}

}  // namespace
}  // namespace tb
