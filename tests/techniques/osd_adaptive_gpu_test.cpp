// osd_adaptive's TCS/TES on the Vulkan device (lavapipe): OpenSubdiv Far's feature-adaptive
// patches evaluated per base face in the TES. Oracle: the CPU float twin
// (OsdAdaptivePatches::evaluateFloat, the shader's sub-patch search and operation order) at
// the captured gl_TessCoord bits, on assets with extraordinary vertices, boundaries, corners
// and creases, Gregory basis and B-spline basis end caps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/gpu/patch_program.h"
#include "core/mesh/float_ulp.h"
#include "core/mesh/obj_loader.h"
#include "techniques/osd_adaptive/osd_adaptive.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb::osd_adaptive {
namespace {

struct LevelCase {
  float level;
  tess::Spacing spacing;
};
const LevelCase kLevels[] = {{1.0f, tess::Spacing::kInteger},
                             {7.3f, tess::Spacing::kFractionalOdd},
                             {16.0f, tess::Spacing::kInteger}};

struct VariantCase {
  const char* name;
  int isolation;
  EndCap end_cap;
};
const VariantCase kVariants[] = {{"iso2_gregory", 2, EndCap::kGregoryBasis},
                                 {"iso4_gregory", 4, EndCap::kGregoryBasis},
                                 {"iso2_bspline", 2, EndCap::kBSplineBasis}};

// Extraordinary vertices (cube), boundaries and corners (edgecorner), semi-sharp and
// infinitely sharp creases (cube_creases1, single_crease).
const char* const kAssets[] = {"opensubdiv/catmark_cube.obj", "opensubdiv/catmark_edgecorner.obj",
                               "opensubdiv/catmark_cube_creases1.obj",
                               "opensubdiv/catmark_single_crease.obj"};

TEST(OsdAdaptiveGpu, CaptureEqualsTheCpuFloatTwin) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const OsdAdaptiveTechnique technique;
  for (const VariantCase& vc : kVariants) {
    const techniques::VariantInfo variant{
        vc.name,
        vc.name,
        {{"isolation", double(vc.isolation)}, {"endcap", double(int(vc.end_cap))}}};
    size_t variant_end_cap_vertices = 0;
    for (const char* name : kAssets) {
      const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(name));
      const techniques::BuiltSurface patches = techniques::buildSurface(technique, mesh, variant);
      const std::vector<gpu::GpuPatchProgram> programs = patches->gpuPrograms();
      ASSERT_EQ(programs.size(), 1u);
      ASSERT_EQ(programs[0].patch_count, patches->patchCount());
      const PatchTableCounts counts = patchTableCounts(*patches);
      for (const LevelCase& lc : kLevels) {
        tess::Levels levels;
        levels.outer = {lc.level, lc.level, lc.level, lc.level};
        levels.inner = {lc.level, lc.level};
        gpu::PatchProgramOptions options;
        options.spacing = lc.spacing;
        options.patches_per_draw = 16;
        const gpu::PatchProgramCapture capture =
            gpu::runPatchProgram(context, programs[0], levels, options);
        uint64_t worst = 0;
        double worst_normal = 0;
        size_t end_cap_vertices = 0;
        for (const gpu::CapturedVertex& v : capture.vertices) {
          const techniques::SurfacePointF cpu = patches->evaluateFloat(v.patch, v.coord);
          worst = std::max(worst, mesh::maxUlpDistance(cpu.position, v.position));
          worst_normal = std::max(worst_normal, double(length(cpu.normal - v.normal)));
          end_cap_vertices += !isRegularAt(*patches, v.patch, v.coord[0], v.coord[1]);
        }
        std::printf(
            "[osd_adaptive gpu] %-12s %-38s level %4.1f: %zu vertices (%zu on end "
            "caps; %zu Far patches), max %llu ulp from evaluateFloat, max normal diff "
            "%.1e\n",
            vc.name, name, lc.level, capture.vertices.size(), end_cap_vertices, counts.patches,
            (unsigned long long)worst, worst_normal);
        // Every vertex of every base face: (level + 1)^2 per face at integer levels.
        if (lc.spacing == tess::Spacing::kInteger) {
          const size_t per_face = size_t(lc.level + 1) * size_t(lc.level + 1);
          EXPECT_GE(capture.vertices.size(), per_face * patches->patchCount()) << name;
        } else {
          EXPECT_GT(capture.vertices.size(), 64 * patches->patchCount()) << name;
        }
        // The bound of the acc and gregory_acc GPU tests: the twin follows the shader's
        // operation order; the device may differ in the last bits of a few operations.
        EXPECT_LE(worst, 4u) << vc.name << " " << name << " level " << lc.level;
        EXPECT_LT(worst_normal, 1e-4) << vc.name << " " << name << " level " << lc.level;
        variant_end_cap_vertices += end_cap_vertices;
      }
    }
    // The cube's extraordinary vertices: the end caps (Gregory or B-spline basis) were
    // compared, not only the regular patches.
    EXPECT_GT(variant_end_cap_vertices, 0u) << vc.name;
  }
}

}  // namespace
}  // namespace tb::osd_adaptive
