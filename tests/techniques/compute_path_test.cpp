// The compute path (core/gpu/compute_path.h) against the hardware path: for every surface
// technique and its non-control variants on a bundled asset it accepts, the vertices the
// compute shaders evaluate are bitwise the TES capture's (runPatchProgram: same patch,
// gl_TessCoord bits, position bits, normal bits) at the same levels, uniform, per edge and
// per patch; the indirect draw draws exactly the CPU tessellator's triangles. Controls: an
// evaluation at a coordinate one ulp off, or in another operation order, is caught as
// unequal.
#include "core/gpu/compute_path.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/gpu/gpu_error.h"
#include "core/mesh/obj_loader.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb::gpu::compute_path_test {
namespace {

// One technique and the bundled asset its programs run on (small: the hardware path's
// lavapipe tessellator costs most of the test's time).
struct TechniqueAsset {
  const char* technique;
  const char* asset;
};
constexpr TechniqueAsset kTechniqueAssets[] = {
    {"acc", "opensubdiv/catmark_cube_creases1.obj"},
    {"gregory_acc", "opensubdiv/catmark_pyramid.obj"},  // quad and triangle programs
    {"osd_adaptive", "opensubdiv/catmark_cube.obj"},
    {"pn_triangles", "tessbench/cylinder_seam.obj"},
    {"phong", "tessbench/cylinder_seam.obj"},
};

// A second asset per technique, run with the default variant at a few levels: boundaries
// and boundary corners (acc), a triangle-only mesh (gregory_acc's triangle program),
// other valences (osd_adaptive, pn_triangles, phong).
constexpr TechniqueAsset kSecondAssets[] = {
    {"acc", "opensubdiv/catmark_edgecorner.obj"},
    {"gregory_acc", "tessbench/tri_torus.obj"},
    {"osd_adaptive", "opensubdiv/catmark_torus.obj"},
    {"pn_triangles", "opensubdiv/loop_icosahedron.obj"},
    {"phong", "tessbench/tri_torus.obj"},
};

// A level case: every patch the same levels, or (per_patch) patch p's outer levels shifted
// by p so neighbours differ.
struct LevelCase {
  const char* name;
  tess::Spacing spacing;
  tess::Levels levels;
  bool per_patch = false;
};

tess::Levels uniform(float level) { return {{level, level, level, level}, {level, level}}; }

// The full sweep for a technique's default variant; the other variants take every third.
std::vector<LevelCase> levelCases() {
  const float above_three = std::nextafter(3.0f, 4.0f);
  std::vector<LevelCase> cases = {
      {"1", tess::Spacing::kInteger, uniform(1)},
      {"2", tess::Spacing::kInteger, uniform(2)},
      {"3", tess::Spacing::kInteger, uniform(3)},
      {"7", tess::Spacing::kInteger, uniform(7)},
      {"16", tess::Spacing::kInteger, uniform(16)},
      {"64", tess::Spacing::kInteger, uniform(64)},
      {"odd 3+ulp", tess::Spacing::kFractionalOdd, uniform(above_three)},
      {"odd 7.3", tess::Spacing::kFractionalOdd, uniform(7.3f)},
      {"even 4.5", tess::Spacing::kFractionalEven, uniform(4.5f)},
      {"pow2 5", tess::Spacing::kPow2, uniform(5)},
      {"edges 2 5 3 7 / 4 6", tess::Spacing::kInteger, {{2, 5, 3, 7}, {4, 6}}},
      {"per patch", tess::Spacing::kInteger, {{1, 4, 2, 6}, {3, 5}}, true},
  };
  return cases;
}

std::vector<tess::Levels> patchLevels(const LevelCase& c, uint32_t patch_count) {
  std::vector<tess::Levels> levels(patch_count, c.levels);
  if (!c.per_patch) return levels;
  for (uint32_t p = 0; p < patch_count; ++p) {
    for (int e = 0; e < 4; ++e) levels[p].outer[e] = float(1 + (p + uint32_t(e) * 3) % 9);
  }
  return levels;
}

// Vertices that differ from the hardware path's (patch, coordinate, position or normal
// bits), counting a size mismatch's surplus as unequal.
size_t unequalVertices(const std::vector<CapturedVertex>& hardware,
                       const std::vector<CapturedVertex>& compute) {
  auto bits = [](const mesh::Vec3f& v) {
    return std::array<uint32_t, 3>{std::bit_cast<uint32_t>(v.x), std::bit_cast<uint32_t>(v.y),
                                   std::bit_cast<uint32_t>(v.z)};
  };
  const size_t n = std::min(hardware.size(), compute.size());
  size_t unequal = std::max(hardware.size(), compute.size()) - n;
  for (size_t i = 0; i < n; ++i) {
    const CapturedVertex& a = hardware[i];
    const CapturedVertex& b = compute[i];
    const bool same = a.patch == b.patch &&
                      std::bit_cast<std::array<uint32_t, 3>>(a.coord) ==
                          std::bit_cast<std::array<uint32_t, 3>>(b.coord) &&
                      bits(a.position) == bits(b.position) && bits(a.normal) == bits(b.normal);
    if (!same) ++unequal;
  }
  return unequal;
}

uint64_t cpuTriangles(const GpuPatchProgram& program, tess::Spacing spacing,
                      const std::vector<tess::Levels>& levels) {
  uint64_t triangles = 0;
  for (const tess::Levels& l : levels) {
    triangles += tess::tessellate(program.domain, spacing, l).triangles.size();
  }
  return triangles;
}

struct Tally {
  size_t cases = 0;     // technique x variant x asset x program x level runs compared
  size_t vertices = 0;  // vertices compared
};

// One program at one level case: compute path == hardware path bit for bit, and the draw
// drew the CPU tessellator's triangles.
// The hardware path's capture, in few draws and without the statistics query.
PatchProgramCapture hardwareCapture(Context& context, const GpuPatchProgram& program,
                                    tess::Spacing spacing,
                                    const std::vector<tess::Levels>& levels) {
  PatchProgramOptions options;
  options.spacing = spacing;
  options.patches_per_draw = 64;
  options.statistics = false;
  return runPatchProgram(context, program, levels, options);
}

void expectBitwiseAt(Context& context, const GpuPatchProgram& program, tess::Spacing spacing,
                     const std::vector<tess::Levels>& levels, const std::string& label,
                     Tally* tally) {
  const PatchProgramCapture hardware = hardwareCapture(context, program, spacing, levels);
  ComputePathOptions options;
  options.spacing = spacing;
  const ComputePathResult compute = runComputePath(context, program, levels, options);
  EXPECT_EQ(compute.vertices.size(), hardware.vertices.size()) << label;
  EXPECT_EQ(unequalVertices(hardware.vertices, compute.vertices), 0u) << label;
  const uint64_t triangles = cpuTriangles(program, spacing, levels);
  EXPECT_EQ(compute.index_words, 3 * triangles) << label;
  EXPECT_EQ(compute.draw_counted, context.features().pipeline_statistics_query) << label;
  if (compute.draw_counted) {
    EXPECT_EQ(compute.drawn_triangles, triangles) << label;
  }
  EXPECT_GE(compute.vertex_buffer_bytes, 40 * compute.points) << label;
  ++tally->cases;
  tally->vertices += compute.vertices.size();
}

void expectBitwise(Context& context, const GpuPatchProgram& program, const LevelCase& c,
                   const std::string& label, Tally* tally) {
  expectBitwiseAt(context, program, c.spacing, patchLevels(c, program.patch_count), label, tally);
}

// The same, 256 patches at a time (the others culled on both paths): the compute path does not
// split a batch its buffers' bound puts over the device's storage buffer range.
void expectBitwiseChunked(Context& context, const GpuPatchProgram& program, const LevelCase& c,
                          const std::string& label, Tally* tally) {
  constexpr uint32_t kChunk = 256;
  const std::vector<tess::Levels> all = patchLevels(c, program.patch_count);
  for (uint32_t first = 0; first < program.patch_count; first += kChunk) {
    std::vector<tess::Levels> levels(all.size(), tess::Levels{{0, 0, 0, 0}, {0, 0}});
    const uint32_t end = std::min(program.patch_count, first + kChunk);
    std::copy(all.begin() + first, all.begin() + end, levels.begin() + first);
    expectBitwiseAt(context, program, c.spacing, levels, label, tally);
  }
}

// acc's default variant on the first asset of kTechniqueAssets: its one GPU program.
GpuPatchProgram accDefaultProgram() {
  const techniques::Technique* acc = techniques::TechniqueRegistry::instance().find("acc");
  const mesh::Mesh mesh = mesh::loadObjFile(::tb::testing::assetPath(kTechniqueAssets[0].asset));
  return techniques::buildSurface(*acc, mesh, acc->variants()[0])->gpuPrograms()[0];
}

TEST(ComputePath, EveryTechniqueVariantIsBitwiseTheTesCapture) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<LevelCase> cases = levelCases();
  Tally tally;
  for (const TechniqueAsset& ta : kTechniqueAssets) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(ta.technique);
    ASSERT_NE(technique, nullptr) << ta.technique;
    const mesh::Mesh mesh = mesh::loadObjFile(::tb::testing::assetPath(ta.asset));
    const std::vector<techniques::VariantInfo> variants = technique->variants();
    const size_t cases_before = tally.cases;
    size_t variants_run = 0;
    for (size_t v = 0; v < variants.size(); ++v) {
      if (!variants[v].control.empty()) continue;
      const auto surface = techniques::buildSurface(*technique, mesh, variants[v]);
      ++variants_run;
      // The default variant (first) takes every level case; the others every third, and
      // under a sanitizer fewer still.
      const size_t stride = (v == 0 ? 1 : 3) * ::tb::testing::sweepStride(4);
      for (const GpuPatchProgram& program : surface->gpuPrograms()) {
        for (size_t k = v % stride; k < cases.size(); k += stride) {
          const std::string label = std::string(ta.technique) + "/" + variants[v].name + " " +
                                    ta.asset + " " + program.evaluation_shader + " level " +
                                    cases[k].name;
          expectBitwise(context, program, cases[k], label, &tally);
        }
      }
    }
    std::printf("[compute path] %s on %s: %zu variants, %zu program x level cases\n", ta.technique,
                ta.asset, variants_run, tally.cases - cases_before);
  }
  std::printf(
      "[compute path] %zu technique x variant x program x level cases, %zu vertices, "
      "compared bit for bit\n",
      tally.cases, tally.vertices);
  EXPECT_GT(tally.cases, 0u);
}

