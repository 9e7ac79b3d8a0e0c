// The compute tessellator (shaders/gpu/tessellate.comp) against the CPU tessellator
// (core/tess, bit-exact with lavapipe: tess_sweep_test.cpp), bit for bit and in order: the
// same culling, the same points (16.16 (u, v), float w), the same triangles or line
// segments in the same order. Every domain x spacing, random level sets from the sweep's
// generator plus per-edge levels just above every integer 1..64 (one float ulp, half a
// 16.16 step: the rounding tie, one step, one and a half), in both windings and point mode,
// all patches of a pass in one batch (one submission). Broken controls: a kernel that
// truncates levels to 16.16 instead of rounding half to even, and CPU levels nudged by one
// 16.16 step, must both be caught on the fractional spacings.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/gpu/compute_tessellator.h"
#include "core/tess/tessellator.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/gpu/tess_level_generator.h"

namespace tb::gpu::compute_tessellator_test {
namespace {

using tess::Domain;
using tess::Spacing;

constexpr uint32_t kSeed = 0xc0de41;
constexpr int kRandomPerCell = 120;
constexpr int kMismatchesReported = 400;

bool fractional(Spacing s) {
  return s == Spacing::kFractionalOdd || s == Spacing::kFractionalEven;
}

// Level k plus offset o for each of the six levels, o cycling through just-above values.
tess::Levels justAbove(int k) {
  const float above[] = {std::nextafter(float(k), 100.0f), float(k) + 0x1p-17f,
                         float(k) + 0x1p-16f, float(k) + 0x3p-17f};
  tess::Levels levels;
  for (int i = 0; i < 4; ++i) levels.outer[i] = above[(k + i) % 4];
  for (int i = 0; i < 2; ++i) levels.inner[i] = above[(k + i + 2) % 4];
  return levels;
}

// Every domain x spacing: kRandomPerCell random level sets, then 1..64 just above.
std::vector<TessPatch> sweepPatches() {
  std::vector<TessPatch> patches;
  for (Domain d : {Domain::kTriangle, Domain::kQuad, Domain::kIsoline}) {
    for (Spacing s : {Spacing::kInteger, Spacing::kPow2, Spacing::kFractionalOdd,
                      Spacing::kFractionalEven}) {
      testing::LevelGenerator generator(kSeed + 16 * uint32_t(d) + uint32_t(s));
      for (int i = 0; i < kRandomPerCell; ++i) patches.push_back({d, s, generator.next()});
      for (int k = 1; k <= 64; ++k) patches.push_back({d, s, justAbove(k)});
    }
  }
  return patches;
}

std::string describe(const TessPatch& patch) {
  std::ostringstream out;
  out.precision(9);
  out << tess::toString(patch.domain) << ' ' << tess::toString(patch.spacing) << " outer {";
  for (float l : patch.levels.outer) out << ' ' << l;
  out << " } inner {";
  for (float l : patch.levels.inner) out << ' ' << l;
  out << " }";
  return out.str();
}

template <class T>
std::optional<size_t> firstDifference(const std::vector<T>& a, const std::vector<T>& b) {
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    if (a[i] != b[i]) return i;
  }
  if (a.size() != b.size()) return std::min(a.size(), b.size());
  return std::nullopt;
}

// The first way cpu and gpu differ; points by their float bits.
std::optional<std::string> difference(const tess::Tessellation& cpu,
                                      const tess::Tessellation& gpu) {
  std::ostringstream out;
  auto bits = [](const tess::Tessellation& t) {
    std::vector<std::array<uint32_t, 3>> b;
    for (const auto& p : t.points) {
      b.push_back({std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
                   std::bit_cast<uint32_t>(p[2])});
    }
    return b;
  };
  if (cpu.culled != gpu.culled) {
    out << "culled: CPU " << cpu.culled << ", compute " << gpu.culled;
  } else if (auto i = firstDifference(bits(cpu), bits(gpu))) {
    out << "point " << *i << " of " << cpu.points.size() << " (CPU) / " << gpu.points.size();
    if (*i < cpu.points.size() && *i < gpu.points.size()) {
      out << ": CPU (" << cpu.points[*i][0] << ", " << cpu.points[*i][1] << "), compute ("
          << gpu.points[*i][0] << ", " << gpu.points[*i][1] << ")";
    }
  } else if (auto t = firstDifference(cpu.triangles, gpu.triangles)) {
    out << "triangle " << *t << " of " << cpu.triangles.size() << " / " << gpu.triangles.size();
  } else if (auto l = firstDifference(cpu.lines, gpu.lines)) {
    out << "line " << *l << " of " << cpu.lines.size() << " / " << gpu.lines.size();
  } else {
    return std::nullopt;
  }
  return out.str();
}

struct Tally {
  std::vector<uint32_t> mismatches_per_cell = std::vector<uint32_t>(12, 0);
  uint64_t points = 0;
  uint32_t total() const {
    uint32_t sum = 0;
    for (uint32_t m : mismatches_per_cell) sum += m;
    return sum;
  }
};

size_t cellOf(const TessPatch& p) { return 4 * size_t(p.domain) + size_t(p.spacing); }

// Compares the batch patch by patch against tess::tessellate of `cpu_levels` (the batch's
// own levels unless a control nudges them); reports the first few when `report`.
Tally compareBatch(const std::vector<TessPatch>& patches, const ComputeTessellation& batch,
                   const tess::Options& options, const std::vector<tess::Levels>& cpu_levels,
                   bool report) {
  Tally tally;
  for (size_t i = 0; i < patches.size(); ++i) {
    const TessPatch& p = patches[i];
    const tess::Tessellation cpu = tess::tessellate(p.domain, p.spacing, cpu_levels[i], options);
    const tess::Tessellation gpu = toTessellation(batch, i, p.domain);
    tally.points += gpu.points.size();
    if (const auto diff = difference(cpu, gpu)) {
      if (report && tally.total() < kMismatchesReported) {
        ADD_FAILURE() << describe(p) << (options.ccw ? " ccw" : " cw")
                      << (options.point_mode ? " point_mode" : "") << ": " << *diff;
      }
      ++tally.mismatches_per_cell[cellOf(p)];
    }
  }
  return tally;
}

std::vector<tess::Levels> levelsOf(const std::vector<TessPatch>& patches) {
  std::vector<tess::Levels> levels;
  for (const TessPatch& p : patches) levels.push_back(p.levels);
  return levels;
}

TEST(ComputeTessellator, EqualsCpuTessellatorBitwiseOnTheSweep) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<TessPatch> patches = sweepPatches();
  for (const auto& [ccw, point_mode] : {std::pair{true, false}, {false, false}, {true, true}}) {
    tess::Options options;
    options.ccw = ccw;
    options.point_mode = point_mode;
    const ComputeTessellation batch = tessellateOnCompute(context, patches, options);
    ASSERT_EQ(batch.patches.size(), patches.size());
    const Tally tally = compareBatch(patches, batch, options, levelsOf(patches), true);
    EXPECT_EQ(tally.total(), 0u) << "of " << patches.size() << " patches";
    for (size_t c = 0; c < 12; ++c) std::printf("cell %zu: %u\n", c, tally.mismatches_per_cell[c]);
    EXPECT_GT(tally.points, 100000u);  // the sweep is not trivially small
  }
}

