// High valence in acc and gregory_acc (issue 16, acceptance 3): a valence-64 pole
// (assets/tessbench/pole64.obj, OpenSubdiv's catmark_pole64 case) and a generated
// valence-256 one (kMaxValence of both) build, evaluate to finite points near the Bfr
// limit, and on the device the capture equals the CPU float twin with the symmetric
// orders bitwise watertight around the pole. Oracles: OpenSubdiv Bfr (ApproxLevel 10),
// evaluateFloat at the captured gl_TessCoord bits, and the neighbouring patch's points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/gpu/patch_program.h"
#include "core/mesh/float_ulp.h"
#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "core/tess/tessellator.h"
#include "harness/measures/cracks.h"
#include "reference/limit_surface.h"
#include "techniques/acc/acc.h"
#include "techniques/gregory_acc/gregory_acc.h"
#include "techniques/gregory_acc/gregory_stencils.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// The capsule of scripts/make_crack_assets.py (pole_capsule) with poles of `valence`:
// N (vertex 0) and S (vertex 1) on the unit sphere, rings of 2 * valence vertices at
// z = +-0.5, caps of `valence` quads and one band between the rings.
std::string capsuleObj(int valence) {
  const int m = 2 * valence;
  const double r = std::sqrt(0.75);
  std::string obj = "v 0 0 1\nv 0 0 -1\n";
  for (double z : {0.5, -0.5}) {
    for (int j = 0; j < m; ++j) {
      const double a = 2 * std::numbers::pi * j / m;
      obj += "v " + std::to_string(r * std::cos(a)) + " " + std::to_string(r * std::sin(a)) +
             " " + std::to_string(z) + "\n";
    }
  }
  const auto a = [m](int j) { return std::to_string(3 + j % m); };  // 1-based
  const auto b = [m](int j) { return std::to_string(3 + m + j % m); };
  for (int i = 0; i < valence; ++i) obj += "f 1 " + a(2 * i) + " " + a(2 * i + 1) + " " + a(2 * i + 2) + "\n";
  for (int j = 0; j < m; ++j) obj += "f " + a(j) + " " + b(j) + " " + b(j + 1) + " " + a(j + 1) + "\n";
  for (int i = 0; i < valence; ++i) obj += "f 2 " + b(2 * i + 2) + " " + b(2 * i + 1) + " " + b(2 * i) + "\n";
  return obj;
}

Mesh pole64() { return loadObjFile(testing::assetPath("tessbench/pole64.obj")); }

VariantInfo variantOf(const Technique& technique, const std::string& name) {
  for (const VariantInfo& v : technique.variants()) {
    if (v.name == name) return v;
  }
  ADD_FAILURE() << technique.info().name << " has no variant " << name;
  return {};
}

double diagonal(const Mesh& mesh) {
  Vec3d lo = mesh.positions.front(), hi = lo;
  for (const Vec3d& p : mesh.positions) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  return length(hi - lo);
}

TEST(Valence, Pole64AssetHasTwoPolesOfValence64) {
  const Mesh mesh = pole64();
  const Topology topology = buildTopology(mesh);
  EXPECT_EQ(mesh.faceCount(), 256u);
  EXPECT_EQ(topology.valence[0], 64u);
  EXPECT_EQ(topology.valence[1], 64u);
  EXPECT_EQ(AccTechnique().checkSupport(mesh), "");
  EXPECT_EQ(gregory_acc::GregoryAccTechnique().checkSupport(mesh), "");
  static_assert(acc::kMaxValence >= 64 && gregory_acc::kMaxValence >= 64);
}

// Worst distance / bounding-box diagonal between the technique and the Bfr limit over a
// 9 x 9 grid of the patches at the pole (vertex 0: every patch of a cap has it as a corner).
struct PoleFigures {
  double worst_double = 0, worst_float = 0;
  size_t patches = 0;
};

PoleFigures nearThePole(const Technique& technique, const std::string& variant, const Mesh& mesh) {
  const ref::LimitSurface limit(mesh, ref::Scheme::kCatmullClark);
  const auto patches = buildSurface(technique, mesh, variantOf(technique, variant));
  const double diag = diagonal(mesh);
  PoleFigures out;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.facePositions(f)[0] != 0) continue;  // cap faces start at the pole N
    ++out.patches;
    const ref::LimitFace face = limit.face(f);
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 8; ++j) {
        const double u = i / 8.0, v = j / 8.0;
        const ref::LimitPoint exact = face.evaluate(u, v);
        const SurfacePoint p = patches->evaluate(f, {u, v, 0});
        const SurfacePointF q = patches->evaluateFloat(f, {float(u), float(v)});
        EXPECT_TRUE(std::isfinite(p.position.x) && std::isfinite(p.position.y) &&
                    std::isfinite(p.position.z) && std::isfinite(p.normal.x))
            << technique.info().name << " face " << f;
        out.worst_double = std::max(out.worst_double, length(p.position - exact.position) / diag);
        out.worst_float =
            std::max(out.worst_float, length(vecCast<double>(q.position) - exact.position) / diag);
      }
    }
  }
  return out;
}

