// The measures on the compute path (core/gpu/compute_path.h). Oracles: the compute path's own
// counts (runComputePath) for memory's transient buffers, and the tessellator path's crack
// figures (the TES capture) for the compute path's: the same surface functions at the same
// points give the same pairs.
#include <gtest/gtest.h>

#include <string>

#include "core/gpu/compute_path.h"
#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/measures/memory/memory.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/measures/bundled_surfaces.h"
#include "tests/test_support.h"

namespace tb {
namespace {

techniques::BuiltSurface surfaceOf(const std::string& id, const std::string& variant,
                                   const std::string& asset) {
  const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
  if (technique == nullptr) throw std::runtime_error("no technique " + id);
  return techniques::buildSurface(*technique, mesh::loadObjFile(testing::assetPath(asset)),
                                  testing::variantNamed(*technique, variant));
}

TEST(ComputePathMeasures, TransientBytesAreTheComputePathsOwnCounts) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const char* id : {"acc", "phong"}) {
    const techniques::BuiltSurface patches =
        surfaceOf(id, id == std::string("acc") ? "default" : "alpha0.75",
                  "opensubdiv/catmark_xord_interior.obj");
    const uint32_t level = 8;
    const measures::TransientFigures t = measures::computePathTransient(*patches, level);
    uint64_t points = 0, index_words = 0;
    for (const gpu::GpuPatchProgram& program : patches->gpuPrograms()) {
      gpu::ComputePathOptions options;
      options.draw = false;
      const float l = float(level);
      const gpu::ComputePathResult run =
          gpu::runComputePath(context, program, tess::Levels{{l, l, l, l}, {l, l}}, options);
      points += run.points;
      index_words += run.index_words;
    }
    EXPECT_EQ(t.points, points) << id;
    EXPECT_EQ(t.index_words, index_words) << id;
    EXPECT_EQ(t.bytes(), points * 40 + index_words * 4) << id;
    // Control: the plain mesh's welded vertex count is not what the compute path writes.
    EXPECT_LT(measures::measureMemory(*patches, level).plain_vertices, points) << id;
  }
}

TEST(ComputePathMeasures, CracksOnTheComputePathEqualTheTessellatorPaths) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  struct PathCase {
    const char* technique;
    const char* variant;
    bool cracks;  // the variant cracks on this asset (a control of the figures' equality)
  };
  for (const PathCase& c :
       {PathCase{"gregory_acc", "asymmetric", true}, PathCase{"pn_triangles", "pn", false}}) {
    const techniques::BuiltSurface patches =
        surfaceOf(c.technique, c.variant, "opensubdiv/loop_xord_interior.obj");
    measures::CrackSession session(*patches);
    for (float level : {7.3f, 16.0f}) {
      const tess::Spacing spacing = tess::Spacing::kFractionalOdd;
      const measures::CrackFigures tes =
          session.measure(spacing, level, measures::CrackBackend::kGpu, &context);
      const measures::CrackFigures compute =
          session.measure(spacing, level, measures::CrackBackend::kGpuCompute, &context);
      ASSERT_TRUE(tes.measured && compute.measured) << compute.skipped_reason;
      EXPECT_EQ(compute.points_compared, tes.points_compared) << c.technique << " " << level;
      EXPECT_EQ(compute.points_not_equal, tes.points_not_equal) << c.technique << " " << level;
      EXPECT_EQ(compute.max_gap_world, tes.max_gap_world) << c.technique << " " << level;
      EXPECT_EQ(compute.device_points_differing, 0u) << c.technique << " " << level;
      EXPECT_EQ(compute.points_not_equal > 0, c.cracks) << c.technique << " " << level;
    }
  }
}

}  // namespace
}  // namespace tb