TEST(ComputePath, SecondAssetsDefaultVariantIsBitwiseTheTesCapture) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<LevelCase> all = levelCases();
  const std::vector<LevelCase> cases = {all[2], all[7], all[10]};  // 3, odd 7.3, edges
  Tally tally;
  for (const TechniqueAsset& ta : kSecondAssets) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(ta.technique);
    const mesh::Mesh mesh = mesh::loadObjFile(::tb::testing::assetPath(ta.asset));
    ASSERT_EQ(technique->checkSupport(mesh), "") << ta.technique << " " << ta.asset;
    const auto surface = techniques::buildSurface(*technique, mesh, technique->variants()[0]);
    for (const GpuPatchProgram& program : surface->gpuPrograms()) {
      for (size_t k = 0; k < cases.size(); k += ::tb::testing::sweepStride(2)) {
        const std::string label = std::string(ta.technique) + " " + ta.asset + " " +
                                  program.evaluation_shader + " level " + cases[k].name;
        expectBitwise(context, program, cases[k], label, &tally);
      }
    }
  }
  std::printf("[compute path] second assets: %zu cases, %zu vertices, compared bit for bit\n",
              tally.cases, tally.vertices);
}

// The whole of acceptance 2, on request (TB_COMPUTE_PATH_EVERY_ASSET=1; about 10 minutes on
// two cores, so not in CI): every surface technique's non-control variants on every bundled
// asset they accept, the default variant at every level case, the others at every third.
TEST(ComputePath, EveryBundledAssetWhenAsked) {
  if (std::getenv("TB_COMPUTE_PATH_EVERY_ASSET") == nullptr) {
    GTEST_SKIP() << "set TB_COMPUTE_PATH_EVERY_ASSET=1 to sweep every bundled asset";
  }
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<LevelCase> cases = levelCases();
  Tally tally;
  size_t records = 0;
  for (const char* id : {"acc", "gregory_acc", "osd_adaptive", "pn_triangles", "phong"}) {
    const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
    ASSERT_NE(technique, nullptr) << id;
    const std::vector<techniques::VariantInfo> variants = technique->variants();
    for (const std::string& asset : ::tb::testing::bundledObjs()) {
      const mesh::Mesh mesh = mesh::loadObjFile(::tb::testing::assetPath(asset));
      if (!technique->checkSupport(mesh).empty()) continue;
      for (size_t v = 0; v < variants.size(); ++v) {
        if (!variants[v].control.empty()) continue;
        techniques::BuiltSurface surface;
        try {
          surface = techniques::buildSurface(*technique, mesh, variants[v]);
        } catch (const techniques::UnsupportedInput&) {
          continue;
        }
        ++records;
        const size_t stride = v == 0 ? 1 : 3;
        for (const GpuPatchProgram& program : surface->gpuPrograms()) {
          for (size_t k = v % stride; k < cases.size(); k += stride) {
            expectBitwiseChunked(context, program, cases[k],
                                 std::string(id) + "/" + variants[v].name + " " + asset + " " +
                                     program.evaluation_shader + " level " + cases[k].name,
                                 &tally);
          }
        }
      }
    }
  }
  std::printf(
      "[compute path] every bundled asset: %zu technique x variant x asset records, "
      "%zu program x level cases, %zu vertices, compared bit for bit\n",
      records, tally.cases, tally.vertices);
}

