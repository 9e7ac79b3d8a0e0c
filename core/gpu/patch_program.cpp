#include "core/gpu/patch_program.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <map>
#include <tuple>

#include "core/gpu/buffer.h"
#include "core/gpu/context.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/spirv_patch.h"
#include "core/gpu/tess_pipelines.h"
#include "core/gpu/vk_handle.h"
#include "core/tess/factor_helpers.h"

namespace tb::gpu {
namespace {

// TbPatchProgramPush in shaders/common/patch_program.glsl.
struct PushBlock {
  uint32_t outer_bits[4];
  uint32_t inner_bits[2];
  uint32_t first_patch;
  uint32_t capture_enabled;
};
static_assert(sizeof(PushBlock) == 32);

constexpr uint32_t kCaptureWords = 10;           // kTbCaptureWords
constexpr VkDeviceSize kCaptureHeaderBytes = 16;  // count, capacity, 2 reserved
constexpr VkDeviceSize kMaxCaptureBytesPerSubmit = 64ull << 20;
constexpr VkShaderStageFlags kTessStages =
    VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;

// One compiled program: its descriptor layout, pipeline and descriptor set.
struct ProgramPipeline {
  VkDescriptorSetLayoutOwner set_layout;
  VkPipelineLayoutOwner layout;
  VkPipelineOwner pipeline;
  StorageBufferSet descriptors;
  uint32_t binding_count = 0;
};

using ProgramKey = std::tuple<std::string, std::string, std::vector<uint32_t>, int, int, uint32_t,
                              uint32_t>;

// Per-device cache of program pipelines (lavapipe compiles at the first draw, so a
// pipeline is worth keeping) and the query pool.
struct PatchProgramCache {
  explicit PatchProgramCache(Context& context) : context_(context) {
    auto info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    info.queryCount = 1;
    info.pipelineStatistics = kTessStatisticFlags;
    VkQueryPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateQueryPool(context.device(), &info, nullptr, &pool), "vkCreateQueryPool");
    queries = VkQueryPoolOwner(context.device(), pool);
    vertex = createShaderModule(context.device(), requireEmbeddedShader("gpu/tess_patch.vert"));
  }

  ProgramPipeline& get(const GpuPatchProgram& program, tess::Spacing spacing) {
    const uint32_t binding_count = uint32_t(program.storage_buffers.size()) + 1;
    ProgramKey key{program.control_shader, program.evaluation_shader, program.specialization,
                   int(program.domain), int(spacing), program.input_vertices_per_patch,
                   binding_count};
    if (auto it = programs.find(key); it != programs.end()) return it->second;

    const VkDevice device = context_.device();
    ProgramPipeline p;
    p.binding_count = binding_count;
    const std::vector<VkShaderStageFlags> stages(binding_count, kTessStages);
    p.set_layout = createStorageBufferSetLayout(device, stages);
    p.layout = createPipelineLayout(device, p.set_layout.get(), kTessStages, sizeof(PushBlock));
    const VkShaderModuleOwner control =
        createShaderModule(device, requireEmbeddedShader(program.control_shader));
    const std::vector<uint32_t> tes_spirv = withTessModes(
        requireEmbeddedShader(program.evaluation_shader), {program.domain, spacing, true, false});
    const VkShaderModuleOwner evaluation = createShaderModule(device, tes_spirv);

    std::vector<VkSpecializationMapEntry> entries;
    for (uint32_t i = 0; i < program.specialization.size(); ++i) {
      entries.push_back({i, i * 4u, 4});
    }
    VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(),
                                        program.specialization.size() * 4,
                                        program.specialization.data()};
    VkPipelineShaderStageCreateInfo shader_stages[] = {
        shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex.get()),
        shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, control.get()),
        shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, evaluation.get()),
    };
    if (!entries.empty()) {
      shader_stages[1].pSpecializationInfo = &specialization;
      shader_stages[2].pSpecializationInfo = &specialization;
    }
    p.pipeline = createDiscardTessPipeline(device, p.layout.get(), shader_stages,
                                           program.input_vertices_per_patch,
                                           "vkCreateGraphicsPipelines (patch program)");
    p.descriptors = StorageBufferSet(device, p.set_layout.get(), binding_count);
    return programs.emplace(std::move(key), std::move(p)).first->second;
  }

  Context& context_;
  VkShaderModuleOwner vertex;
  VkQueryPoolOwner queries;
  Buffer capture;
  std::map<ProgramKey, ProgramPipeline> programs;
};

