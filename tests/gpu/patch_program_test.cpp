// core/gpu/patch_program.h against its oracles: the CPU tessellator for the domain
// points and their count, and the same bilinear formula in float on the CPU.
#include "core/gpu/patch_program.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <set>
#include <thread>
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

// The device's triangle count (VK_EXT_primitives_generated_query, under rasterizer
// discard) equals the CPU tessellator's, under per-patch fractional levels too.
TEST(PatchProgram, PrimitivesGeneratedEqualTheTessellatorsTriangles) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  if (!context.features().primitives_generated_query) {
    GTEST_SKIP() << "the device has no primitives-generated query with rasterizer discard";
  }
  const GpuPatchProgram program = bilinearProgram(4, 1.0f);
  const std::vector<tess::Levels> levels = {{{3.5f, 7, 2.25f, 9}, {5.5f, 4}},
                                            {{1, 1, 1, 1}, {1, 1}},
                                            {{12.75f, 3, 3, 5}, {8.25f, 2.5f}},
                                            {{0, 4, 4, 4}, {4, 4}}};  // culled
  for (tess::Spacing spacing :
       {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd, tess::Spacing::kFractionalEven}) {
    uint64_t triangles = 0, points = 0;
    for (const tess::Levels& l : levels) {
      const tess::Tessellation t = tess::tessellate(tess::Domain::kQuad, spacing, l);
      triangles += t.triangles.size();
      points += t.points.size();
    }
    PatchProgramOptions options;
    options.spacing = spacing;
    options.capture = false;
    const PatchProgramCapture capture = runPatchProgram(context, program, levels, options);
    EXPECT_TRUE(capture.stats.primitives_counted);
    EXPECT_EQ(capture.stats.primitives_generated, triangles) << tess::toString(spacing);
    EXPECT_EQ(capture.stats.tes_invocations, points) << tess::toString(spacing);
  }
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

// Boundary-only capture keeps exactly the captured vertices whose gl_TessCoord lies on
// the patch's edges. Oracles: the CPU tessellator's boundary points (coordinate bits) and
// the full capture (same positions bit for bit). The quad test TES runs in both domains
// (withTessModes rewrites the domain; the formula reads gl_TessCoord.xy).
TEST(PatchProgram, BoundaryOnlyCaptureKeepsExactlyTheEdgePoints) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (tess::Domain domain : {tess::Domain::kQuad, tess::Domain::kTriangle}) {
    GpuPatchProgram program = bilinearProgram(3, 1.0f);
    program.domain = domain;
    std::vector<tess::Levels> levels(3);
    levels[0].outer = {3, 5.5f, 2, 7};
    levels[0].inner = {4.25f, 3};
    levels[1].outer = {9, 1, 6.5f, 4};
    levels[1].inner = {2, 8};
    levels[2].outer = {16, 16, 16, 16};
    levels[2].inner = {16, 16};
    PatchProgramOptions options;
    options.spacing = tess::Spacing::kFractionalOdd;
    options.patches_per_draw = 2;
    const PatchProgramCapture every = runPatchProgram(context, program, levels, options);
    options.boundary_only = true;
    const PatchProgramCapture boundary = runPatchProgram(context, program, levels, options);
    EXPECT_EQ(boundary.stats.tes_invocations, every.stats.tes_invocations);

    std::vector<CapturedVertex> expected;
    for (const CapturedVertex& v : every.vertices) {
      const bool on_edge =
          domain == tess::Domain::kQuad
              ? v.coord[0] == 0 || v.coord[0] == 1 || v.coord[1] == 0 || v.coord[1] == 1
              : v.coord[0] == 0 || v.coord[1] == 0 || v.coord[2] == 0;
      if (on_edge) expected.push_back(v);
    }
    ASSERT_EQ(boundary.vertices.size(), expected.size()) << tess::toString(domain);
    EXPECT_EQ(std::memcmp(boundary.vertices.data(), expected.data(),
                          expected.size() * sizeof(CapturedVertex)),
              0);
    for (uint32_t p = 0; p < 3; ++p) {
      const tess::Tessellation cpu =
          tess::tessellate(domain, tess::Spacing::kFractionalOdd, levels[p]);
      size_t on_edge = 0;
      for (const tess::DomainPoint& d : cpu.points) {
        const bool edge = domain == tess::Domain::kQuad
                              ? d[0] == 0 || d[0] == 1 || d[1] == 0 || d[1] == 1
                              : d[0] == 0 || d[1] == 0 || d[2] == 0;
        on_edge += edge ? 1 : 0;
      }
      const size_t captured =
          size_t(std::count_if(boundary.vertices.begin(), boundary.vertices.end(),
                               [&](const CapturedVertex& v) { return v.patch == p; }));
      EXPECT_EQ(captured, on_edge) << tess::toString(domain) << " patch " << p;
      EXPECT_GT(cpu.points.size(), on_edge);  // the interior is there and left out
    }
  }
}

