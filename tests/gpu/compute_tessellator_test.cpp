// The compute tessellator (shaders/gpu/tessellate.comp) against the CPU tessellator
// (core/tess, bit-exact with lavapipe: tess_sweep_test.cpp), bit for bit and in order: the
// same culling, the same points (16.16 (u, v), float w), the same triangles or line segments
// in the same order. Every domain x spacing: random level sets from the lavapipe sweep's
// generator (culling, NaN, the clamps, just above odd integers) and per-edge levels just
// above every integer 1..64 (one float ulp, half a 16.16 step: the rounding tie, one step,
// one and a half), in ccw; fewer random ones in cw and in point mode. Broken controls: a
// kernel that rounds levels up to 16.16 instead of half to even (on the just-above levels),
// and CPU levels nudged by one 16.16 step, must both be caught on the fractional spacings;
// integer spacings round levels to integers first, so the kernel control leaves them equal.
// Everything is
// one batch (one pipeline build, one submission), built once per test binary.
// TB_COMPUTE_TESS_SWEEP=N runs N random level sets per cell in ccw (default 32). Under
// AddressSanitizer half the random sets and every other integer (sweepStride).
#include "core/gpu/compute_tessellator.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/tess/tessellator.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/gpu/tess_level_generator.h"
#include "tests/test_support.h"

