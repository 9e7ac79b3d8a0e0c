#include "core/gpu/patch_program_pipeline.h"

#include <utility>

#include "core/gpu/sampled_image.h"
#include "core/gpu/spirv_patch.h"
#include "core/gpu/tess_pipelines.h"

namespace tb::gpu {
namespace {

// kTbFactorPolicy in shaders/common/patch_program_tcs.glsl.
constexpr uint32_t kFactorPolicyConstantId = 201;
// kTbCullPolicy in shaders/common/patch_program_tcs.glsl.
constexpr uint32_t kCullPolicyConstantId = 202;
// kTbDisplaceKind, kTbDisplaceSampling, kTbDisplaceTriangle in shaders/common/displace.glsl.
constexpr uint32_t kDisplaceKindConstantId = 203;
constexpr uint32_t kDisplaceSamplingConstantId = 204;
constexpr uint32_t kDisplaceTriangleConstantId = 205;

// The displacement's specialisation as one key word: 0 without a map, else kind, sampling
// and a presence bit.
uint32_t displacementKey(const GpuPatchProgram& program) {
  if (!program.displacement) return 0;
  return 1u << 8 | program.displacement->sampling << 4 | program.displacement->kind;
}

// `boundary`: kTbCaptureBoundary (kCapture*); a non-zero value is one more specialisation
// entry, ignored by the TCS, which does not declare it. `factor_policy`: kTbFactorPolicy,
// likewise ignored by the TES, and so is `cull_policy`: kTbCullPolicy.
VkPipelineOwner createProgramPipeline(VkDevice device, const GpuPatchProgram& program,
                                      tess::Spacing spacing, uint32_t boundary,
                                      uint32_t factor_policy, uint32_t cull_policy,
                                      VkShaderModule vertex, VkPipelineLayout layout,
                                      VkPipelineCreateFlags flags) {
  const VkShaderModuleOwner control =
      createShaderModule(device, requireEmbeddedShader(program.control_shader));
  const std::vector<uint32_t> tes_spirv = withTessModes(
      requireEmbeddedShader(program.evaluation_shader), {program.domain, spacing, true, false});
  const VkShaderModuleOwner evaluation = createShaderModule(device, tes_spirv);

  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values = program.specialization;
  for (uint32_t i = 0; i < values.size(); ++i) entries.push_back({i, i * 4u, 4});
  if (boundary != kCaptureEvery) {
    entries.push_back({kCaptureBoundaryConstantId, uint32_t(values.size()) * 4u, 4});
    values.push_back(boundary);
  }
  if (factor_policy != 0) {
    entries.push_back({kFactorPolicyConstantId, uint32_t(values.size()) * 4u, 4});
    values.push_back(factor_policy);
  }
  if (cull_policy != 0) {
    entries.push_back({kCullPolicyConstantId, uint32_t(values.size()) * 4u, 4});
    values.push_back(cull_policy);
  }
  if (program.displacement) {
    const uint32_t triangle = program.domain == tess::Domain::kTriangle ? 1u : 0u;
    for (const auto& [id, value] :
         {std::pair{kDisplaceKindConstantId, program.displacement->kind},
          std::pair{kDisplaceSamplingConstantId, program.displacement->sampling},
          std::pair{kDisplaceTriangleConstantId, triangle}}) {
      entries.push_back({id, uint32_t(values.size()) * 4u, 4});
      values.push_back(value);
    }
  }
  VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(), values.size() * 4,
                                      values.data()};
  VkPipelineShaderStageCreateInfo shader_stages[] = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, control.get()),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, evaluation.get()),
  };
  if (!entries.empty()) {
    shader_stages[1].pSpecializationInfo = &specialization;
    shader_stages[2].pSpecializationInfo = &specialization;
  }
  return createDiscardTessPipeline(device, layout, shader_stages, program.input_vertices_per_patch,
                                   "vkCreateGraphicsPipelines (patch program)", flags);
}

}  // namespace