// Two threads running programs on one Context at once get what one thread gets running
// them in turn (oracle: the serial captures, bit for bit, and their statistics).
TEST(PatchProgram, ConcurrentCallsOnOneContextMatchSerialCalls) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  struct Job {
    GpuPatchProgram program;
    tess::Levels levels;
    PatchProgramOptions options;
  };
  std::vector<Job> jobs;
  for (uint32_t j = 0; j < 4; ++j) {
    Job job{bilinearProgram(6 + j, 1.0f + float(j)), {}, {}};
    const float level = 3.5f + 4.0f * float(j);
    job.levels.outer = {level, level + 1, level, level + 2};
    job.levels.inner = {level, level + 0.5f};
    job.options.spacing = j % 2 ? tess::Spacing::kFractionalEven : tess::Spacing::kInteger;
    job.options.patches_per_draw = 1 + j;
    job.options.boundary_only = j == 3;
    jobs.push_back(job);
  }
  // Thread 0 runs the jobs in order, thread 1 in reverse, so they overlap in every mix
  // (pipeline creation included: the concurrent runs come first).
  constexpr int kRepeats = 5;
  auto job_of = [&](int thread, size_t k) {
    const size_t j = k % jobs.size();
    return thread == 0 ? j : jobs.size() - 1 - j;
  };
  std::vector<std::vector<PatchProgramCapture>> concurrent(2);
  auto work = [&](int thread) {
    for (size_t k = 0; k < kRepeats * jobs.size(); ++k) {
      const Job& job = jobs[job_of(thread, k)];
      concurrent[thread].push_back(runPatchProgram(context, job.program, job.levels, job.options));
    }
  };
  std::thread a(work, 0), b(work, 1);
  a.join();
  b.join();
  std::vector<PatchProgramCapture> serial;
  for (const Job& job : jobs) {
    serial.push_back(runPatchProgram(context, job.program, job.levels, job.options));
  }
  for (int thread = 0; thread < 2; ++thread) {
    for (size_t k = 0; k < kRepeats * jobs.size(); ++k) {
      const size_t j = job_of(thread, k);
      const PatchProgramCapture& got = concurrent[thread][k];
      SCOPED_TRACE("thread " + std::to_string(thread) + " job " + std::to_string(j));
      ASSERT_EQ(got.vertices.size(), serial[j].vertices.size());
      EXPECT_EQ(std::memcmp(got.vertices.data(), serial[j].vertices.data(),
                            got.vertices.size() * sizeof(CapturedVertex)),
                0);
      EXPECT_EQ(got.stats.tes_invocations, serial[j].stats.tes_invocations);
      EXPECT_EQ(got.stats.tcs_patches, serial[j].stats.tcs_patches);
      EXPECT_EQ(got.draws, serial[j].draws);
    }
  }
}

}  // namespace
}  // namespace tb::gpu