PushBlock pushBlock(const tess::Levels& levels, uint32_t first_patch, bool capture) {
  PushBlock push{};
  for (int i = 0; i < 4; ++i) push.outer_bits[i] = std::bit_cast<uint32_t>(levels.outer[i]);
  for (int i = 0; i < 2; ++i) push.inner_bits[i] = std::bit_cast<uint32_t>(levels.inner[i]);
  push.first_patch = first_patch;
  push.capture_enabled = capture ? 1u : 0u;
  return push;
}

void barrierShaderWritesToHost(VkCommandBuffer cmd) {
  auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TESSELLATION_EVALUATION_SHADER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

// Upper bound of TES invocations of one patch: the CPU tessellator's distinct points,
// doubled (fractional spacing may run the TES twice on one coordinate) plus slack.
uint64_t invocationBound(tess::Domain domain, tess::Spacing spacing, const tess::Levels& levels) {
  const tess::Levels device_levels =
      spacing == tess::Spacing::kPow2 ? tess::roundPow2Levels(domain, levels) : levels;
  const tess::Spacing device_spacing =
      spacing == tess::Spacing::kPow2 ? tess::Spacing::kInteger : spacing;
  const tess::Tessellation t = tess::tessellate(domain, device_spacing, device_levels,
                                                {.point_mode = true, .ccw = true});
  return 2 * t.points.size() + 16;
}

}  // namespace

PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    const tess::Levels& levels,
                                    const PatchProgramOptions& options) {
  context.requireFeatures(tessCaptureFeatures(), "patch program");
  if (program.input_vertices_per_patch == 0 ||
      program.input_vertices_per_patch > context.limits().maxTessellationPatchSize) {
    throw GpuError("patch program " + program.control_shader + ": " +
                   std::to_string(program.input_vertices_per_patch) +
                   " input vertices per patch is outside the device's patch size");
  }
  PatchProgramCache& cache = context.attachment<PatchProgramCache>();
  ProgramPipeline& pipeline = cache.get(program, options.spacing);
  const VkDevice device = context.device();

  // The technique's buffers, bindings 1..N.
  std::vector<Buffer> data;
  for (const std::vector<uint32_t>& words : program.storage_buffers) {
    Buffer buffer(context, std::max<VkDeviceSize>(words.size() * 4, 16),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    buffer.write(words.data(), words.size() * 4);
    data.push_back(std::move(buffer));
  }

  const tess::Levels device_levels =
      options.spacing == tess::Spacing::kPow2 ? tess::roundPow2Levels(program.domain, levels)
                                              : levels;
  const uint64_t per_patch = invocationBound(program.domain, options.spacing, levels);
  const uint32_t first = std::min(options.first_patch, program.patch_count);
  const uint32_t end =
      uint32_t(std::min<uint64_t>(program.patch_count, uint64_t(first) + options.patch_count));
  const uint32_t per_draw = std::max(options.patches_per_draw, 1u);
  const uint64_t max_patches_per_submit = std::max<uint64_t>(
      per_draw, (kMaxCaptureBytesPerSubmit - kCaptureHeaderBytes) / (per_patch * kCaptureWords * 4));

  PatchProgramCapture result;
  auto record = [&](VkCommandBuffer cmd, uint32_t from, uint32_t to, bool capture) {
    vkCmdResetQueryPool(cmd, cache.queries.get(), 0, 1);
    beginDiscardRendering(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline.get());
    const VkDescriptorSet set = pipeline.descriptors.set;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout.get(), 0, 1,
                            &set, 0, nullptr);
    vkCmdBeginQuery(cmd, cache.queries.get(), 0, 0);
    for (uint32_t p = from; p < to; p += per_draw) {
      const uint32_t count = std::min(per_draw, to - p);
      const PushBlock push = pushBlock(device_levels, p, capture);
      vkCmdPushConstants(cmd, pipeline.layout.get(), kTessStages, 0, sizeof(push), &push);
      vkCmdDraw(cmd, count * program.input_vertices_per_patch, 1, 0, 0);
    }
    vkCmdEndQuery(cmd, cache.queries.get(), 0);
    vkCmdEndRendering(cmd);
    barrierShaderWritesToHost(cmd);
  };
  auto bindBuffers = [&]() {
    std::vector<VkBuffer> handles{cache.capture.handle()};
    for (const Buffer& buffer : data) handles.push_back(buffer.handle());
    pipeline.descriptors.bind(device, handles);
  };

  // Warm-up (lavapipe compiles at the first draw), not captured and not counted.
  ensureCapacity(context, cache.capture, kCaptureHeaderBytes + 64,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  bindBuffers();
  if (first < end) {
    context.submitAndWait([&](VkCommandBuffer cmd) { record(cmd, first, first + 1, false); });
  }

  for (uint32_t from = first; from < end;) {
    const uint32_t to = uint32_t(std::min<uint64_t>(end, from + max_patches_per_submit));
    const uint64_t capacity = options.capture ? per_patch * (to - from) : 0;
    const VkDeviceSize bytes = kCaptureHeaderBytes + capacity * kCaptureWords * 4;
    if (cache.capture.sizeBytes() < bytes) {
      ensureCapacity(context, cache.capture, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    bindBuffers();
    const uint32_t header[4] = {0, uint32_t(capacity), 0, 0};
    cache.capture.write(header, sizeof(header));
    result.submit_to_fence_s +=
        context.submitAndWait([&](VkCommandBuffer cmd) { record(cmd, from, to, options.capture); });
    result.draws += (to - from + per_draw - 1) / per_draw;

    uint64_t stats[kTessStatisticCount] = {};
    vkCheck(vkGetQueryPoolResults(device, cache.queries.get(), 0, 1, sizeof(stats), stats,
                                  sizeof(stats), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
    result.stats.vs_invocations += stats[0];
    result.stats.clipping_invocations += stats[1];
    result.stats.clipping_primitives += stats[2];
    result.stats.tcs_patches += stats[3];
    result.stats.tes_invocations += stats[4];

    if (options.capture) {
      uint32_t written = 0;
      cache.capture.read(&written, sizeof(written));
      if (written > capacity) {
        throw GpuError("patch program " + program.evaluation_shader + ": capture overflowed (" +
                       std::to_string(written) + " vertices, room for " +
                       std::to_string(capacity) + ")");
      }
      std::vector<uint32_t> words(size_t(written) * kCaptureWords);
      cache.capture.read(words.data(), words.size() * 4, kCaptureHeaderBytes);
      for (uint32_t i = 0; i < written; ++i) {
        const uint32_t* w = &words[size_t(i) * kCaptureWords];
        CapturedVertex v;
        v.patch = program.patch_ids.empty() ? w[0] : program.patch_ids.at(w[0]);
        for (int k = 0; k < 3; ++k) v.coord[k] = std::bit_cast<float>(w[1 + k]);
        v.position = {std::bit_cast<float>(w[4]), std::bit_cast<float>(w[5]),
                      std::bit_cast<float>(w[6])};
        v.normal = {std::bit_cast<float>(w[7]), std::bit_cast<float>(w[8]),
                    std::bit_cast<float>(w[9])};
        result.vertices.push_back(v);
      }
    }
    from = to;
  }

  auto key = [](const CapturedVertex& v) {
    return std::make_tuple(v.patch, std::bit_cast<uint32_t>(v.coord[0]),
                           std::bit_cast<uint32_t>(v.coord[1]), std::bit_cast<uint32_t>(v.coord[2]));
  };
  std::sort(result.vertices.begin(), result.vertices.end(),
            [&](const CapturedVertex& a, const CapturedVertex& b) { return key(a) < key(b); });
  result.vertices.erase(std::unique(result.vertices.begin(), result.vertices.end(),
                                    [&](const CapturedVertex& a, const CapturedVertex& b) {
                                      return key(a) == key(b);
                                    }),
                        result.vertices.end());
  return result;
}

}  // namespace tb::gpu
