#include "core/gpu/patch_program.h"

#include <algorithm>
#include <array>
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
  uint32_t first_patch;
  uint32_t capture_enabled;
};
static_assert(sizeof(PushBlock) == 8);

// TbPatchLevels in shaders/common/patch_program_tcs.glsl: float bits, 32 bytes per patch.
struct PatchLevelsBits {
  uint32_t outer_bits[4];
  uint32_t inner_bits[2];
  uint32_t unused[2];
};
static_assert(sizeof(PatchLevelsBits) == 32);

constexpr uint32_t kCaptureWords = 10;            // kTbCaptureWords
constexpr VkDeviceSize kCaptureHeaderBytes = 16;  // count, capacity, 2 reserved
constexpr VkDeviceSize kMaxCaptureBytesPerSubmit = 64ull << 20;
constexpr VkShaderStageFlags kTessStages =
    VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;

// One compiled program: its descriptor layouts (set 0: capture + the technique's
// buffers; set 1: per-patch levels), pipeline and descriptor sets.
struct ProgramPipeline {
  VkDescriptorSetLayoutOwner set_layout;
  VkDescriptorSetLayoutOwner levels_set_layout;
  VkPipelineLayoutOwner layout;
  VkPipelineOwner pipeline;
  StorageBufferSet descriptors;
  StorageBufferSet levels_descriptors;
  uint32_t binding_count = 0;
};

using ProgramKey =
    std::tuple<std::string, std::string, std::vector<uint32_t>, int, int, uint32_t, uint32_t>;

VkPipelineOwner createProgramPipeline(VkDevice device, const GpuPatchProgram& program,
                                      tess::Spacing spacing, VkShaderModule vertex,
                                      VkPipelineLayout layout) {
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
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, control.get()),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, evaluation.get()),
  };
  if (!entries.empty()) {
    shader_stages[1].pSpecializationInfo = &specialization;
    shader_stages[2].pSpecializationInfo = &specialization;
  }
  return createDiscardTessPipeline(device, layout, shader_stages, program.input_vertices_per_patch,
                                   "vkCreateGraphicsPipelines (patch program)");
}

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
    ProgramKey key{program.control_shader, program.evaluation_shader,
                   program.specialization, int(program.domain),
                   int(spacing),           program.input_vertices_per_patch,
                   binding_count};
    if (auto it = programs.find(key); it != programs.end()) return it->second;

    const VkDevice device = context_.device();
    ProgramPipeline p;
    p.binding_count = binding_count;
    const std::vector<VkShaderStageFlags> stages(binding_count, kTessStages);
    p.set_layout = createStorageBufferSetLayout(device, stages);
    const VkShaderStageFlags levels_stage[] = {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT};
    p.levels_set_layout = createStorageBufferSetLayout(device, levels_stage);
    const VkDescriptorSetLayout set_layouts[] = {p.set_layout.get(), p.levels_set_layout.get()};
    p.layout = createPipelineLayout(device, set_layouts, kTessStages, sizeof(PushBlock));
    p.pipeline = createProgramPipeline(device, program, spacing, vertex.get(), p.layout.get());
    p.descriptors = StorageBufferSet(device, p.set_layout.get(), binding_count);
    p.levels_descriptors = StorageBufferSet(device, p.levels_set_layout.get(), 1);
    return programs.emplace(std::move(key), std::move(p)).first->second;
  }

  Context& context_;
  VkShaderModuleOwner vertex;
  VkQueryPoolOwner queries;
  Buffer capture;
  std::map<ProgramKey, ProgramPipeline> programs;
};