TEST(ComputePath, BezierPositionTwinIsAccTesPosition) {
  // bezier_position.comp (the counting probe's compute twin) emits acc's position alone: it
  // is acc.tese's captured position bit for bit (two Bézier orders; every pipeline costs
  // lavapipe a compile, and the main sweep runs the others through acc.comp).
  TB_GPU_CONTEXT_OR_SKIP(context);
  GpuPatchProgram program = accDefaultProgram();
  const std::vector<tess::Levels> levels(program.patch_count, uniform(5));
  for (uint32_t order : {2u, 1u}) {  // symmetric with and without FMA (bezier.glsl)
    program.specialization.at(0) = order;
    const PatchProgramCapture hardware =
        hardwareCapture(context, program, tess::Spacing::kInteger, levels);
    GpuPatchProgram probe = program;
    probe.compute_shader = "acc/bezier_position.comp";
    ComputePathResult compute = runComputePath(context, probe, levels);
    ASSERT_EQ(compute.vertices.size(), hardware.vertices.size()) << "order " << order;
    for (size_t i = 0; i < compute.vertices.size(); ++i) {
      compute.vertices[i].normal = hardware.vertices[i].normal;  // the probe has none
    }
    EXPECT_EQ(unequalVertices(hardware.vertices, compute.vertices), 0u) << "order " << order;
  }
}

