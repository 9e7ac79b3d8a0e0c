// Tessellation capture on the device. Oracles: the closed-form counts of docs/ARCHITECTURE.md
// ("quad 2n^2 triangles and (n+1)^2 points; triangle floor(3n^2/2) triangles", measured
// on lavapipe) and the Vulkan specification's culling rule (an outer level <= 0 or NaN
// discards the patch).
#include "core/gpu/tess_capture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <set>

#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

using tess::Domain;
using tess::Levels;
using tess::Spacing;

Levels uniform(float level) { return Levels{{level, level, level, level}, {level, level}}; }

TEST(TessCapture, QuadLevel4Integer) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const GpuTessellation t = tessellateOnGpu(context, Domain::kQuad, Spacing::kInteger, uniform(4));
  EXPECT_FALSE(t.culled);
  EXPECT_EQ(t.points.size(), 25u);
  EXPECT_EQ(t.triangles.size(), 32u);
  EXPECT_TRUE(t.lines.empty());
  EXPECT_EQ(t.stats.tes_invocations, 25u);
  EXPECT_EQ(t.stats.tcs_patches, 1u);
  EXPECT_EQ(t.stats.vs_invocations, 1u);
  EXPECT_EQ(t.stats.clipping_invocations, 0u) << "rasterizer discard";
  EXPECT_GT(t.submit_to_fence_s, 0.0);
  // Integer spacing at level 4: every coordinate is a multiple of 1/4, exactly.
  for (const tess::DomainPoint& p : t.points) {
    EXPECT_EQ(p[0] * 4, std::floor(p[0] * 4));
    EXPECT_EQ(p[1] * 4, std::floor(p[1] * 4));
    EXPECT_EQ(p[2], 0.0f);
  }
}

TEST(TessCapture, TriangleCountsFollowFloor3nSquaredOver2) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  std::vector<Levels> levels;
  for (int n = 1; n <= 64; ++n) levels.push_back(uniform(float(n)));
  const GpuTessellationBatch batch =
      tessellateOnGpuBatch(context, Domain::kTriangle, Spacing::kInteger, levels);
  ASSERT_EQ(batch.patches.size(), levels.size());
  for (int n = 1; n <= 64; ++n) {
    const GpuTessellation& t = batch.patches[n - 1];
    EXPECT_EQ(t.triangles.size(), uint64_t(3 * n * n / 2)) << "n=" << n;
    EXPECT_EQ(t.stats.tes_invocations, t.points.size()) << "n=" << n;
  }
}

TEST(TessCapture, BatchEqualsSingleDraws) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<Levels> levels = {uniform(3), uniform(7.5f), Levels{{2, 5, 9, 1}, {3, 6}}};
  const auto batch = tessellateOnGpuBatch(context, Domain::kQuad, Spacing::kFractionalEven, levels);
  for (size_t i = 0; i < levels.size(); ++i) {
    const auto single =
        tessellateOnGpu(context, Domain::kQuad, Spacing::kFractionalEven, levels[i]);
    EXPECT_EQ(single.points, batch.patches[i].points) << i;
    EXPECT_EQ(single.triangles, batch.patches[i].triangles) << i;
  }
}

TEST(TessCapture, NanNegativeAndZeroOuterLevelsCull) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (float bad : {nan, -1.0f, 0.0f, -0.0f}) {
    for (Domain domain : {Domain::kTriangle, Domain::kQuad, Domain::kIsoline}) {
      Levels levels = uniform(5);
      levels.outer[1] = bad;
      const auto t = tessellateOnGpu(context, domain, Spacing::kFractionalOdd, levels);
      EXPECT_TRUE(t.culled) << "domain " << static_cast<int>(domain) << " outer[1]=" << bad;
      EXPECT_EQ(t.points.size(), 0u);
      EXPECT_EQ(t.stats.tes_invocations, 0u);
    }
  }
  // An unused outer level (quad's 4th is used; triangle's 4th is not) must not cull.
  Levels levels = uniform(5);
  levels.outer[3] = nan;
  EXPECT_FALSE(tessellateOnGpu(context, Domain::kTriangle, Spacing::kInteger, levels).culled);
  EXPECT_TRUE(tessellateOnGpu(context, Domain::kQuad, Spacing::kInteger, levels).culled);
}

TEST(TessCapture, IsolinesAndPointMode) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  // Isolines: outer[0] lines of outer[1] segments each.
  const auto lines =
      tessellateOnGpu(context, Domain::kIsoline, Spacing::kInteger, Levels{{3, 4, 1, 1}, {1, 1}});
  EXPECT_EQ(lines.lines.size(), 12u);
  EXPECT_EQ(lines.points.size(), 15u);
  EXPECT_TRUE(lines.triangles.empty());

  tess::Options point_mode;
  point_mode.point_mode = true;
  const auto points =
      tessellateOnGpu(context, Domain::kQuad, Spacing::kInteger, uniform(4), point_mode);
  EXPECT_EQ(points.points.size(), 25u);
  EXPECT_TRUE(points.triangles.empty());
  EXPECT_EQ(points.stats.tes_invocations, 25u);
}

TEST(TessCapture, ClockwiseReversesEveryTriangle) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  tess::Options cw;
  cw.ccw = false;
  const auto a = tessellateOnGpu(context, Domain::kTriangle, Spacing::kInteger, uniform(3));
  const auto b = tessellateOnGpu(context, Domain::kTriangle, Spacing::kInteger, uniform(3), cw);
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  // Oriented triangles as coordinate triples, rotated to start at their smallest vertex.
  auto oriented = [](const tess::Tessellation& t, bool reverse) {
    std::set<std::array<tess::DomainPoint, 3>> set;
    for (auto tri : t.triangles) {
      if (reverse) std::swap(tri[1], tri[2]);
      std::array<tess::DomainPoint, 3> c = {t.points[tri[0]], t.points[tri[1]], t.points[tri[2]]};
      std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
      set.insert(c);
    }
    return set;
  };
  EXPECT_EQ(oriented(a, false), oriented(b, true));
  EXPECT_NE(oriented(a, false), oriented(b, false));
}

// tess::Options::ccw means counter-clockwise in the (u, v) plane with v up (GL's and
// Vulkan's lower-left domain origin; the CPU tessellator's convention).
TEST(TessCapture, CcwIsCounterClockwiseInUvWithVUp) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (Domain domain : {Domain::kTriangle, Domain::kQuad}) {
    const auto t = tessellateOnGpu(context, domain, Spacing::kInteger, uniform(2));
    ASSERT_FALSE(t.triangles.empty());
    for (const auto& tri : t.triangles) {
      const auto& a = t.points[tri[0]];
      const auto& b = t.points[tri[1]];
      const auto& c = t.points[tri[2]];
      const float twice_area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
      EXPECT_GT(twice_area, 0.0f) << "domain " << static_cast<int>(domain);
    }
  }
}

TEST(TessCapture, ThroughputCountsEveryDraw) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const auto run = measureTessThroughput(context, Domain::kQuad, Spacing::kInteger, uniform(8), 10);
  EXPECT_EQ(run.stats.tcs_patches, 10u);
  EXPECT_EQ(run.stats.tes_invocations, 10u * 81u);
  EXPECT_GT(run.submit_to_fence_s, 0.0);
}

}  // namespace
}  // namespace tb::gpu
