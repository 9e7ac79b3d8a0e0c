// SPIR-V execution-mode rewriting. Oracle: the SPIR-V 1.6 specification's enumerants
// (Execution Mode: SpacingEqual 1, FractionalEven 2, FractionalOdd 3, VertexOrderCw 4,
// VertexOrderCcw 5, PointMode 10, Triangles 22, Quads 24, Isolines 25).
#include "core/gpu/spirv_patch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/gpu/gpu_error.h"
#include "shaders/embedded_shaders.h"

namespace tb::gpu {
namespace {

std::vector<uint32_t> executionModes(const std::vector<uint32_t>& spirv) {
  std::vector<uint32_t> modes;
  for (size_t i = 5; i < spirv.size(); i += spirv[i] >> 16) {
    if ((spirv[i] & 0xffff) == 16) modes.push_back(spirv[i + 2]);
  }
  std::sort(modes.begin(), modes.end());
  return modes;
}

TEST(SpirvPatch, RewritesDomainSpacingWindingAndPointMode) {
  const auto tes = embeddedShader("gpu/tess_plain.tese");
  ASSERT_FALSE(tes.empty());
  TessModes modes{tess::Domain::kQuad, tess::Spacing::kFractionalOdd, false, true};
  EXPECT_EQ(executionModes(withTessModes(tes, modes)), (std::vector<uint32_t>{3, 4, 10, 24}));
  modes = {tess::Domain::kIsoline, tess::Spacing::kPow2, true, false};
  EXPECT_EQ(executionModes(withTessModes(tes, modes)), (std::vector<uint32_t>{1, 5, 25}));
  modes = {tess::Domain::kTriangle, tess::Spacing::kFractionalEven, true, false};
  EXPECT_EQ(executionModes(withTessModes(tes, modes)), (std::vector<uint32_t>{2, 5, 22}));
}

TEST(SpirvPatch, PatchingTwiceDropsTheOldPointMode) {
  const auto tes = embeddedShader("gpu/tess_capture.tese");
  const auto point = withTessModes(tes, {tess::Domain::kQuad, tess::Spacing::kInteger, true, true});
  const auto plain =
      withTessModes(point, {tess::Domain::kQuad, tess::Spacing::kInteger, true, false});
  const auto modes = executionModes(plain);
  EXPECT_EQ(std::count(modes.begin(), modes.end(), 10u), 0);
  EXPECT_EQ(plain.size() + 3, point.size());
}

TEST(SpirvPatch, RejectsAComputeShader) {
  const auto comp = embeddedShader("gpu/scale_buffer.comp");
  EXPECT_THROW(withTessModes(comp, {}), GpuError);
  const std::vector<uint32_t> garbage = {1, 2, 3};
  EXPECT_THROW(withTessModes(garbage, {}), GpuError);
}

}  // namespace
}  // namespace tb::gpu
