// What the driver's compiler made of a pipeline (VK_KHR_pipeline_executable_properties):
// its executables as the driver splits them (AMD from GFX9 merges the vertex and
// tessellation-control shaders into one), each with the statistics the driver names
// (registers, instructions, latency ...) and, when asked, its internal representations
// (RADV: "NIR Shader(s)", "ACO IR", "Assembly"). Compiles pipelines; never executes them.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/gpu/compute_program_desc.h"
#include "core/gpu/patch_program_desc.h"
#include "core/gpu/patch_program_pipeline.h"

namespace tb::gpu {

// The pipeline-create bits that ask for statistics (and internal representations).
constexpr VkPipelineCreateFlags kCaptureStatistics = VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR;
constexpr VkPipelineCreateFlags kCaptureRepresentations =
    VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;

// One statistic as the driver names it ("VGPRs", "Inverse Throughput"); integers and
// booleans converted to double exactly (values beyond 2^53, such as hashes, lose bits).
struct ExecutableStatistic {
  std::string name;
  std::string description;
  double value = 0;
  bool is_float = false;  // VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR
};

struct ExecutableRepresentation {
  std::string name;  // "Assembly"
  std::string text;  // empty for a binary representation
};

struct PipelineExecutable {
  std::string name;         // "Vertex + Tessellation Control Shaders"
  std::string description;  // the driver's line
  VkShaderStageFlags stages = 0;
  uint32_t subgroup_size = 0;  // the wave size it runs with (32 or 64 on AMD)
  std::vector<ExecutableStatistic> statistics;
  std::vector<ExecutableRepresentation> representations;
};

// "vertex+tess_control", "tess_evaluation", "compute": the stages joined by '+'.
std::string stageNames(VkShaderStageFlags stages);

// The executables of `pipeline`, created with kCaptureStatistics (and
// kCaptureRepresentations when `representations`), in the driver's order.
std::vector<PipelineExecutable> readPipelineExecutables(VkDevice device, VkPipeline pipeline,
                                                        bool representations);

// Compiles the program's pipeline as PatchProgramCache would (only the storage buffers'
// count is read) and reads its executables. The device must have been created with
// VK_KHR_pipeline_executable_properties (a Context's, when DeviceFeatures::
// pipeline_executable_info; a CompilerDevice's). Throws GpuError.
std::vector<PipelineExecutable> patchProgramExecutables(VkDevice device,
                                                        const GpuPatchProgram& program,
                                                        const ProgramBuild& build,
                                                        bool representations);

// The same for a compute pass, as ComputeRunner builds it (bindingCountOf bindings).
std::vector<PipelineExecutable> computePassExecutables(VkDevice device, const GpuComputePass& pass,
                                                       bool representations);

}  // namespace tb::gpu
