// Instruction counts against hand counts: a bicubic Bézier patch evaluated with the
// counting scalar, and the arithmetic of shaders/gpu/test_bilinear.tese after spirv-opt -O.
#include "harness/measures/common/instruction_counts/instructions.h"

#include <gtest/gtest.h>

#include <bit>
#include <map>

#include "core/mesh/obj_loader.h"
#include "harness/measures/measure.h"
#include "shaders/embedded_shaders.h"
#include "techniques/counting_scalar.h"
#include "techniques/registry.h"
#include "tests/measures/face_patches.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// Bernstein form of a bicubic Bézier patch (Farin, Curves and Surfaces for CAGD, ch. 14).
template <class S>
mesh::Vec3T<S> bicubicBezier(const mesh::Vec3T<S> (&control)[4][4], S u, S v) {
  auto basis = [](S t, S(&b)[4]) {
    const S s = S(1) - t;
    b[0] = s * s * s;
    b[1] = S(3) * t * s * s;
    b[2] = S(3) * t * t * s;
    b[3] = t * t * t;
  };
  S bu[4], bv[4];
  basis(u, bu);
  basis(v, bv);
  mesh::Vec3T<S> p{S(0), S(0), S(0)};
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const S w = bu[i] * bv[j];
      p = p + control[j][i] * w;
    }
  }
  return p;
}

TEST(Instructions, CountingScalarMatchesAHandCountOfABicubicBezierPatch) {
  using C = techniques::CountingScalar<float>;
  mesh::Vec3T<C> control[4][4];
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) control[j][i] = {C(float(i)), C(float(j)), C(float(i * j) * 0.1f)};
  }
  techniques::resetOperationCounts();
  const mesh::Vec3T<C> p = bicubicBezier(control, C(0.25f), C(0.5f));
  const techniques::OperationCounts counts = techniques::operationCounts();
  // Hand count. Basis per direction: 1 subtraction, 2 + 3 + 3 + 2 = 10 multiplications.
  // Sum: 16 terms of 1 weight product + 3 scalings (4 mul) and 3 additions.
  EXPECT_EQ(counts.add, 2u * 1 + 16u * 3);
  EXPECT_EQ(counts.mul, 2u * 10 + 16u * 4);
  EXPECT_EQ(counts.div, 0u);
  EXPECT_EQ(counts.sqrt, 0u);
  EXPECT_EQ(counts.total(), 134u);
  // The patch is affine in (i, j) for x and y: x = 3u, y = 3v.
  EXPECT_FLOAT_EQ(p.x.value(), 0.75f);
  EXPECT_FLOAT_EQ(p.y.value(), 1.5f);
}

TEST(Instructions, StaticCountOfTheBilinearTestShaderMatchesAHandCount) {
  const measures::StageInstructionCounts counts =
      measures::countEmbeddedShader("gpu/test_bilinear.tese", {std::bit_cast<uint32_t>(2.0f)});
  // Hand count of test_bilinear.tese after common-subexpression elimination:
  //   1 - u (once, used twice), 1 - v                          2 FSub (scalar)
  //   bottom, top: 2 × (2 vec3 × scalar + 1 vec3 add)           4 mul, 2 add
  //   bottom (1 - v) + top v                                   2 mul, 1 add
  //   × scale (2.0, a frozen specialisation constant)           1 mul
  // tbEmitVertex does integer and bit-cast work only (no float arithmetic).
  EXPECT_EQ(counts.vector.add, 2u + 3u);
  EXPECT_EQ(counts.vector.mul, 7u);
  EXPECT_EQ(counts.scalar.add, 2u + 3u * 3);
  EXPECT_EQ(counts.scalar.mul, 7u * 3);
  EXPECT_EQ(counts.vector.div + counts.vector.sqrt + counts.vector.fma + counts.vector.compare, 0u);
  // One atomic add and the capture stores at least; scalar expansion never counts less.
  EXPECT_GE(counts.vector.load_store, 1u);
  EXPECT_GE(counts.scalar.total(), counts.vector.total());
}