namespace tb::gpu::compute_tessellator_test {
namespace {

using tess::Domain;
using tess::Spacing;

constexpr uint32_t kSeed = 0xc0de41;
constexpr int kMismatchesReported = 5;
constexpr size_t kCells = 12;  // domain x spacing

int randomPerCell() {
  const char* value = std::getenv("TB_COMPUTE_TESS_SWEEP");
  const int stride = static_cast<int>(::tb::testing::sweepStride(2));
  return value != nullptr ? std::max(1, std::atoi(value)) : 32 / stride;
}

size_t cellOf(const TessPatch& p) { return 4 * size_t(p.domain) + size_t(p.spacing); }
bool fractional(Spacing s) { return s == Spacing::kFractionalOdd || s == Spacing::kFractionalEven; }

// Level k plus an offset for each of the six levels, cycling through just-above values.
tess::Levels justAbove(int k) {
  const float above[] = {std::nextafter(float(k), 100.0f), float(k) + 0x1p-17f, float(k) + 0x1p-16f,
                         float(k) + 0x3p-17f};
  tess::Levels levels;
  for (int i = 0; i < 4; ++i) levels.outer[i] = above[(k + i) % 4];
  for (int i = 0; i < 2; ++i) levels.inner[i] = above[(k + i + 2) % 4];
  return levels;
}

enum Pass { kCcw, kCw, kPointMode, kControl, kPasses };

// The batch: per cell, ccw random + just above 1..64; cw and point mode with half as many
// random level sets; the rounding-up control on the just-above levels.
struct Sweep {
  std::vector<TessPatch> patches;
  std::vector<Pass> pass;  // per patch
  ComputeTessellation batch;
};

std::vector<TessPatch> sweepPatches(std::vector<Pass>* pass) {
  std::vector<TessPatch> patches;
  const int random = randomPerCell();
  for (Domain d : {Domain::kTriangle, Domain::kQuad, Domain::kIsoline}) {
    for (Spacing s :
         {Spacing::kInteger, Spacing::kPow2, Spacing::kFractionalOdd, Spacing::kFractionalEven}) {
      testing::LevelGenerator generator(kSeed + 16 * uint32_t(d) + uint32_t(s));
      for (int p = kCcw; p < kPasses; ++p) {
        TessPatch patch;
        patch.domain = d;
        patch.spacing = s;
        patch.options.ccw = p != kCw;
        patch.options.point_mode = p == kPointMode;
        patch.rounding_up_control = p == kControl;
        const int count = p == kCcw ? random : (p == kControl ? 0 : std::max(1, random / 2));
        for (int i = 0; i < count; ++i) {
          patch.levels = generator.next();
          patches.push_back(patch);
          pass->push_back(Pass(p));
        }
        const int k_step = static_cast<int>(::tb::testing::sweepStride(2));
        for (int k = 1; (p == kCcw || p == kControl) && k <= 64; k += k_step) {
          patch.levels = justAbove(k);
          patches.push_back(patch);
          pass->push_back(Pass(p));
        }
      }
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

// Mismatching patches per cell of the given pass, against tess::tessellate of the patch's
// levels with `adjust` applied; the first few are reported as failures when `report`.
template <class Adjust>
std::vector<uint32_t> mismatches(const Sweep& s, Pass pass, bool report, Adjust adjust) {
  std::vector<uint32_t> per_cell(kCells, 0);
  int reported = 0;
  for (size_t i = 0; i < s.patches.size(); ++i) {
    if (s.pass[i] != pass) continue;
    const TessPatch& p = s.patches[i];
    tess::Levels levels = p.levels;
    adjust(&levels);
    const tess::Tessellation cpu = tess::tessellate(p.domain, p.spacing, levels, p.options);
    if (const auto diff = difference(cpu, toTessellation(s.batch, i, p.domain))) {
      if (report && reported++ < kMismatchesReported) {
        ADD_FAILURE() << describe(p) << (p.options.ccw ? " ccw" : " cw")
                      << (p.options.point_mode ? " point_mode" : "") << ": " << *diff;
      }
      ++per_cell[cellOf(p)];
    }
  }
  return per_cell;
}

void asIs(tess::Levels*) {}

// The pass's mismatching patches are 0 in every cell.
void expectEqual(const Sweep& s) {
  for (Pass pass : {kCcw, kCw, kPointMode}) {
    const std::vector<uint32_t> per_cell = mismatches(s, pass, true, asIs);
    for (size_t cell = 0; cell < kCells; ++cell) EXPECT_EQ(per_cell[cell], 0u) << "cell " << cell;
  }
  // The sweep is not trivially small (a quarter of it under a sanitizer).
  EXPECT_GT(s.batch.points.size(), 1000000u / ::tb::testing::sweepStride(4));
}

// The comparison catches a kernel off by a 16.16 rounding, and CPU levels off by one 16.16
// step, on every fractional cell. Integer and pow2 round levels up to integers first, where
// both roundings agree, so the kernel control leaves them equal.
void expectControlsCaught(const Sweep& s) {
  const std::vector<uint32_t> kernel_control = mismatches(s, kControl, false, asIs);
  const std::vector<uint32_t> level_control =
      mismatches(s, kCcw, false, [](tess::Levels* l) { l->outer[1] += 0x1p-16f; });
  for (size_t cell = 0; cell < kCells; ++cell) {
    SCOPED_TRACE(std::string(tess::toString(Domain(cell / 4))) + " x " +
                 std::string(tess::toString(Spacing(cell % 4))));
    if (fractional(Spacing(cell % 4))) {
      EXPECT_GT(kernel_control[cell], 0u);
      EXPECT_GT(level_control[cell], 0u);
    } else {
      EXPECT_EQ(kernel_control[cell], 0u);
    }
  }
}

// Offsets are the prefix sums of the counts; every index stays inside its own patch.
void expectContiguous(const ComputeTessellation& batch) {
  uint64_t point = 0, index = 0, outside = 0;
  for (const TessPatchRange& range : batch.patches) {
    EXPECT_EQ(range.first_point, point);
    EXPECT_EQ(range.first_index, index);
    for (uint32_t k = 0; k < range.index_count; ++k) {
      const uint32_t i = batch.indices[range.first_index + k];
      outside += i < range.first_point || i >= range.first_point + range.point_count;
    }
    point += range.point_count;
    index += range.index_count;
  }
  EXPECT_EQ(outside, 0u);
  EXPECT_EQ(point, batch.points.size());
  EXPECT_EQ(index, batch.indices.size());
}

// One test (one process under ctest): the batch's pipelines take most of its time.
TEST(ComputeTessellator, EqualsCpuTessellatorBitwiseAndCatchesBrokenControls) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  Sweep s;
  s.patches = sweepPatches(&s.pass);
  s.batch = tessellateOnCompute(context, s.patches);
  ASSERT_EQ(s.batch.patches.size(), s.patches.size());
  expectEqual(s);
  expectControlsCaught(s);
  expectContiguous(s.batch);
  EXPECT_TRUE(tessellateOnCompute(context, std::vector<TessPatch>{}).patches.empty());
}

}  // namespace
}  // namespace tb::gpu::compute_tessellator_test