TEST(ComputePath, ControlAnUlpOffCoordinateIsCaught) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const TechniqueAsset& ta : kTechniqueAssets) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(ta.technique);
    const auto surface =
        techniques::buildSurface(*technique, mesh::loadObjFile(::tb::testing::assetPath(ta.asset)),
                                 technique->variants()[0]);
    const GpuPatchProgram program = surface->gpuPrograms()[0];
    const std::vector<tess::Levels> levels(program.patch_count, uniform(7));
    const PatchProgramCapture hardware =
        hardwareCapture(context, program, tess::Spacing::kInteger, levels);
    ComputePathOptions control;
    control.control = 1;
    const ComputePathResult compute = runComputePath(context, program, levels, control);
    ASSERT_EQ(compute.vertices.size(), hardware.vertices.size()) << ta.technique;
    const size_t unequal = unequalVertices(hardware.vertices, compute.vertices);
    EXPECT_GT(unequal, 0u) << ta.technique;
    std::printf("[compute path control] %s, u one ulp up: %zu of %zu vertices unequal\n",
                ta.technique, unequal, compute.vertices.size());
  }
}

TEST(ComputePath, ControlAnotherOperationOrderIsCaught) {
  // acc's compute shader with the asymmetric Bézier order (specialisation constant 0 = 0,
  // an FMA chain along u then v) against the TES capture in the default symmetric FMA order.
  TB_GPU_CONTEXT_OR_SKIP(context);
  const GpuPatchProgram program = accDefaultProgram();
  ASSERT_EQ(program.specialization.at(0), 2u);  // symmetric_fma
  const std::vector<tess::Levels> levels(program.patch_count, uniform(7));
  const PatchProgramCapture hardware =
      hardwareCapture(context, program, tess::Spacing::kInteger, levels);
  GpuPatchProgram reordered = program;
  reordered.specialization[0] = 0;  // asymmetric
  const ComputePathResult compute = runComputePath(context, reordered, levels);
  ASSERT_EQ(compute.vertices.size(), hardware.vertices.size());
  const size_t unequal = unequalVertices(hardware.vertices, compute.vertices);
  EXPECT_GT(unequal, 0u);
  std::printf("[compute path control] acc in the asymmetric order: %zu of %zu vertices unequal\n",
              unequal, compute.vertices.size());
}

TEST(ComputePath, RefusesProgramsItCannotRun) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const mesh::Mesh mesh = mesh::loadObjFile(::tb::testing::assetPath("tessbench/flat_cube.obj"));
  const auto surface = techniques::buildSurface(*phong, mesh, phong->variants()[0]);
  GpuPatchProgram program = surface->gpuPrograms()[0];
  program.displacement = std::make_shared<GpuDisplacement>();
  EXPECT_THROW(runComputePath(context, program, uniform(2)), GpuError);
  program.displacement.reset();
  program.compute_shader.clear();
  EXPECT_THROW(runComputePath(context, program, uniform(2)), GpuError);
}

}  // namespace
}  // namespace tb::gpu::compute_path_test
