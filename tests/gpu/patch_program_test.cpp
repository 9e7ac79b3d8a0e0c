// core/gpu/patch_program.h against its oracles: the CPU tessellator for the domain
// points and their count, and the same bilinear formula in float on the CPU.
#include "core/gpu/patch_program.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <set>
#include <tuple>
#include <vector>

#include "core/tess/tessellator.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

GpuPatchProgram bilinearProgram(uint32_t patches, float scale) {
  GpuPatchProgram program;
  program.control_shader = "gpu/test_bilinear.tesc";
  program.evaluation_shader = "gpu/test_bilinear.tese";
  program.domain = tess::Domain::kQuad;
  program.patch_count = patches;
  std::vector<uint32_t> corners;
  for (uint32_t p = 0; p < patches; ++p) {
    const float corner[4][4] = {{float(p), 0, 0, 1},
                                {float(p) + 1, 0, 0, 1},
                                {float(p) + 1, 1, 0.5f, 1},
                                {float(p), 1, 0.25f, 1}};
    for (const auto& c : corner) {
      for (float x : c) corners.push_back(std::bit_cast<uint32_t>(x));
    }
  }
  program.storage_buffers = {corners};
  program.specialization = {std::bit_cast<uint32_t>(scale)};
  return program;
}

TEST(PatchProgram, CapturesEveryDomainPointOfEveryPatchWithTheCpuFormula) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const float scale = 2.0f;
  const GpuPatchProgram program = bilinearProgram(5, scale);
  tess::Levels levels;
  levels.outer = {3, 5.5f, 2, 7};
  levels.inner = {4.25f, 3};
  PatchProgramOptions options;
  options.spacing = tess::Spacing::kFractionalOdd;
  options.patches_per_draw = 2;
  const PatchProgramCapture capture = runPatchProgram(context, program, levels, options);

  const tess::Tessellation cpu =
      tess::tessellate(tess::Domain::kQuad, tess::Spacing::kFractionalOdd, levels);
  ASSERT_EQ(capture.vertices.size(), 5 * cpu.points.size());
  EXPECT_EQ(capture.stats.tcs_patches, 5u);
  EXPECT_EQ(capture.draws, 3u);
  EXPECT_GE(capture.stats.tes_invocations, capture.vertices.size());
  size_t i = 0;
  for (uint32_t p = 0; p < 5; ++p) {
    std::vector<tess::DomainPoint> expected = cpu.points;
    auto bits = [](const tess::DomainPoint& d) {
      return std::make_tuple(std::bit_cast<uint32_t>(d[0]), std::bit_cast<uint32_t>(d[1]),
                             std::bit_cast<uint32_t>(d[2]));
    };
    std::sort(expected.begin(), expected.end(),
              [&](const auto& a, const auto& b) { return bits(a) < bits(b); });
    for (const tess::DomainPoint& d : expected) {
      const CapturedVertex& v = capture.vertices[i++];
      ASSERT_EQ(v.patch, p);
      ASSERT_EQ(bits(v.coord), bits(d));
      const float u = d[0], w = d[1];
      const float x = ((float(p) * (1 - u) + (float(p) + 1) * u) * (1 - w) +
                       ((float(p)) * (1 - u) + (float(p) + 1) * u) * w) *
                      scale;
      const float z =
          ((0.0f * (1 - u) + 0.0f * u) * (1 - w) + (0.25f * (1 - u) + 0.5f * u) * w) * scale;
      EXPECT_EQ(v.position.x, x) << "patch " << p << " at " << u << "," << w;
      EXPECT_EQ(v.position.y, w * scale);
      EXPECT_EQ(v.position.z, z);
    }
  }
}

TEST(PatchProgram, TimingRunCapturesNothingButCountsInvocations) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const GpuPatchProgram program = bilinearProgram(3, 1.0f);
  tess::Levels levels;
  levels.outer = {8, 8, 8, 8};
  levels.inner = {8, 8};
  PatchProgramOptions options;
  options.capture = false;
  const PatchProgramCapture capture = runPatchProgram(context, program, levels, options);
  EXPECT_TRUE(capture.vertices.empty());
  EXPECT_EQ(capture.stats.tes_invocations, 3u * 81u);
}

