// The CPU tessellator (harness/tess) against the device's fixed-function tessellator,
// bit for bit. Oracle: lavapipe 22.3.6 (Mesa's copy of the D3D11 reference tessellator),
// captured by transform feedback. For every domain x spacing, 2,400 random level sets
// (fixed seed) including the edge cases of the D3D11 rules, in both windings and point mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/gpu/tess_capture.h"
#include "core/tess/tessellator.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/gpu/tess_level_generator.h"
#include "tests/test_support.h"

namespace tb::gpu {
namespace {

using tess::Domain;
using tess::Levels;
using tess::Spacing;
using testing::LevelGenerator;

// Per domain x spacing, each pass with its own random levels.
struct Pass {
  const char* name;
  bool ccw;
  bool point_mode;
  uint32_t combinations;
};
constexpr Pass kPasses[] = {
    {"ccw", true, false, 1000}, {"cw", false, false, 1000}, {"point_mode", true, true, 400}};
constexpr uint32_t kSeed = 0x7e55b0;
constexpr int kMismatchesReported = 5;  // per cell; the count covers all of them

using Bits = std::array<uint32_t, 3>;
using Primitive = std::array<Bits, 3>;  // unused vertices stay zero (lines)

Bits bitsOf(const tess::DomainPoint& p) {
  return {std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
          std::bit_cast<uint32_t>(p[2])};
}

// Distinct coordinates, sorted. Fractional spacing can put two tessellator vertices on the
// same 2^-16 coordinate; the device then runs the TES for each, but the capture cannot
// tell them apart, so coordinates are compared as a set and vertices by their count.
std::vector<Bits> uniquePoints(const tess::Tessellation& t) {
  std::vector<Bits> points;
  for (const auto& p : t.points) points.push_back(bitsOf(p));
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

// Triangles keep their orientation (rotated to start at the smallest vertex); a line's
// two ends are sorted, since only the triangle winding is specified.
std::vector<Primitive> sortedPrimitives(const tess::Tessellation& t) {
  std::vector<Primitive> primitives;
  for (const auto& tri : t.triangles) {
    Primitive p = {bitsOf(t.points[tri[0]]), bitsOf(t.points[tri[1]]), bitsOf(t.points[tri[2]])};
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
    primitives.push_back(p);
  }
  for (const auto& line : t.lines) {
    Primitive p = {bitsOf(t.points[line[0]]), bitsOf(t.points[line[1]]), Bits{}};
    if (p[1] < p[0]) std::swap(p[0], p[1]);
    primitives.push_back(p);
  }
  std::sort(primitives.begin(), primitives.end());
  return primitives;
}

std::string hex(const Bits& b) {
  char text[96];
  std::snprintf(text, sizeof(text),
                "(0x%08" PRIx32 ", 0x%08" PRIx32 ", 0x%08" PRIx32 ") = (%.9g, %.9g, %.9g)", b[0],
                b[1], b[2], std::bit_cast<float>(b[0]), std::bit_cast<float>(b[1]),
                std::bit_cast<float>(b[2]));
  return text;
}

std::string describe(const Levels& levels) {
  std::ostringstream out;
  out.precision(9);
  out << "outer {";
  for (float l : levels.outer)
    out << ' ' << l << " [0x" << std::hex << std::bit_cast<uint32_t>(l) << std::dec << ']';
  out << " } inner {";
  for (float l : levels.inner)
    out << ' ' << l << " [0x" << std::hex << std::bit_cast<uint32_t>(l) << std::dec << ']';
  out << " }";
  return out.str();
}

template <class T>
std::optional<size_t> firstDifference(const std::vector<T>& a, const std::vector<T>& b) {
  const auto [ia, ib] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  if (ia == a.end() && ib == b.end()) return std::nullopt;
  return static_cast<size_t>(ia - a.begin());
}

// First way in which cpu and gpu differ, or nullopt.
std::optional<std::string> compare(const tess::Tessellation& cpu, const GpuTessellation& gpu) {
  std::ostringstream out;
  if (cpu.culled != gpu.culled) {
    out << "culled: CPU " << cpu.culled << ", GPU " << gpu.culled;
    return out.str();
  }
  const auto cpu_points = uniquePoints(cpu), gpu_points = uniquePoints(gpu);
  if (cpu.points.size() != gpu.stats.tes_invocations || cpu_points.size() != gpu_points.size() ||
      cpu.triangles.size() != gpu.triangles.size() || cpu.lines.size() != gpu.lines.size()) {
    out << "counts (vertices = TES invocations, distinct coordinates, triangles, lines): CPU ("
        << cpu.points.size() << ", " << cpu_points.size() << ", " << cpu.triangles.size() << ", "
        << cpu.lines.size() << "), GPU (" << gpu.stats.tes_invocations << ", " << gpu_points.size()
        << ", " << gpu.triangles.size() << ", " << gpu.lines.size() << ")";
    return out.str();
  }
  if (auto i = firstDifference(cpu_points, gpu_points)) {
    out << "sorted point " << *i << ": CPU " << hex(cpu_points[*i]) << ", GPU "
        << hex(gpu_points[*i]);
    return out.str();
  }
  const auto cpu_prims = sortedPrimitives(cpu), gpu_prims = sortedPrimitives(gpu);
  if (auto i = firstDifference(cpu_prims, gpu_prims)) {
    out << "sorted primitive " << *i << ":";
    for (int v = 0; v < 3; ++v) {
      out << "\n    v" << v << " CPU " << hex(cpu_prims[*i][v]) << ", GPU "
          << hex(gpu_prims[*i][v]);
    }
    return out.str();
  }
  return std::nullopt;
}

struct SweepCell {
  Domain domain;
  Spacing spacing;
};

void PrintTo(const SweepCell& cell, std::ostream* out) {
  *out << tess::toString(cell.domain) << " x " << tess::toString(cell.spacing);
}

class TessSweep : public ::testing::TestWithParam<SweepCell> {
 protected:
  static void TearDownTestSuite() {
    if (total_combinations_ > 0) {
      std::printf("tess sweep: %u combinations in %.1f s (CPU %.1f s, GPU %.1f s)\n",
                  total_combinations_, total_cpu_s_ + total_gpu_s_, total_cpu_s_, total_gpu_s_);
    }
  }
  static inline uint32_t total_combinations_ = 0;
  static inline double total_cpu_s_ = 0;
  static inline double total_gpu_s_ = 0;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST_P(TessSweep, CpuMatchesGpuBitwise) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const SweepCell cell = GetParam();
  LevelGenerator generator(kSeed + 16 * static_cast<uint32_t>(cell.domain) +
                           static_cast<uint32_t>(cell.spacing));
  uint32_t combinations = 0, mismatches = 0, culled = 0, coincident = 0;
  uint64_t points = 0;
  double cpu_s = 0, gpu_s = 0, device_s = 0;
  for (const Pass& pass : kPasses) {
    // Under a sanitizer a quarter of each pass (the same code on fewer random levels).
    std::vector<Levels> levels(pass.combinations / ::tb::testing::sweepStride(4));
    for (Levels& l : levels) l = generator.next();
    tess::Options options;
    options.ccw = pass.ccw;
    options.point_mode = pass.point_mode;
    auto start = std::chrono::steady_clock::now();
    const GpuTessellationBatch gpu =
        tessellateOnGpuBatch(context, cell.domain, cell.spacing, levels, options);
    gpu_s += secondsSince(start);
    device_s += gpu.submit_to_fence_s;
    for (size_t i = 0; i < levels.size(); ++i) {
      start = std::chrono::steady_clock::now();
      const tess::Tessellation cpu =
          tess::tessellate(cell.domain, cell.spacing, levels[i], options);
      cpu_s += secondsSince(start);
      const GpuTessellation& g = gpu.patches[i];
      culled += g.culled;
      points += g.points.size();
      coincident += g.stats.tes_invocations != g.points.size();
      if (const auto difference = compare(cpu, g)) {
        if (++mismatches <= kMismatchesReported) {
          ADD_FAILURE() << tess::toString(cell.domain) << " " << tess::toString(cell.spacing) << " "
                        << pass.name << " " << describe(levels[i]) << "\n  " << *difference;
        }
      }
    }
    combinations += uint32_t(levels.size());
  }
  std::printf("%s x %s: %u combinations, %u culled, %u with coincident vertices, %" PRIu64
              " points; CPU %.2f s, GPU %.2f s (submit->fence %.2f s); %u mismatches\n",
              std::string(tess::toString(cell.domain)).c_str(),
              std::string(tess::toString(cell.spacing)).c_str(), combinations, culled, coincident,
              points, cpu_s, gpu_s, device_s, mismatches);
  total_combinations_ += combinations;
  total_cpu_s_ += cpu_s;
  total_gpu_s_ += gpu_s;
  EXPECT_EQ(mismatches, 0u) << "of " << combinations;
}

std::vector<SweepCell> allCells() {
  std::vector<SweepCell> cells;
  for (Domain d : {Domain::kTriangle, Domain::kQuad, Domain::kIsoline}) {
    for (Spacing s :
         {Spacing::kInteger, Spacing::kPow2, Spacing::kFractionalOdd, Spacing::kFractionalEven}) {
      cells.push_back({d, s});
    }
  }
  return cells;
}

std::string cellName(const ::testing::TestParamInfo<SweepCell>& info) {
  static constexpr const char* kDomains[] = {"tri", "quad", "isoline"};
  static constexpr const char* kSpacings[] = {"integer", "pow2", "fractional_odd",
                                              "fractional_even"};
  return std::string(kDomains[static_cast<int>(info.param.domain)]) + "_" +
         kSpacings[static_cast<int>(info.param.spacing)];
}

INSTANTIATE_TEST_SUITE_P(AllDomainsAndSpacings, TessSweep, ::testing::ValuesIn(allCells()),
                         cellName);

}  // namespace
}  // namespace tb::gpu