void barrierShaderWritesToHost(VkCommandBuffer cmd) {
  auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TESSELLATION_EVALUATION_SHADER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

// The levels the device is given: pow2 spacing has no Vulkan equivalent, so its levels
// are rounded up to powers of two and the pipeline uses equal spacing.
tess::Levels deviceLevels(tess::Domain domain, tess::Spacing spacing, const tess::Levels& levels) {
  return spacing == tess::Spacing::kPow2 ? tess::roundPow2Levels(domain, levels) : levels;
}

// Upper bound of TES invocations of one patch: the CPU tessellator's distinct points,
// doubled (fractional spacing may run the TES twice on one coordinate) plus slack.
uint64_t invocationBound(tess::Domain domain, tess::Spacing spacing,
                         const tess::Levels& device_levels) {
  const tess::Spacing device_spacing =
      spacing == tess::Spacing::kPow2 ? tess::Spacing::kInteger : spacing;
  const tess::Tessellation t =
      tess::tessellate(domain, device_spacing, device_levels, {.point_mode = true, .ccw = true});
  return 2 * t.points.size() + 16;
}

// invocationBound of patches [first, end), one tessellation per distinct level set.
std::vector<uint64_t> invocationBounds(tess::Domain domain, tess::Spacing spacing,
                                       std::span<const tess::Levels> device_levels, uint32_t first,
                                       uint32_t end) {
  std::map<tess::LevelsBits, uint64_t> by_levels;
  std::vector<uint64_t> bounds;
  bounds.reserve(end - first);
  for (uint32_t p = first; p < end; ++p) {
    const tess::LevelsBits key = tess::levelsBits(device_levels[p]);
    auto it = by_levels.find(key);
    if (it == by_levels.end()) {
      it = by_levels.emplace(key, invocationBound(domain, spacing, device_levels[p])).first;
    }
    bounds.push_back(it->second);
  }
  return bounds;
}

// Patches [from, to) captured by one submission, with room for `capacity` vertices.
struct SubmitRange {
  uint32_t from = 0, to = 0;
  uint64_t capacity = 0;
};

// Splits [first, first + bounds.size()) so each submission's capture stays under
// kMaxCaptureBytesPerSubmit (at least `per_draw` patches each).
std::vector<SubmitRange> planSubmits(uint32_t first, std::span<const uint64_t> bounds,
                                     uint32_t per_draw, bool capture) {
  const uint64_t max_vertices =
      (kMaxCaptureBytesPerSubmit - kCaptureHeaderBytes) / (kCaptureWords * 4);
  std::vector<SubmitRange> ranges;
  const uint32_t end = first + uint32_t(bounds.size());
  for (uint32_t from = first; from < end;) {
    SubmitRange range{from, from, 0};
    while (range.to < end && (range.to - from < per_draw ||
                              range.capacity + bounds[range.to - first] <= max_vertices)) {
      range.capacity += bounds[range.to - first];
      ++range.to;
    }
    if (!capture) range.capacity = 0;
    ranges.push_back(range);
    from = range.to;
  }
  return ranges;
}

std::vector<Buffer> uploadStorageBuffers(Context& context, const GpuPatchProgram& program) {
  std::vector<Buffer> buffers;
  for (const std::vector<uint32_t>& words : program.storage_buffers) {
    Buffer buffer(context, std::max<VkDeviceSize>(words.size() * 4, 16),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    buffer.write(words.data(), words.size() * 4);
    buffers.push_back(std::move(buffer));
  }
  return buffers;
}

Buffer uploadPatchLevels(Context& context, std::span<const tess::Levels> device_levels) {
  std::vector<PatchLevelsBits> bits(std::max<size_t>(device_levels.size(), 1));
  for (size_t p = 0; p < device_levels.size(); ++p) {
    const tess::LevelsBits key = tess::levelsBits(device_levels[p]);
    std::copy(key.begin(), key.begin() + 4, bits[p].outer_bits);
    std::copy(key.begin() + 4, key.end(), bits[p].inner_bits);
  }
  Buffer buffer(context, bits.size() * sizeof(PatchLevelsBits), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  buffer.write(bits.data(), bits.size() * sizeof(PatchLevelsBits));
  return buffer;
}

// Everything one call draws with.
struct DrawSetup {
  const PatchProgramCache& cache;
  const ProgramPipeline& pipeline;
  uint32_t input_vertices_per_patch = 1;
  uint32_t per_draw = 1;
};

// Draws patches [from, to), `per_draw` patches per draw, inside one statistics query.
void recordDraws(VkCommandBuffer cmd, const DrawSetup& setup, uint32_t from, uint32_t to,
                 bool capture) {
  const VkQueryPool queries = setup.cache.queries.get();
  const VkPipelineLayout layout = setup.pipeline.layout.get();
  vkCmdResetQueryPool(cmd, queries, 0, 1);
  beginDiscardRendering(cmd);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, setup.pipeline.pipeline.get());
  const VkDescriptorSet sets[] = {setup.pipeline.descriptors.set,
                                  setup.pipeline.levels_descriptors.set};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 2, sets, 0, nullptr);
  vkCmdBeginQuery(cmd, queries, 0, 0);
  for (uint32_t p = from; p < to; p += setup.per_draw) {
    const uint32_t count = std::min(setup.per_draw, to - p);
    const PushBlock push{p, capture ? 1u : 0u};
    vkCmdPushConstants(cmd, layout, kTessStages, 0, sizeof(push), &push);
    vkCmdDraw(cmd, count * setup.input_vertices_per_patch, 1, 0, 0);
  }
  vkCmdEndQuery(cmd, queries, 0);
  vkCmdEndRendering(cmd);
  barrierShaderWritesToHost(cmd);
}

void addStatistics(VkDevice device, VkQueryPool queries, PipelineStatistics* stats) {
  uint64_t values[kTessStatisticCount] = {};
  vkCheck(vkGetQueryPoolResults(device, queries, 0, 1, sizeof(values), values, sizeof(values),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
  stats->vs_invocations += values[0];
  stats->clipping_invocations += values[1];
  stats->clipping_primitives += values[2];
  stats->tcs_patches += values[3];
  stats->tes_invocations += values[4];
}

// Appends the vertices the last submission captured (room for `capacity`).
void readCapture(const Buffer& capture, const GpuPatchProgram& program, uint64_t capacity,
                 std::vector<CapturedVertex>* vertices) {
  uint32_t written = 0;
  capture.read(&written, sizeof(written));
  if (written > capacity) {
    throw GpuError("patch program " + program.evaluation_shader + ": capture overflowed (" +
                   std::to_string(written) + " vertices, room for " + std::to_string(capacity) +
                   ")");
  }
  std::vector<uint32_t> words(size_t(written) * kCaptureWords);
  capture.read(words.data(), words.size() * 4, kCaptureHeaderBytes);
  for (uint32_t i = 0; i < written; ++i) {
    const uint32_t* w = &words[size_t(i) * kCaptureWords];
    CapturedVertex v;
    v.patch = program.patch_ids.empty() ? w[0] : program.patch_ids.at(w[0]);
    for (int k = 0; k < 3; ++k) v.coord[k] = std::bit_cast<float>(w[1 + k]);
    v.position = {std::bit_cast<float>(w[4]), std::bit_cast<float>(w[5]),
                  std::bit_cast<float>(w[6])};
    v.normal = {std::bit_cast<float>(w[7]), std::bit_cast<float>(w[8]), std::bit_cast<float>(w[9])};
    vertices->push_back(v);
  }
}

// Sorts by (patch, coord bits) and keeps one of each.
void sortUnique(std::vector<CapturedVertex>* vertices) {
  auto key = [](const CapturedVertex& v) {
    return std::make_tuple(v.patch, std::bit_cast<uint32_t>(v.coord[0]),
                           std::bit_cast<uint32_t>(v.coord[1]),
                           std::bit_cast<uint32_t>(v.coord[2]));
  };
  std::sort(vertices->begin(), vertices->end(),
            [&](const CapturedVertex& a, const CapturedVertex& b) { return key(a) < key(b); });
  vertices->erase(std::unique(vertices->begin(), vertices->end(),
                              [&](const CapturedVertex& a, const CapturedVertex& b) {
                                return key(a) == key(b);
                              }),
                  vertices->end());
}

void checkProgram(const Context& context, const GpuPatchProgram& program, size_t level_count) {
  if (program.input_vertices_per_patch == 0 ||
      program.input_vertices_per_patch > context.limits().maxTessellationPatchSize) {
    throw GpuError("patch program " + program.control_shader + ": " +
                   std::to_string(program.input_vertices_per_patch) +
                   " input vertices per patch is outside the device's patch size");
  }
  if (level_count != program.patch_count) {
    throw GpuError("patch program " + program.control_shader + ": " + std::to_string(level_count) +
                   " per-patch levels for " + std::to_string(program.patch_count) + " patches");
  }
}

}  // namespace

PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    std::span<const tess::Levels> patch_levels,
                                    const PatchProgramOptions& options) {
  context.requireFeatures(tessCaptureFeatures(), "patch program");
  checkProgram(context, program, patch_levels.size());
  PatchProgramCache& cache = context.attachment<PatchProgramCache>();
  ProgramPipeline& pipeline = cache.get(program, options.spacing);
  const VkDevice device = context.device();

  std::vector<tess::Levels> device_levels;
  device_levels.reserve(patch_levels.size());
  for (const tess::Levels& levels : patch_levels) {
    device_levels.push_back(deviceLevels(program.domain, options.spacing, levels));
  }
  const std::vector<Buffer> data = uploadStorageBuffers(context, program);
  const Buffer levels_buffer = uploadPatchLevels(context, device_levels);
  const VkBuffer levels_handle = levels_buffer.handle();
  pipeline.levels_descriptors.bind(device, std::span(&levels_handle, 1));
  auto bindBuffers = [&]() {
    std::vector<VkBuffer> handles{cache.capture.handle()};
    for (const Buffer& buffer : data) handles.push_back(buffer.handle());
    pipeline.descriptors.bind(device, handles);
  };

  const uint32_t first = std::min(options.first_patch, program.patch_count);
  const uint32_t end =
      uint32_t(std::min<uint64_t>(program.patch_count, uint64_t(first) + options.patch_count));
  const DrawSetup setup{cache, pipeline, program.input_vertices_per_patch,
                        std::max(options.patches_per_draw, 1u)};

  // Warm-up (lavapipe compiles at the first draw), not captured and not counted.
  ensureCapacity(context, cache.capture, kCaptureHeaderBytes + 64,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  bindBuffers();
  if (first < end) {
    context.submitAndWait(
        [&](VkCommandBuffer cmd) { recordDraws(cmd, setup, first, first + 1, false); });
  }

  PatchProgramCapture result;
  const std::vector<uint64_t> bounds =
      invocationBounds(program.domain, options.spacing, device_levels, first, end);
  for (const SubmitRange& range : planSubmits(first, bounds, setup.per_draw, options.capture)) {
    const VkDeviceSize bytes = kCaptureHeaderBytes + range.capacity * kCaptureWords * 4;
    if (cache.capture.sizeBytes() < bytes) {
      ensureCapacity(context, cache.capture, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    bindBuffers();
    const uint32_t header[4] = {0, uint32_t(range.capacity), 0, 0};
    cache.capture.write(header, sizeof(header));
    result.submit_to_fence_s += context.submitAndWait([&](VkCommandBuffer cmd) {
      recordDraws(cmd, setup, range.from, range.to, options.capture);
    });
    result.draws += (range.to - range.from + setup.per_draw - 1) / setup.per_draw;
    addStatistics(device, cache.queries.get(), &result.stats);
    if (options.capture) readCapture(cache.capture, program, range.capacity, &result.vertices);
  }
  sortUnique(&result.vertices);
  return result;
}

PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    const tess::Levels& levels,
                                    const PatchProgramOptions& options) {
  const std::vector<tess::Levels> patch_levels(program.patch_count, levels);
  return runPatchProgram(context, program, patch_levels, options);
}

}  // namespace tb::gpu