// The comparison catches a kernel off by a 16.16 rounding, and CPU levels off by one 16.16
// step, on every fractional cell; integer and pow2 round levels up to integers first, where
// truncation and rounding agree, so the kernel control leaves them equal.
TEST(ComputeTessellator, BrokenControlsAreCaught) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<TessPatch> patches = sweepPatches();
  const tess::Options options;
  const ComputeTessellation truncating =
      tessellateOnCompute(context, patches, options, TessKernel::kTruncatingControl);
  const Tally kernel_control = compareBatch(patches, truncating, options, levelsOf(patches), false);

  const ComputeTessellation exact = tessellateOnCompute(context, patches, options);
  std::vector<tess::Levels> nudged = levelsOf(patches);
  for (tess::Levels& l : nudged) l.outer[1] += 0x1p-16f;
  const Tally level_control = compareBatch(patches, exact, options, nudged, false);

  for (size_t cell = 0; cell < 12; ++cell) {
    const bool is_fractional = fractional(Spacing(cell % 4));
    SCOPED_TRACE("cell " + std::string(tess::toString(Domain(cell / 4))) + " x " +
                 std::string(tess::toString(Spacing(cell % 4))));
    if (is_fractional) {
      EXPECT_GT(kernel_control.mismatches_per_cell[cell], 0u);
      EXPECT_GT(level_control.mismatches_per_cell[cell], 0u);
    } else {
      EXPECT_EQ(kernel_control.mismatches_per_cell[cell], 0u);
    }
  }
}

TEST(ComputeTessellator, EmptyBatchAndOffsetsArePrefixSums) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  EXPECT_TRUE(tessellateOnCompute(context, std::vector<TessPatch>{}).patches.empty());
  const std::vector<TessPatch> patches = sweepPatches();
  const ComputeTessellation batch = tessellateOnCompute(context, patches);
  uint32_t point = 0, index = 0;
  for (const TessPatchRange& range : batch.patches) {
    EXPECT_EQ(range.first_point, point);
    EXPECT_EQ(range.first_index, index);
    point += range.point_count;
    index += range.index_count;
  }
  EXPECT_EQ(point, batch.points.size());
  EXPECT_EQ(index, batch.indices.size());
}

}  // namespace
}  // namespace tb::gpu::compute_tessellator_test
namespace tb::gpu::compute_tessellator_test {
TEST(ComputeTessellatorDebug, Single) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  std::vector<TessPatch> all = sweepPatches();
  auto t0 = std::chrono::steady_clock::now();
  ComputeTessellator tess(context, all);
  auto t1 = std::chrono::steady_clock::now();
  tess.run();
  auto t2 = std::chrono::steady_clock::now();
  const ComputeTessellation batch = tess.read();
  auto t3 = std::chrono::steady_clock::now();
  const Tally t = compareBatch(all, batch, {}, levelsOf(all), false);
  auto t4 = std::chrono::steady_clock::now();
  auto s = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("build %.2f run %.2f read %.2f compare %.2f, %u mismatches, %zu points\n", s(t0,t1), s(t1,t2), s(t2,t3), s(t3,t4), t.total(), batch.points.size());
}
}