TEST(PatchProgram, AMissingShaderIsAClearError) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  GpuPatchProgram program = bilinearProgram(1, 1.0f);
  program.evaluation_shader = "nope/missing.tese";
  try {
    runPatchProgram(context, program, tess::Levels{});
    FAIL() << "expected GpuError";
  } catch (const GpuError& error) {
    EXPECT_NE(std::string(error.what()).find("nope/missing.tese"), std::string::npos);
  }
}

// Per-patch levels reach the device: each patch's captured domain points are exactly the
// CPU tessellator's for that patch's own levels (count and coordinate bits), under a
// fractional spacing and under pow2 (which the harness rounds before the device sees it).
TEST(PatchProgram, PerPatchLevelsReachTheDevice) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const GpuPatchProgram program = bilinearProgram(4, 1.0f);
  std::vector<tess::Levels> levels(4);
  levels[0].outer = {1, 2, 3, 4};
  levels[0].inner = {2, 3};
  levels[1].outer = {7.3f, 5.5f, 2.25f, 9};
  levels[1].inner = {6.5f, 3.75f};
  levels[2].outer = {16, 16, 16, 16};
  levels[2].inner = {16, 16};
  levels[3].outer = {3, 11.5f, 1, 5};
  levels[3].inner = {1.5f, 12};
  for (tess::Spacing spacing : {tess::Spacing::kFractionalEven, tess::Spacing::kPow2}) {
    PatchProgramOptions options;
    options.spacing = spacing;
    options.patches_per_draw = 3;
    const PatchProgramCapture capture = runPatchProgram(context, program, levels, options);
    std::vector<std::set<std::tuple<uint32_t, uint32_t, uint32_t>>> captured(4);
    for (const CapturedVertex& v : capture.vertices) {
      ASSERT_LT(v.patch, 4u);
      captured[v.patch].insert({std::bit_cast<uint32_t>(v.coord[0]),
                                std::bit_cast<uint32_t>(v.coord[1]),
                                std::bit_cast<uint32_t>(v.coord[2])});
    }
    for (uint32_t p = 0; p < 4; ++p) {
      const tess::Tessellation cpu = tess::tessellate(tess::Domain::kQuad, spacing, levels[p]);
      std::set<std::tuple<uint32_t, uint32_t, uint32_t>> expected;
      for (const tess::DomainPoint& d : cpu.points) {
        expected.insert({std::bit_cast<uint32_t>(d[0]), std::bit_cast<uint32_t>(d[1]),
                         std::bit_cast<uint32_t>(d[2])});
      }
      EXPECT_EQ(captured[p].size(), cpu.points.size()) << tess::toString(spacing) << " patch " << p;
      EXPECT_EQ(captured[p], expected) << tess::toString(spacing) << " patch " << p;
    }
  }
}

// The uniform overload is the per-patch one with the same levels everywhere.
TEST(PatchProgram, UniformLevelsEqualTheSameLevelsPerPatch) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const GpuPatchProgram program = bilinearProgram(3, 1.5f);
  tess::Levels levels;
  levels.outer = {5.5f, 3, 7.25f, 2};
  levels.inner = {4, 6.5f};
  PatchProgramOptions options;
  options.spacing = tess::Spacing::kFractionalOdd;
  const PatchProgramCapture uniform = runPatchProgram(context, program, levels, options);
  const std::vector<tess::Levels> same(3, levels);
  const PatchProgramCapture per_patch = runPatchProgram(context, program, same, options);
  ASSERT_EQ(uniform.vertices.size(), per_patch.vertices.size());
  EXPECT_EQ(std::memcmp(uniform.vertices.data(), per_patch.vertices.data(),
                        uniform.vertices.size() * sizeof(CapturedVertex)),
            0);
  EXPECT_EQ(uniform.stats.tes_invocations, per_patch.stats.tes_invocations);
}

TEST(PatchProgram, ALevelCountOtherThanThePatchCountIsAClearError) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const GpuPatchProgram program = bilinearProgram(3, 1.0f);
  const std::vector<tess::Levels> two(2);
  EXPECT_THROW(runPatchProgram(context, program, two), GpuError);
}

}  // namespace
}  // namespace tb::gpu
