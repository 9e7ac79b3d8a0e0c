#include "core/gpu/pipeline_executables.h"

#include <cassert>
#include <utility>

#include "core/gpu/compute_runner.h"
#include "core/gpu/gpu_error.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

// The extension's entry points, from the device (the loader exports none of them).
struct ExecutableFunctions {
  PFN_vkGetPipelineExecutablePropertiesKHR properties = nullptr;
  PFN_vkGetPipelineExecutableStatisticsKHR statistics = nullptr;
  PFN_vkGetPipelineExecutableInternalRepresentationsKHR representations = nullptr;
};

ExecutableFunctions functionsOf(VkDevice device) {
  ExecutableFunctions f;
  f.properties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutablePropertiesKHR"));
  f.statistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutableStatisticsKHR"));
  f.representations = reinterpret_cast<PFN_vkGetPipelineExecutableInternalRepresentationsKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutableInternalRepresentationsKHR"));
  if (!f.properties || !f.statistics || !f.representations) {
    throw GpuError("VK_KHR_pipeline_executable_properties: the device has no entry points");
  }
  return f;
}

double statisticValue(const VkPipelineExecutableStatisticKHR& s) {
  switch (s.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
      return s.value.b32 ? 1.0 : 0.0;
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
      return double(s.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
      return double(s.value.u64);
    default:
      return s.value.f64;
  }
}

std::vector<ExecutableStatistic> statisticsOf(const ExecutableFunctions& f, VkDevice device,
                                              const VkPipelineExecutableInfoKHR& info) {
  uint32_t count = 0;
  vkCheck(f.statistics(device, &info, &count, nullptr), "vkGetPipelineExecutableStatisticsKHR");
  std::vector<VkPipelineExecutableStatisticKHR> raw(
      count, vkStruct<VkPipelineExecutableStatisticKHR>(
                 VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR));
  vkCheck(f.statistics(device, &info, &count, raw.data()), "vkGetPipelineExecutableStatisticsKHR");
  std::vector<ExecutableStatistic> out;
  for (uint32_t i = 0; i < count; ++i) {
    out.push_back({raw[i].name, raw[i].description, statisticValue(raw[i]),
                   raw[i].format == VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR});
  }
  return out;
}

std::vector<ExecutableRepresentation> representationsOf(const ExecutableFunctions& f,
                                                        VkDevice device,
                                                        const VkPipelineExecutableInfoKHR& info) {
  uint32_t count = 0;
  const char* what = "vkGetPipelineExecutableInternalRepresentationsKHR";
  vkCheck(f.representations(device, &info, &count, nullptr), what);
  std::vector<VkPipelineExecutableInternalRepresentationKHR> raw(
      count, vkStruct<VkPipelineExecutableInternalRepresentationKHR>(
                 VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INTERNAL_REPRESENTATION_KHR));
  vkCheck(f.representations(device, &info, &count, raw.data()), what);  // the sizes
  std::vector<std::string> texts(count);
  for (uint32_t i = 0; i < count; ++i) {
    texts[i].assign(raw[i].dataSize, '\0');
    raw[i].pData = texts[i].data();
  }
  vkCheck(f.representations(device, &info, &count, raw.data()), what);
  std::vector<ExecutableRepresentation> out;
  for (uint32_t i = 0; i < count; ++i) {
    std::string text = raw[i].isText ? std::move(texts[i]) : std::string();
    while (!text.empty() && text.back() == '\0') text.pop_back();
    out.push_back({raw[i].name, std::move(text)});
  }
  return out;
}

}  // namespace

std::string stageNames(VkShaderStageFlags stages) {
  constexpr std::pair<VkShaderStageFlagBits, const char*> kNames[] = {
      {VK_SHADER_STAGE_VERTEX_BIT, "vertex"},
      {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, "tess_control"},
      {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, "tess_evaluation"},
      {VK_SHADER_STAGE_GEOMETRY_BIT, "geometry"},
      {VK_SHADER_STAGE_FRAGMENT_BIT, "fragment"},
      {VK_SHADER_STAGE_COMPUTE_BIT, "compute"},
  };
  std::string out;
  for (const auto& [bit, name] : kNames) {
    if ((stages & bit) == 0) continue;
    if (!out.empty()) out += '+';
    out += name;
  }
  return out.empty() ? "other" : out;
}

std::vector<PipelineExecutable> readPipelineExecutables(VkDevice device, VkPipeline pipeline,
                                                        bool representations) {
  assert(device != VK_NULL_HANDLE && pipeline != VK_NULL_HANDLE);
  const ExecutableFunctions f = functionsOf(device);
  auto pipeline_info = vkStruct<VkPipelineInfoKHR>(VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR);
  pipeline_info.pipeline = pipeline;
  uint32_t count = 0;
  vkCheck(f.properties(device, &pipeline_info, &count, nullptr),
          "vkGetPipelineExecutablePropertiesKHR");
  std::vector<VkPipelineExecutablePropertiesKHR> raw(
      count, vkStruct<VkPipelineExecutablePropertiesKHR>(
                 VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR));
  vkCheck(f.properties(device, &pipeline_info, &count, raw.data()),
          "vkGetPipelineExecutablePropertiesKHR");
  std::vector<PipelineExecutable> out;
  for (uint32_t i = 0; i < count; ++i) {
    auto info =
        vkStruct<VkPipelineExecutableInfoKHR>(VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR);
    info.pipeline = pipeline;
    info.executableIndex = i;
    PipelineExecutable e;
    e.name = raw[i].name;
    e.description = raw[i].description;
    e.stages = raw[i].stages;
    e.subgroup_size = raw[i].subgroupSize;
    e.statistics = statisticsOf(f, device, info);
    if (representations) e.representations = representationsOf(f, device, info);
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<PipelineExecutable> patchProgramExecutables(VkDevice device,
                                                        const GpuPatchProgram& program,
                                                        const ProgramBuild& build,
                                                        bool representations) {
  const VkShaderModuleOwner vertex =
      createShaderModule(device, requireEmbeddedShader("gpu/tess_patch.vert"));
  const VkPipelineCreateFlags flags =
      kCaptureStatistics | (representations ? kCaptureRepresentations : 0);
  const std::unique_ptr<ProgramPipeline> pipeline =
      buildProgramPipeline(device, vertex.get(), program, build, flags);
  return readPipelineExecutables(device, pipeline->pipeline.get(), representations);
}

std::vector<PipelineExecutable> computePassExecutables(VkDevice device, const GpuComputePass& pass,
                                                       bool representations) {
  const VkPipelineCreateFlags flags =
      kCaptureStatistics | (representations ? kCaptureRepresentations : 0);
  const std::shared_ptr<const CachedComputePipeline> pipeline =
      createComputePassPipeline(device, pass, bindingCountOf(pass), flags);
  return readPipelineExecutables(device, pipeline->pipeline.get(), representations);
}

}  // namespace tb::gpu
