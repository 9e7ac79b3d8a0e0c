// Internal to runPatchProgram (patch_program.cpp): the compiled programs (descriptor
// layouts and pipeline, one per program, spacing and specialisation) and the per-call
// resources, both kept per device by PatchProgramCache, a Context attachment.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "core/gpu/buffer.h"
#include "core/gpu/context.h"
#include "core/gpu/patch_program_desc.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"
#include "core/tess/tessellator.h"
#include "shaders/common/layout/bindings.h"

namespace tb::gpu {

// TbPatchProgramPush in shaders/common/patch_program.glsl.
struct PushBlock {
  uint32_t first_patch;
  uint32_t capture_enabled;
};
static_assert(sizeof(PushBlock) == 8);

// kTbCaptureBoundary in shaders/common/patch_program_tes.glsl: its constant_id and values.
constexpr uint32_t kCaptureBoundaryConstantId = 200;
constexpr uint32_t kCaptureEvery = 0, kCaptureQuadBoundary = 1, kCaptureTriangleBoundary = 2;
// Set 1: the harness levels, then the factor policy's corners, parameters and output, then
// the culling policy's parameters and per-patch bounds.
constexpr uint32_t kLevelsSetBindings = layout::kBindingCullTangentPlanes + 1;
constexpr VkShaderStageFlags kTessStages =
    VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;

// One compiled program: its descriptor layouts (set 0: capture + the technique's
// buffers; set 1: per-patch levels) and pipeline. Immutable once built (but for the
// warm-up flag), so calls on several threads share it; each call allocates its own
// descriptor sets.
struct ProgramPipeline {
  VkDescriptorSetLayoutOwner set_layout;
  VkDescriptorSetLayoutOwner levels_set_layout;
  VkDescriptorSetLayoutOwner displacement_set_layout;  // set 2, "#displaced" programs only
  VkPipelineLayoutOwner layout;
  VkPipelineOwner pipeline;
  uint32_t binding_count = 0;
  std::atomic<bool> warmed{false};  // the compile-at-first-draw warm-up has been drawn
};

// What one call uploads to, captures into, binds and counts with; pooled so that calls
// reuse the buffers (fresh device memory costs page faults on lavapipe) and descriptor
// sets. Buffers only grow; each is bound with the range the call uses.
struct CallResources {
  struct PipelineSets {
    StorageBufferSet data;    // set 0: capture + GpuPatchProgram::storage_buffers
    StorageBufferSet levels;  // set 1: per-patch levels
  };
  VkQueryPoolOwner queries;
  VkQueryPoolOwner primitives;  // VK_QUERY_TYPE_PRIMITIVES_GENERATED_EXT, when supported
  Buffer capture;
  Buffer levels;
  Buffer factor_corners;     // TcsFactorPolicy::corner_words (a 16-byte stub without a policy)
  Buffer factor_params;      // TcsFactorPolicy::param_words
  Buffer factor_out;         // the levels the TCS wrote, 8 words per patch
  Buffer cull_params;        // TcsCullPolicy::param_words
  Buffer cull_patches;       // TcsCullPolicy::patch_words
  Buffer cull_tangent;       // TcsCullPolicy::tangent_words
  std::vector<Buffer> data;  // GpuPatchProgram::storage_buffers
  std::map<const ProgramPipeline*, PipelineSets> sets;  // per pipeline drawn with
};

// The build switches of a program's pipeline besides the program itself.
struct ProgramBuild {
  tess::Spacing spacing = tess::Spacing::kInteger;
  uint32_t boundary = kCaptureEvery;  // kTbCaptureBoundary (kCapture*)
  uint32_t factor_policy = 0;         // kTbFactorPolicy: 0 the harness's levels, 1 the policy's
  uint32_t cull_policy = 0;           // kTbCullPolicy: 0, 1, or kTbCullPolicyFixed + policy
};

// The program's layouts and pipeline (rasterizer discard, patch list of
// input_vertices_per_patch), created with `flags` (0, or the capture bits of
// pipeline_executables.h); only the count of storage_buffers is read. Throws GpuError.
std::unique_ptr<ProgramPipeline> buildProgramPipeline(VkDevice device, VkShaderModule vertex,
                                                      const GpuPatchProgram& program,
                                                      const ProgramBuild& build,
                                                      VkPipelineCreateFlags flags);

using ProgramKey = std::tuple<std::string, std::string, std::vector<uint32_t>, int, int, uint32_t,
                              uint32_t, uint32_t, uint32_t, uint32_t, uint32_t>;

// Per-device cache of program pipelines (lavapipe compiles at the first draw, so a
// pipeline is worth keeping) and a pool of per-call resources. `mutex` guards the map
// and the pool; what they hand out is used without it.
class PatchProgramCache {
 public:
  explicit PatchProgramCache(Context& context);

  ProgramPipeline& get(const GpuPatchProgram& program, tess::Spacing spacing, uint32_t boundary,
                       uint32_t factor_policy, uint32_t cull_policy);
  std::unique_ptr<CallResources> acquire();
  void release(std::unique_ptr<CallResources> resources);

 private:
  Context& context_;
  VkShaderModuleOwner vertex_;
  std::mutex mutex_;
  std::map<ProgramKey, std::unique_ptr<ProgramPipeline>> programs_;
  std::vector<std::unique_ptr<CallResources>> free_;
};

// Per-call resources from the cache, given back when the call ends (or throws).
class CallResourcesLease {
 public:
  explicit CallResourcesLease(PatchProgramCache& cache)
      : cache_(cache), resources_(cache.acquire()) {}
  ~CallResourcesLease() { cache_.release(std::move(resources_)); }
  CallResourcesLease(const CallResourcesLease&) = delete;
  CallResourcesLease& operator=(const CallResourcesLease&) = delete;
  CallResources* operator->() const { return resources_.get(); }
  CallResources& operator*() const { return *resources_; }

 private:
  PatchProgramCache& cache_;
  std::unique_ptr<CallResources> resources_;
};

}  // namespace tb::gpu