std::unique_ptr<ProgramPipeline> buildProgramPipeline(VkDevice device, VkShaderModule vertex,
                                                      const GpuPatchProgram& program,
                                                      const ProgramBuild& build,
                                                      VkPipelineCreateFlags flags) {
  const uint32_t binding_count =
      uint32_t(program.storage_buffers.size()) + layout::kBindingFirstTechnique;
  auto p = std::make_unique<ProgramPipeline>();
  p->binding_count = binding_count;
  const std::vector<VkShaderStageFlags> stages(binding_count, kTessStages);
  p->set_layout = createStorageBufferSetLayout(device, stages);
  const std::vector<VkShaderStageFlags> levels_stages(kLevelsSetBindings,
                                                      VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT);
  p->levels_set_layout = createStorageBufferSetLayout(device, levels_stages);
  std::vector<VkDescriptorSetLayout> set_layouts = {p->set_layout.get(),
                                                    p->levels_set_layout.get()};
  if (program.displacement) {
    p->displacement_set_layout = createDisplacementSetLayout(device);
    set_layouts.push_back(p->displacement_set_layout.get());
  }
  p->layout = createPipelineLayout(device, set_layouts, kTessStages, sizeof(PushBlock));
  p->pipeline =
      createProgramPipeline(device, program, build.spacing, build.boundary, build.factor_policy,
                            build.cull_policy, vertex, p->layout.get(), flags);
  return p;
}

PatchProgramCache::PatchProgramCache(Context& context) : context_(context) {
  vertex_ = createShaderModule(context.device(), requireEmbeddedShader("gpu/tess_patch.vert"));
}

ProgramPipeline& PatchProgramCache::get(const GpuPatchProgram& program, tess::Spacing spacing,
                                        uint32_t boundary, uint32_t factor_policy,
                                        uint32_t cull_policy) {
  const uint32_t binding_count =
      uint32_t(program.storage_buffers.size()) + layout::kBindingFirstTechnique;
  ProgramKey key{program.control_shader,
                 program.evaluation_shader,
                 program.specialization,
                 int(program.domain),
                 int(spacing),
                 program.input_vertices_per_patch,
                 binding_count,
                 boundary,
                 factor_policy,
                 cull_policy,
                 displacementKey(program)};
  const std::lock_guard lock(mutex_);
  if (auto it = programs_.find(key); it != programs_.end()) return *it->second;

  std::unique_ptr<ProgramPipeline> p =
      buildProgramPipeline(context_.device(), vertex_.get(), program,
                           {spacing, boundary, factor_policy, cull_policy}, 0);
  return *programs_.emplace(std::move(key), std::move(p)).first->second;
}

std::unique_ptr<CallResources> PatchProgramCache::acquire() {
  {
    const std::lock_guard lock(mutex_);
    if (!free_.empty()) {
      std::unique_ptr<CallResources> resources = std::move(free_.back());
      free_.pop_back();
      return resources;
    }
  }
  auto resources = std::make_unique<CallResources>();
  auto info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
  info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
  info.queryCount = 1;
  info.pipelineStatistics = kTessStatisticFlags;
  VkQueryPool pool = VK_NULL_HANDLE;
  vkCheck(vkCreateQueryPool(context_.device(), &info, nullptr, &pool), "vkCreateQueryPool");
  resources->queries = VkQueryPoolOwner(context_.device(), pool);
  if (context_.features().primitives_generated_query) {
    auto primitives = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    primitives.queryType = VK_QUERY_TYPE_PRIMITIVES_GENERATED_EXT;
    primitives.queryCount = 1;
    VkQueryPool primitives_pool = VK_NULL_HANDLE;
    vkCheck(vkCreateQueryPool(context_.device(), &primitives, nullptr, &primitives_pool),
            "vkCreateQueryPool (primitives generated)");
    resources->primitives = VkQueryPoolOwner(context_.device(), primitives_pool);
  }
  return resources;
}

void PatchProgramCache::release(std::unique_ptr<CallResources> resources) {
  const std::lock_guard lock(mutex_);
  free_.push_back(std::move(resources));
}

}  // namespace tb::gpu
