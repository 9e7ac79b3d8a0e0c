#include "harness/cli/run_context.h"

#include <embree3/rtcore_config.h>
#include <fmt/format.h>
#include <glslang/build_info.h>
#include <meshoptimizer.h>
#include <oneapi/tbb/version.h>
#include <opensubdiv/version.h>
#include <unistd.h>
#include <vulkan/vulkan.h>

#include <CLI/Version.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/gpu/context.h"
#include "tb_build_info.h"

namespace tb::cli {
namespace {

#define TB_STRINGIFY2(x) #x
#define TB_STRINGIFY(x) TB_STRINGIFY2(x)

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const size_t colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}

std::string hostName() {
  char name[256] = {};
  if (gethostname(name, sizeof(name) - 1) != 0) return "unknown";
  return name;
}

std::string vulkanLoaderVersion() {
  uint32_t version = 0;
  if (vkEnumerateInstanceVersion(&version) != VK_SUCCESS) return "unavailable";
  return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(version), VK_API_VERSION_MINOR(version),
                     VK_API_VERSION_PATCH(version));
}

}  // namespace

results::RunContext probeRunContext(const std::string& command_line,
                                    const std::string& device_name) {
  results::RunContext context;
  context.vulkan_device = gpu::describeDevice(device_name);
  context.git_sha = TB_GIT_SHA;
  context.commit_time = TB_GIT_COMMIT_TIME;
  context.host = hostName();
  context.cpu = cpuModel() + " (" + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores)";
  context.compiler = TB_COMPILER;
  context.build_type = TB_BUILD_TYPE;
  context.command_line = command_line;
  context.libraries = {
      {"OpenSubdiv", TB_STRINGIFY(OPENSUBDIV_VERSION)},
      {"Embree", RTC_VERSION_STRING},
      {"Vulkan loader", vulkanLoaderVersion()},
      {"Vulkan headers", fmt::format("1.3.{}", VK_HEADER_VERSION)},
      {"glslang", fmt::format("{}.{}.{}", GLSLANG_VERSION_MAJOR, GLSLANG_VERSION_MINOR,
                              GLSLANG_VERSION_PATCH)},
      {"meshoptimizer",
       fmt::format("{}.{}", MESHOPTIMIZER_VERSION / 1000, (MESHOPTIMIZER_VERSION % 1000) / 10)},
      {"oneTBB", TBB_VERSION_STRING},
      {"fmt",
       fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"nlohmann_json", fmt::format("{}.{}.{}", NLOHMANN_JSON_VERSION_MAJOR,
                                    NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
      {"CLI11", CLI11_VERSION},
  };
  return context;
}

}  // namespace tb::cli
