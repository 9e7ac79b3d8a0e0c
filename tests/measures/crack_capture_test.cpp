// The crack measure's boundary tessellations (crack_boundaries.h) and GPU half
// (crack_capture.h). Oracles: the CPU tessellator's own points on the patch boundary; the
// device's capture under the patches' own levels (lowered inner levels must capture the
// same positions bit for bit); lavapipe's TES invocation statistic for the count the
// capture reports without a query.
#include "harness/measures/common/cracks/crack_capture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/gpu/patch_program.h"
#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/crack_boundaries.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using Bits = std::tuple<uint32_t, uint32_t, uint32_t>;

// The tessellator's points on the domain's boundary, as coordinate bits.
std::set<Bits> boundarySet(tess::Domain domain, tess::Spacing spacing, const tess::Levels& levels) {
  std::set<Bits> points;
  for (const tess::DomainPoint& p : tess::tessellate(domain, spacing, levels).points) {
    const bool edge = domain == tess::Domain::kQuad
                          ? p[0] == 0 || p[0] == 1 || p[1] == 0 || p[1] == 1
                          : p[0] == 0 || p[1] == 0 || p[2] == 0;
    if (edge) {
      points.insert({std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
                     std::bit_cast<uint32_t>(p[2])});
    }
  }
  return points;
}

tess::Levels levels(std::array<float, 4> outer, std::array<float, 2> inner) {
  tess::Levels l;
  l.outer = outer;
  l.inner = inner;
  return l;
}

TEST(CrackBoundaries, HoldExactlyTheTessellatorsBoundaryPointsInEdgeOrder) {
  for (techniques::PatchDomain domain :
       {techniques::PatchDomain::kQuad, techniques::PatchDomain::kTriangle}) {
    const tess::Domain d =
        domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle;
    for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                  tess::Spacing::kFractionalEven, tess::Spacing::kPow2}) {
      const tess::Levels l = levels({5.5f, 9, 2.25f, 13}, {7.5f, 3});
      const auto b = measures::boundaryTessellation(domain, spacing, l);
      std::set<Bits> got;
      for (const tess::DomainPoint& p : b->points) {
        got.insert({std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
                    std::bit_cast<uint32_t>(p[2])});
      }
      EXPECT_EQ(got.size(), b->points.size());  // no point twice
      EXPECT_EQ(got, boundarySet(d, spacing, l)) << tess::toString(spacing);
      for (uint32_t e = 0; e + 1 < b->edge_begin.size(); ++e) {
        for (uint32_t k = b->edge_begin[e]; k < b->edge_begin[e + 1]; ++k) {
          EXPECT_EQ(measures::domainEdgeParameter(domain, e, b->points[k]), b->edge_t[k]);
          if (k > b->edge_begin[e]) {
            EXPECT_LT(b->edge_t[k - 1], b->edge_t[k]);
          }
          EXPECT_EQ(b->indexOf(domain, b->points[k]), int64_t(k));
        }
      }
      EXPECT_EQ(measures::boundaryTessellation(domain, spacing, l), b);  // one shared entry
    }
  }
}

TEST(CrackBoundaries, CaptureLevelsKeepTheBoundaryWithFewerInteriorPoints) {
  const tess::Levels l64 = levels({64, 64, 64, 64}, {64, 64});
  const auto quad =
      measures::boundaryTessellation(techniques::PatchDomain::kQuad, tess::Spacing::kInteger, l64);
  EXPECT_EQ(quad->tessellated_points, 65u * 65u);
  EXPECT_EQ(quad->capture_levels.inner[0], 1.0f);
  EXPECT_LT(quad->capture_points * 10, quad->tessellated_points);
  for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                tess::Spacing::kFractionalEven, tess::Spacing::kPow2}) {
    for (techniques::PatchDomain domain :
         {techniques::PatchDomain::kQuad, techniques::PatchDomain::kTriangle}) {
      const tess::Domain d =
          domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle;
      for (const tess::Levels& l : {l64, levels({7.3f, 12, 3, 40}, {20, 33.5f})}) {
        const auto b = measures::boundaryTessellation(domain, spacing, l);
        EXPECT_EQ(boundarySet(d, spacing, b->capture_levels), boundarySet(d, spacing, l))
            << tess::toString(spacing);
        EXPECT_LT(b->capture_points, b->tessellated_points) << tess::toString(spacing);
      }
    }
  }
  // fractional_odd with one inside level below 1 and the other large: the inner ring
  // degenerates onto the edges, and lowering the large one moves those points, so the
  // levels are kept as they are (the case the check exists for).
  const tess::Levels degenerate = levels({21, 50, 51, 67}, {0.49f, 65.7f});
  tess::Levels lowered = degenerate;
  lowered.inner = {0.49f, 3};
  ASSERT_NE(boundarySet(tess::Domain::kQuad, tess::Spacing::kFractionalOdd, lowered),
            boundarySet(tess::Domain::kQuad, tess::Spacing::kFractionalOdd, degenerate));
  const auto kept = measures::boundaryTessellation(techniques::PatchDomain::kQuad,
                                                   tess::Spacing::kFractionalOdd, degenerate);
  EXPECT_EQ(tess::levelsBits(kept->capture_levels), tess::levelsBits(degenerate));
  EXPECT_EQ(kept->capture_points, kept->tessellated_points);
}

