// gregory_acc's TCS/TES on the Vulkan device (lavapipe). Oracles: the CPU float
// evaluation (GregoryPatches::evaluateFloat, the shader's operation order) at the same
// gl_TessCoord bits, and the neighbouring patch's capture across every shared edge.
#include <gtest/gtest.h>

#include <bit>
#include <cstdlib>
#include <map>
#include <tuple>

#include "core/gpu/patch_program.h"
#include "core/mesh/float_ulp.h"
#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "techniques/gregory_acc/gregory_acc.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/techniques/gregory_acc_test_support.h"
#include "tests/test_support.h"

namespace tb::gregory_acc {
namespace {

const std::vector<std::string>& supported() {
  static const std::vector<std::string> kAssets = testing::supportedBundledAssets();
  return kAssets;
}

struct Case {
  float level;
  tess::Spacing spacing;
};
const Case kCases[] = {{1.0f, tess::Spacing::kInteger},
                       {7.3f, tess::Spacing::kFractionalOdd},
                       {16.0f, tess::Spacing::kInteger}};

// Every program (quads, triangles) of the patches, captures merged.
gpu::PatchProgramCapture run(gpu::Context& context, const techniques::SurfacePatches& patches,
                             const Case& c) {
  tess::Levels levels;
  levels.outer = {c.level, c.level, c.level, c.level};
  levels.inner = {c.level, c.level};
  gpu::PatchProgramOptions options;
  options.spacing = c.spacing;
  options.patches_per_draw = 8;
  gpu::PatchProgramCapture all;
  for (const gpu::GpuPatchProgram& program : patches.gpuPrograms()) {
    const gpu::PatchProgramCapture one = gpu::runPatchProgram(context, program, levels, options);
    all.vertices.insert(all.vertices.end(), one.vertices.begin(), one.vertices.end());
  }
  return all;
}

techniques::BuiltSurface build(const mesh::Mesh& mesh, const std::string& variant) {
  GregoryAccTechnique technique;
  for (const techniques::VariantInfo& info : technique.variants()) {
    if (info.name == variant) return techniques::buildSurface(technique, mesh, info);
  }
  return nullptr;
}

TEST(GregoryAccGpu, CapturedPositionsEqualTheCpuFloatEvaluationWithin4Ulp) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const char* variant : {"edge_symmetric", "asymmetric", "exact_tangents"}) {
    for (const std::string& name : supported()) {
      const mesh::Mesh mesh = mesh::loadObjFile(tb::testing::assetPath(name));
      const auto patches = build(mesh, variant);
      for (const Case& c : kCases) {
        const gpu::PatchProgramCapture capture = run(context, *patches, c);
        ASSERT_FALSE(capture.vertices.empty());
        uint64_t worst = 0;
        double worst_normal = 0;
        for (const gpu::CapturedVertex& vertex : capture.vertices) {
          const techniques::SurfacePointF expected =
              patches->evaluateFloat(vertex.patch, vertex.coord);
          for (int k = 0; k < 3; ++k) {
            worst = std::max(worst, mesh::ulpDistance(vertex.position[k], expected.position[k]));
          }
          worst_normal = std::max(worst_normal, length(vecCast<double>(vertex.normal) -
                                                       vecCast<double>(expected.normal)));
        }
        RecordProperty(
            std::string(variant) + "_" + name + "_" + std::to_string(c.level) + "_ulp_vertices",
            std::to_string(worst) + "_" + std::to_string(capture.vertices.size()));
        EXPECT_LE(worst, 4u) << variant << " " << name << " level " << c.level;
        EXPECT_LE(worst_normal, 1e-5) << variant << " " << name << " level " << c.level;
      }
    }
  }
}

TEST(GregoryAccGpu, SharedEdgePointsAreBitwiseEqualInTheCapture) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const std::string& name : supported()) {
    const mesh::Mesh mesh = mesh::loadObjFile(tb::testing::assetPath(name));
    const auto patches = build(mesh, "edge_symmetric");
    const Case c = kCases[1];
    const gpu::PatchProgramCapture capture = run(context, *patches, c);
    // Boundary points keyed by (patch, local edge, edge parameter in 16.16): the crack
    // measure's pairing rule, so quad and triangle sides meet.
    using Key = std::tuple<uint32_t, uint32_t, int64_t>;
    std::map<Key, mesh::Vec3f> by_edge;
    for (const gpu::CapturedVertex& v : capture.vertices) {
      const techniques::PatchDomain domain = patches->patchDomain(v.patch);
      for (int corner = 0; corner < testing::cornerCount(domain); ++corner) {
        const int64_t t = measures::domainEdgeParameter(domain, uint32_t(corner), v.coord);
        if (t >= 0) by_edge[{v.patch, uint32_t(corner), t}] = v.position;
      }
    }
    const std::vector<testing::EdgeTwin> twins = testing::edgeTwins(patches->controlMesh());
    size_t compared = 0;
    for (const auto& [key, position] : by_edge) {
      const auto [patch, corner, t] = key;
      const testing::EdgeTwin twin = twins[patch * 4 + corner];
      if (twin.face < 0) continue;
      const auto it = by_edge.find({uint32_t(twin.face), uint32_t(twin.corner), 65536 - t});
      ASSERT_NE(it, by_edge.end()) << name << " patch " << twin.face << " edge " << twin.corner
                                   << " lacks t " << double(65536 - t) / 65536;
      ++compared;
      EXPECT_TRUE(it->second == position)
          << name << " patches " << patch << "/" << twin.face << " t " << double(t) / 65536;
    }
    EXPECT_GT(compared, 8 * patches->patchCount()) << name;
  }
}

}  // namespace
}  // namespace tb::gregory_acc
