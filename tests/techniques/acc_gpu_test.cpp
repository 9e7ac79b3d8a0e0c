// acc's shaders (shaders/acc/) on the Vulkan device against their CPU twin: the
// captured position at each gl_TessCoord equals evaluateFloat there within 4 ulp, and
// with the symmetric orders the points two patches give on a shared edge are bitwise
// equal in the capture (docs/ARCHITECTURE.md §5 rule 1 and 2).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>

#include "core/gpu/patch_program.h"
#include "core/mesh/float_ulp.h"
#include "techniques/acc/acc.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/techniques/acc_test_support.h"

namespace tb::acc {
namespace {

struct LevelCase {
  float level;
  tess::Spacing spacing;
};

TEST(AccGpu, ShadersMatchTheCpuFloatEvaluationAndSymmetricOrdersAreWatertight) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const auto assets = testing::supportedAssets();
  ASSERT_FALSE(assets.empty());
  for (const techniques::VariantInfo& variant : AccTechnique().variants()) {
    // symmetric_imprecise is the counter-example: symmetric as written, but without
    // `precise` the driver may reassociate it, so neither bitwise symmetry nor agreement
    // with the CPU twin is promised; tests/measures/watertight_variants_test.cpp pins
    // what it does.
    if (variant.name == "symmetric_imprecise") continue;
    const bool symmetric = variant.name != "asymmetric";
    uint64_t worst_ulp = 0;
    double worst_normal = 0;
    size_t vertices = 0, shared = 0, differing = 0;
    for (const auto& asset : assets) {
      const auto patches = techniques::buildSurface(AccTechnique(), asset.mesh, variant);
      const auto programs = patches->gpuPrograms();
      ASSERT_EQ(programs.size(), 1u);
      const gpu::GpuPatchProgram* program = &programs.front();
      for (const LevelCase& lc :
           {LevelCase{1, tess::Spacing::kInteger}, LevelCase{7.3f, tess::Spacing::kFractionalOdd},
            LevelCase{16, tess::Spacing::kInteger}}) {
        tess::Levels levels;
        levels.outer = {lc.level, lc.level, lc.level, lc.level};
        levels.inner = {lc.level, lc.level};
        gpu::PatchProgramOptions options;
        options.spacing = lc.spacing;
        options.patches_per_draw = 16;
        const gpu::PatchProgramCapture capture =
            gpu::runPatchProgram(context, *program, levels, options);
        const size_t expected_points =
            tess::tessellate(tess::Domain::kQuad, lc.spacing, levels).points.size();
        ASSERT_EQ(capture.vertices.size(), expected_points * patches->patchCount())
            << asset.name << " " << variant.name;
        std::map<testing::EdgeKey, mesh::Vec3f> seen;
        for (const gpu::CapturedVertex& v : capture.vertices) {
          const techniques::SurfacePointF cpu = patches->evaluateFloat(v.patch, v.coord);
          const uint64_t ulp = mesh::maxUlpDistance(cpu.position, v.position);
          worst_ulp = std::max(worst_ulp, ulp);
          EXPECT_LE(ulp, 4u) << asset.name << " " << variant.name << " patch " << v.patch << " at "
                             << v.coord[0] << "," << v.coord[1];
          worst_normal = std::max(worst_normal, double(length(cpu.normal - v.normal)));
          ++vertices;
          for (const auto& key :
               testing::edgeKeys(patches->patchCorners(v.patch), v.coord[0], v.coord[1])) {
            const auto [it, inserted] = seen.emplace(key, v.position);
            if (inserted) continue;
            ++shared;
            if (!(it->second == v.position)) ++differing;
          }
        }
      }
    }
    std::printf(
        "%-16s GPU: %zu vertices, max %lld ulp from evaluateFloat, max normal diff %.1e; "
        "%zu of %zu shared edge points differ bitwise\n",
        variant.name.c_str(), vertices, (long long)worst_ulp, worst_normal, differing, shared);
    EXPECT_LT(worst_normal, 1e-4) << variant.name;
    EXPECT_GT(shared, 1000u);
    if (symmetric) {
      EXPECT_EQ(differing, 0u) << variant.name;
    }
  }
}

}  // namespace
}  // namespace tb::acc