techniques::BuiltSurface defaultPatches(const char* technique_id, const char* asset) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  if (technique == nullptr) throw std::runtime_error(std::string("no technique ") + technique_id);
  return techniques::buildSurface(*technique, mesh::loadObjFile(testing::assetPath(asset)),
                                  technique->variants()[0]);
}

// Lowered inner levels capture every boundary point with the positions the patches' own
// levels give, bit for bit, with fewer TES invocations; the invocation count without a
// query equals lavapipe's statistic.
TEST(CrackCapture, LoweredInnerLevelsCaptureTheSamePositions) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  // gregory_acc on the pyramid: a quad and a triangle program.
  for (const auto& [id, asset] : {std::pair{"gregory_acc", "opensubdiv/catmark_pyramid.obj"},
                                  std::pair{"phong", "opensubdiv/loop_icosahedron.obj"}}) {
    const techniques::BuiltSurface patches = defaultPatches(id, asset);
    const std::vector<gpu::GpuPatchProgram> programs = patches->gpuPrograms();
    ASSERT_FALSE(programs.empty());
    for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                  tess::Spacing::kFractionalEven, tess::Spacing::kPow2}) {
      for (float level : {1.0f, 7.3f, 64.0f}) {
        SCOPED_TRACE(std::string(id) + " " + std::string(tess::toString(spacing)) + " level " +
                     std::to_string(level));
        const std::vector<tess::Levels> patch_levels(
            patches->patchCount(), levels({level, level, level, level}, {level, level}));
        const measures::PatchBoundaries boundaries =
            measures::patchBoundaries(*patches, spacing, patch_levels);
        measures::CrackCaptureOptions full_options;
        full_options.lower_inner_levels = false;
        const measures::BoundaryCapture full = measures::captureBoundaryPositions(
            *patches, programs, boundaries, spacing, patch_levels, context, full_options);
        const measures::BoundaryCapture lowered = measures::captureBoundaryPositions(
            *patches, programs, boundaries, spacing, patch_levels, context);
        EXPECT_EQ(full.points_captured, boundaries.size());
        EXPECT_EQ(lowered.points_captured, boundaries.size());
        ASSERT_EQ(lowered.positions.size(), full.positions.size());
        EXPECT_EQ(std::memcmp(lowered.positions.data(), full.positions.data(),
                              full.positions.size() * sizeof(mesh::Vec3f)),
                  0);
        EXPECT_LE(lowered.tes_invocations, full.tes_invocations);
        if (level == 64.0f) {
          EXPECT_LT(lowered.tes_invocations * 5, full.tes_invocations);
        }

        uint64_t statistic = 0;
        for (const gpu::GpuPatchProgram& program : programs) {
          std::vector<tess::Levels> program_levels(program.patch_count);
          for (uint32_t i = 0; i < program.patch_count; ++i) {
            const uint32_t p = program.patch_ids.empty() ? i : program.patch_ids[i];
            program_levels[i] = boundaries.of(p).capture_levels;
          }
          gpu::PatchProgramOptions options;
          options.spacing = spacing;
          options.capture = false;
          statistic +=
              gpu::runPatchProgram(context, program, program_levels, options).stats.tes_invocations;
        }
        EXPECT_EQ(lowered.tes_invocations, statistic);
      }
    }
  }
}

// A bound on the vertices held at once splits the patches into more runPatchProgram calls
// and changes nothing else (oracle: the capture in one call).
TEST(CrackCapture, ChunksOfPatchesCaptureWhatOneCallDoes) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface patches =
      defaultPatches("gregory_acc", "opensubdiv/catmark_pyramid.obj");
  const std::vector<gpu::GpuPatchProgram> programs = patches->gpuPrograms();
  const tess::Spacing spacing = tess::Spacing::kFractionalOdd;
  const std::vector<tess::Levels> patch_levels(patches->patchCount(),
                                               levels({9.5f, 9.5f, 9.5f, 9.5f}, {9.5f, 9.5f}));
  const measures::PatchBoundaries boundaries =
      measures::patchBoundaries(*patches, spacing, patch_levels);
  const measures::BoundaryCapture one = measures::captureBoundaryPositions(
      *patches, programs, boundaries, spacing, patch_levels, context);
  measures::CrackCaptureOptions small;
  small.max_vertices_per_call = 1;  // one patch per call
  const measures::BoundaryCapture chunked = measures::captureBoundaryPositions(
      *patches, programs, boundaries, spacing, patch_levels, context, small);
  EXPECT_EQ(one.calls, uint32_t(programs.size()));
  EXPECT_EQ(chunked.calls, uint32_t(patches->patchCount()));
  EXPECT_EQ(chunked.points_captured, one.points_captured);
  EXPECT_EQ(chunked.tes_invocations, one.tes_invocations);
  ASSERT_EQ(chunked.positions.size(), one.positions.size());
  EXPECT_EQ(std::memcmp(chunked.positions.data(), one.positions.data(),
                        one.positions.size() * sizeof(mesh::Vec3f)),
            0);
}

}  // namespace
}  // namespace tb