TEST(Instructions, SpecialisationIsFrozenBeforeCounting) {
  // shaders/gpu/test_spec_switch.tese: constant 0 guards one normalize(vec3) (one
  // GLSL.std.450 call, float_other) and its branch; frozen to 0 the branch is dead code.
  const measures::StageInstructionCounts off =
      measures::countEmbeddedShader("gpu/test_spec_switch.tese", {0});
  const measures::StageInstructionCounts on =
      measures::countEmbeddedShader("gpu/test_spec_switch.tese", {1});
  EXPECT_EQ(off.vector.float_other, 3u);                          // three mix() calls
  EXPECT_EQ(on.vector.float_other, 4u);                           // and normalize
  EXPECT_EQ(on.scalar.float_other - off.scalar.float_other, 3u);  // a vec3 result
  EXPECT_EQ(off.vector.control_flow, on.vector.control_flow);     // the if folds away
}

TEST(Instructions, OptimisationRemovesWorkAndRejectsGarbage) {
  const auto words = gpu::embeddedShader("gpu/test_bilinear.tese");
  ASSERT_FALSE(words.empty());
  const measures::InstructionCounts raw = measures::countSpirvInstructions(words, false);
  const measures::InstructionCounts optimized =
      measures::countSpirvInstructions(measures::optimizeSpirv(words, {}), false);
  // glslang's unoptimised output goes through function calls and local variables.
  EXPECT_GT(raw.load_store, optimized.load_store);
  EXPECT_LT(optimized.total(), raw.total());
  const std::vector<uint32_t> garbage{1, 2, 3, 4, 5, 6};
  EXPECT_THROW(measures::countSpirvInstructions(garbage, false), std::runtime_error);
  EXPECT_THROW(measures::countEmbeddedShader("gpu/no_such.tese", {}), std::runtime_error);
}

// Patches whose operation counts differ per patch: patch p costs 10 + (p * 7) % 5
// multiplications per vertex, so the measure's min and max rows are known.
class ProfiledPatches final : public testing::FacePatches {
 public:
  using FacePatches::FacePatches;
  techniques::SurfacePoint evaluate(size_t, const techniques::DomainCoord&) const override {
    return {};
  }
  techniques::SurfacePointF evaluateFloat(size_t, const tess::DomainPoint&) const override {
    return {};
  }
  std::optional<techniques::OperationProfile> operationProfile(size_t p) const override {
    techniques::OperationProfile profile;
    profile.per_vertex.mul = 10 + (p * 7) % 5;
    profile.per_vertex.add = 4;
    profile.per_patch_setup.div = 1;
    return profile;
  }
};

double metricOf(const results::MetricRow& row, const std::string& name) {
  for (const results::Metric& metric : row.metrics) {
    if (metric.name == name) return metric.value;
  }
  return -1;
}

TEST(Instructions, MeasureReportsTheCheapestAndDearestPatchProfile) {
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const measures::Measure* measure = measures::MeasureRegistry::instance().find("instructions");
  ASSERT_NE(phong, nullptr);
  ASSERT_NE(measure, nullptr);
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const ProfiledPatches patches(mesh);
  const techniques::VariantInfo variant = phong->variants()[0];
  const results::MeasureResult result =
      measure->run({*phong, variant, "loop_icosahedron", mesh, &patches, nullptr, "none"});
  std::map<std::string, double> mul_per_vertex;
  for (const results::MetricRow& row : result.rows) {
    if (row.keys.at("source") != "counting_scalar" || row.keys.at("stage") != "per_vertex")
      continue;
    mul_per_vertex[row.keys.at("patch")] = metricOf(row, "mul");
    EXPECT_EQ(metricOf(row, "total"), metricOf(row, "mul") + 4);
  }
  // Hand evaluation of 10 + (7p mod 5): p = 0 gives the first 10, p = 2 the first 14.
  EXPECT_EQ(mul_per_vertex["min (patch 0)"], 10);
  EXPECT_EQ(mul_per_vertex["max (patch 2)"], 14);
  EXPECT_EQ(mul_per_vertex.size(), 2u);
}

}  // namespace
}  // namespace tb