// Bounds: measured 2026-11 (figures printed) and rounded up about 2x; the approximation's
// own error (ACC and Gregory are not the limit at extraordinary vertices), not round-off:
// float and double agree to ~1e-7 of the diagonal.
TEST(Valence, Valence64And256BuildAndStayNearTheBfrLimitAtThePole) {
  struct Case {
    const char* label;
    Mesh mesh;
  };
  const Case cases[] = {{"pole64.obj", pole64()},
                        {"capsule256", loadObjText(capsuleObj(256), "capsule256.obj")}};
  const AccTechnique acc_technique;
  const gregory_acc::GregoryAccTechnique gregory;
  for (const Case& c : cases) {
    for (const auto& [technique, variant] :
         {std::pair<const Technique*, const char*>{&acc_technique, "default"},
          {&gregory, "edge_symmetric"}}) {
      const PoleFigures f = nearThePole(*technique, variant, c.mesh);
      std::printf("[valence] %-10s %-11s %3zu pole patches: max |surface - Bfr| / diagonal "
                  "double %.3e float %.3e\n",
                  c.label, technique->info().name.c_str(), f.patches, f.worst_double,
                  f.worst_float);
      EXPECT_GT(f.patches, 60u);
      EXPECT_LT(f.worst_double, 2e-2) << c.label << " " << technique->info().name;
      EXPECT_LT(std::abs(f.worst_float - f.worst_double), 1e-6) << c.label;
    }
  }
}

struct LevelCase {
  float level;
  tess::Spacing spacing;
};
constexpr LevelCase kLevels[] = {{1.0f, tess::Spacing::kInteger},
                                 {7.3f, tess::Spacing::kFractionalOdd},
                                 {16.0f, tess::Spacing::kInteger}};

// Every GPU program's capture against evaluateFloat at the captured coordinates.
TEST(ValenceGpu, Pole64CaptureEqualsTheCpuFloatTwin) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const Mesh mesh = pole64();
  const AccTechnique acc_technique;
  const gregory_acc::GregoryAccTechnique gregory;
  for (const auto& [technique, variant] :
       {std::pair<const Technique*, const char*>{&acc_technique, "default"},
        {&acc_technique, "symmetric_nofma"},
        {&acc_technique, "no_tangent"},
        {&gregory, "edge_symmetric"},
        {&gregory, "exact_tangents"}}) {
    const auto patches = buildSurface(*technique, mesh, variantOf(*technique, variant));
    uint64_t worst = 0;
    double worst_normal = 0;
    size_t vertices = 0;
    for (const LevelCase& lc : kLevels) {
      tess::Levels levels;
      levels.outer = {lc.level, lc.level, lc.level, lc.level};
      levels.inner = {lc.level, lc.level};
      gpu::PatchProgramOptions options;
      options.spacing = lc.spacing;
      options.patches_per_draw = 16;
      for (const gpu::GpuPatchProgram& program : patches->gpuPrograms()) {
        const gpu::PatchProgramCapture capture =
            gpu::runPatchProgram(context, program, levels, options);
        for (const gpu::CapturedVertex& v : capture.vertices) {
          const SurfacePointF cpu = patches->evaluateFloat(v.patch, v.coord);
          worst = std::max(worst, maxUlpDistance(cpu.position, v.position));
          worst_normal = std::max(worst_normal, double(length(cpu.normal - v.normal)));
          ++vertices;
        }
      }
    }
    std::printf("[valence gpu] pole64 %-11s %-15s %zu vertices: max %llu ulp from "
                "evaluateFloat, max normal diff %.1e\n",
                technique->info().name.c_str(), variant, vertices, (unsigned long long)worst,
                worst_normal);
    EXPECT_GT(vertices, 16 * patches->patchCount());  // level 16 alone gives 289 per patch
    // The bound of acc_gpu_test and gregory_acc_gpu_test: the CPU twin follows the
    // shader's operation order, the device may differ in the last bits of a few FMAs.
    EXPECT_LE(worst, 4u) << technique->info().name << " " << variant;
    EXPECT_LT(worst_normal, 1e-4) << technique->info().name << " " << variant;
  }
}

// Symmetric variants: bitwise watertight on the CPU float twin and on the device,
// around both poles and everywhere else on the asset.
TEST(ValenceGpu, SymmetricVariantsStayBitwiseWatertightAroundThePole) {
  const Mesh mesh = pole64();
  const AccTechnique acc_technique;
  const gregory_acc::GregoryAccTechnique gregory;
  std::string skip;
  gpu::Context* context = gpu::testing::sharedContext(&skip);
  for (const auto& [technique, variant] :
       {std::pair<const Technique*, const char*>{&acc_technique, "default"},
        {&acc_technique, "symmetric_nofma"},
        {&acc_technique, "symmetric_edges"},
        {&gregory, "edge_symmetric"}}) {
    const auto patches = buildSurface(*technique, mesh, variantOf(*technique, variant));
    for (const LevelCase& lc : kLevels) {
      for (CrackBackend backend : {CrackBackend::kCpuFloat, CrackBackend::kGpu}) {
        if (backend == CrackBackend::kGpu && context == nullptr) continue;
        const CrackFigures f = measureCracks(*patches, lc.spacing, lc.level, backend, context);
        std::printf("[valence cracks] pole64 %-11s %-15s level %4.1f %-9s: %llu pairs, %llu not "
                    "bitwise, max gap %.3g, device max %llu ulp\n",
                    technique->info().name.c_str(), variant, lc.level, toString(backend),
                    (unsigned long long)f.points_compared, (unsigned long long)f.points_not_equal,
                    f.max_gap_world, (unsigned long long)f.device_max_ulp);
        ASSERT_TRUE(f.measured) << f.skipped_reason;
        EXPECT_GT(f.shared_edges, 500u);  // 512 edges on the closed 256-quad capsule
        EXPECT_EQ(f.points_not_equal, 0u) << technique->info().name << " " << variant;
        EXPECT_EQ(f.unpaired_points, 0u);
      }
    }
  }
  if (context == nullptr) GTEST_SKIP() << "CPU float checked; no usable Vulkan device: " << skip;
}

}  // namespace
}  // namespace tb
