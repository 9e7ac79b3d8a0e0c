// Device selection, feature report and shader embedding. Oracle: `vulkaninfo --summary`
// on the Debian 12 test machine (lavapipe 22.3.6, docs/ARCHITECTURE.md §6).
#include "core/gpu/context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "shaders/embedded_shaders.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

TEST(EmbeddedShader, KnownPathsAreSpirvUnknownIsEmpty) {
  for (std::string_view path : {"gpu/tess_patch.vert", "gpu/tess_levels.tesc",
                                "gpu/tess_capture.tese", "gpu/scale_buffer.comp"}) {
    const auto spirv = embeddedShader(path);
    ASSERT_GT(spirv.size(), 5u) << path;
    EXPECT_EQ(spirv[0], kSpirvMagic) << path;
  }
  EXPECT_TRUE(embeddedShader("gpu/no_such_shader.comp").empty());
  EXPECT_TRUE(embeddedShader("").empty());
  const auto paths = embeddedShaderPaths();
  EXPECT_NE(std::find(paths.begin(), paths.end(), "gpu/tess_capture.tese"), paths.end());
}

TEST(Context, PicksAGpuOrLavapipeAndReportsIt) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const DeviceInfo& info = context.info();
  std::printf("device: %s (%s), driver %s: %s, Vulkan %s, validation %s\n",
              info.device_name.c_str(), info.device_type.c_str(), info.driver_name.c_str(),
              info.driver_info.c_str(), info.api_version.c_str(),
              info.validation_enabled ? "on" : "off");
  EXPECT_FALSE(info.device_name.empty());
  EXPECT_FALSE(info.api_version.empty());
  if (info.device_type == "cpu") {
    EXPECT_NE(info.device_name.find("llvmpipe"), std::string::npos);
    EXPECT_EQ(info.driver_name, "llvmpipe");
    EXPECT_EQ(info.max_tessellation_level, 64u);
  }
  // The default options require the capture features, so they must be reported present.
  EXPECT_TRUE(info.features.tessellation_shader);
  EXPECT_TRUE(info.features.transform_feedback);
  EXPECT_TRUE(info.features.pipeline_statistics_query);
  EXPECT_TRUE(info.features.dynamic_rendering);
}

TEST(Context, FeatureListNamesEveryFeature) {
  DeviceFeatures f;
  f.transform_feedback = true;
  const auto list = featureList(f);
  EXPECT_EQ(list.size(), 11u);
  EXPECT_EQ(list.back().first, "pipelineExecutableInfo");
  EXPECT_EQ(list.front().first, "tessellationShader");
  EXPECT_EQ(firstMissingFeature(f, tessCaptureFeatures()), "tessellationShader");
  EXPECT_EQ(firstMissingFeature(tessCaptureFeatures(), f), "");
}

TEST(Context, UnknownDeviceNameFailsWithAReason) {
  ContextOptions options;
  options.device_name = "no-such-device-xyz";
  const auto context = Context::create(options);
  ASSERT_FALSE(context.ok());
  EXPECT_NE(context.error().find("no"), std::string::npos) << context.error();
  EXPECT_EQ(context.error().find('\n'), std::string::npos) << "one line";
}

// With no Vulkan driver the loader finds no device: creation must return a reason, not
// crash or exit. The loader reads VK_DRIVER_FILES / VK_ICD_FILENAMES at instance creation.
TEST(Context, NoDriverFailsWithAReason) {
  const char* kVariables[] = {"VK_DRIVER_FILES", "VK_ICD_FILENAMES"};
  for (const char* name : kVariables) setenv(name, "/nonexistent/tessbench_icd.json", 1);
  const auto context = Context::create();
  for (const char* name : kVariables) unsetenv(name);
  ASSERT_FALSE(context.ok());
  std::printf("reason: %s\n", context.error().c_str());
  EXPECT_FALSE(context.error().empty());
  EXPECT_EQ(context.error().find('\n'), std::string::npos) << "one line";
}

TEST(Context, DeviceNameSubstringSelectsCaseInsensitively) {
  TB_GPU_CONTEXT_OR_SKIP(shared);
  if (shared.info().driver_name != "llvmpipe") GTEST_SKIP() << "lavapipe is not the device";
  ContextOptions options;
  options.device_name = "LLVMPIPE";
  const auto context = Context::create(options);
  ASSERT_TRUE(context.ok()) << context.error();
  EXPECT_EQ(context.value()->info().driver_name, "llvmpipe");
}

}  // namespace
}  // namespace tb::gpu
