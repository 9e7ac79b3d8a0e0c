#include "core/gpu/patch_program.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <map>
#include <optional>

#include "core/gpu/buffer.h"
#include "core/gpu/context.h"
#include "core/gpu/patch_program_pipeline.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/sampled_image.h"
#include "core/gpu/tess_pipelines.h"
#include "core/gpu/vk_handle.h"
#include "core/tess/factor_helpers.h"
#include "shaders/common/layout/capture_layout.h"
#include "shaders/common/layout/levels_layout.h"

namespace tb::gpu {
namespace {

// Whether malloc is AddressSanitizer's (GCC defines __SANITIZE_ADDRESS__; clang has the feature).
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitizedAllocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitizedAllocator = true;
#else
constexpr bool kSanitizedAllocator = false;
#endif
#else
constexpr bool kSanitizedAllocator = false;
#endif

// Set 1's per-patch levels (shaders/common/layout/levels_layout.h).
using PatchLevelsBits = layout::TbPatchLevels;
// The levels the TCS writes back per patch (TbFactorOut), 6 of them used.
constexpr size_t kFactorOutWords = layout::kTbFactorOutWordsPerPatch;

constexpr uint32_t kCaptureWords = kCaptureRecordWords;
constexpr VkDeviceSize kCaptureHeaderBytes =
    sizeof(layout::TbCapture);  // count, capacity, 2 reserved
constexpr VkDeviceSize kMaxCaptureBytesPerSubmit = 64ull << 20;

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

bool onBoundary(tess::Domain domain, const tess::DomainPoint& p) {
  if (domain == tess::Domain::kQuad) return p[0] == 0 || p[0] == 1 || p[1] == 0 || p[1] == 1;
  return p[0] == 0 || p[1] == 0 || p[2] == 0;
}

// Upper bound of the vertices one patch captures: the CPU tessellator's distinct points
// (on the boundary only, when that is all that is captured), doubled (fractional spacing
// may run the TES twice on one coordinate) plus slack.
uint64_t captureBound(tess::Domain domain, tess::Spacing spacing, const tess::Levels& device_levels,
                      bool boundary_only) {
  const tess::Spacing device_spacing =
      spacing == tess::Spacing::kPow2 ? tess::Spacing::kInteger : spacing;
  const tess::Tessellation t =
      tess::tessellate(domain, device_spacing, device_levels, {.point_mode = true, .ccw = true});
  const uint64_t points =
      boundary_only ? uint64_t(std::count_if(t.points.begin(), t.points.end(),
                                             [&](const auto& p) { return onBoundary(domain, p); }))
                    : t.points.size();
  return 2 * points + 16;
}

// captureBound of patches [first, end), one tessellation per distinct level set.
std::vector<uint64_t> captureBounds(tess::Domain domain, tess::Spacing spacing,
                                    std::span<const tess::Levels> device_levels, uint32_t first,
                                    uint32_t end, bool boundary_only) {
  std::map<tess::LevelsBits, uint64_t> by_levels;
  std::vector<uint64_t> bounds;
  bounds.reserve(end - first);
  for (uint32_t p = first; p < end; ++p) {
    const tess::LevelsBits key = tess::levelsBits(device_levels[p]);
    auto it = by_levels.find(key);
    if (it == by_levels.end()) {
      it = by_levels.emplace(key, captureBound(domain, spacing, device_levels[p], boundary_only))
               .first;
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

// Copies the program's storage buffers into `buffers` (grown as needed); returns the
// bytes each binding covers (16 at least: a zero-sized range is invalid).
std::vector<VkDeviceSize> uploadStorageBuffers(Context& context, const GpuPatchProgram& program,
                                               std::vector<Buffer>* buffers) {
  if (buffers->size() < program.storage_buffers.size()) {
    buffers->resize(program.storage_buffers.size());
  }
  std::vector<VkDeviceSize> ranges;
  for (size_t i = 0; i < program.storage_buffers.size(); ++i) {
    const std::vector<uint32_t>& words = program.storage_buffers[i];
    const VkDeviceSize bytes = std::max<VkDeviceSize>(words.size() * 4, 16);
    ensureCapacity(context, (*buffers)[i], bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    (*buffers)[i].write(words.data(), words.size() * 4);
    ranges.push_back(bytes);
  }
  return ranges;
}

// Writes the per-patch levels into `buffer` (grown as needed); returns the bytes written.
VkDeviceSize uploadPatchLevels(Context& context, std::span<const tess::Levels> device_levels,
                               Buffer* buffer) {
  const size_t count = std::max<size_t>(device_levels.size(), 1);
  const VkDeviceSize bytes = count * sizeof(PatchLevelsBits);
  ensureCapacity(context, *buffer, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  PatchLevelsBits* bits = buffer->as<PatchLevelsBits>().data();
  for (size_t p = 0; p < device_levels.size(); ++p) {
    const tess::LevelsBits key = tess::levelsBits(device_levels[p]);
    PatchLevelsBits entry{};
    entry.outer_bits = {key[0], key[1], key[2], key[3]};
    entry.inner_bits = {key[4], key[5], 0, 0};
    bits[p] = entry;
  }
  return bytes;
}

// Copies `words` into `buffer` (grown as needed; 16 bytes at least); returns the range.
VkDeviceSize uploadWords(Context& context, std::span<const uint32_t> words, Buffer* buffer) {
  const VkDeviceSize bytes = std::max<VkDeviceSize>(words.size() * 4, 16);
  ensureCapacity(context, *buffer, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  if (!words.empty()) buffer->write(words.data(), words.size() * 4);
  return bytes;
}

// Everything one call draws with.
struct DrawSetup {
  const ProgramPipeline& pipeline;
  VkQueryPool queries = VK_NULL_HANDLE;
  VkQueryPool primitives = VK_NULL_HANDLE;  // with queries, when the device counts primitives
  // set 0 (capture + data), set 1 (levels), set 2 (displacement, when the program has one)
  VkDescriptorSet sets[3] = {};
  uint32_t set_count = 2;
  uint32_t input_vertices_per_patch = 1;
  uint32_t per_draw = 1;
  // Non-empty (PatchProgramOptions::skip_culled): per program patch, 1 when its levels cull
  // it; those patches are not drawn.
  std::vector<uint8_t> culled;
};

// Whether `levels` cull a patch of `domain`: a relevant outer level <= 0 or NaN.
bool cullsPatch(tess::Domain domain, const tess::Levels& levels) {
  const size_t outer = domain == tess::Domain::kQuad       ? 4
                       : domain == tess::Domain::kTriangle ? 3
                                                           : 2;
  for (size_t i = 0; i < outer; ++i) {
    if (!(levels.outer[i] > 0)) return true;
  }
  return false;
}

// Draws patches [from, to), `per_draw` patches per draw (runs of drawn patches, when
// setup.culled leaves some out), inside one statistics query (none when setup.queries is
// null). Returns the draws.
uint32_t recordDraws(VkCommandBuffer cmd, const DrawSetup& setup, uint32_t from, uint32_t to,
                     bool capture) {
  const VkPipelineLayout layout = setup.pipeline.layout.get();
  const bool query = setup.queries != VK_NULL_HANDLE;
  const bool count_primitives = query && setup.primitives != VK_NULL_HANDLE;
  if (query) vkCmdResetQueryPool(cmd, setup.queries, 0, 1);
  if (count_primitives) vkCmdResetQueryPool(cmd, setup.primitives, 0, 1);
  beginDiscardRendering(cmd);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, setup.pipeline.pipeline.get());
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, setup.set_count,
                          setup.sets, 0, nullptr);
  if (query) vkCmdBeginQuery(cmd, setup.queries, 0, 0);
  if (count_primitives) vkCmdBeginQuery(cmd, setup.primitives, 0, 0);
  uint32_t draws = 0;
  const auto drawn = [&](uint32_t p) { return setup.culled.empty() || !setup.culled[p]; };
  for (uint32_t p = from; p < to;) {
    if (!drawn(p)) {
      ++p;
      continue;
    }
    uint32_t count = 1;
    while (count < setup.per_draw && p + count < to && drawn(p + count)) ++count;
    const PushBlock push{p, capture ? 1u : 0u};
    vkCmdPushConstants(cmd, layout, kTessStages, 0, sizeof(push), &push);
    vkCmdDraw(cmd, count * setup.input_vertices_per_patch, 1, 0, 0);
    ++draws;
    p += count;
  }
  if (count_primitives) vkCmdEndQuery(cmd, setup.primitives, 0);
  if (query) vkCmdEndQuery(cmd, setup.queries, 0);
  vkCmdEndRendering(cmd);
  barrierShaderWritesToHost(cmd);
  return draws;
}

void addStatistics(VkDevice device, VkQueryPool queries, VkQueryPool primitives,
                   PipelineStatistics* stats) {
  if (primitives != VK_NULL_HANDLE) {
    uint64_t generated = 0;
    vkCheck(
        vkGetQueryPoolResults(device, primitives, 0, 1, sizeof(generated), &generated,
                              sizeof(generated), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults (primitives generated)");
    stats->primitives_generated += generated;
    stats->primitives_counted = true;
  }
  uint64_t values[kTessStatisticCount] = {};
  // The fence has signalled, so the results are available; lavapipe's WAIT path costs
  // ~0.1 ms a call even then, so it is only the fallback.
  const VkResult ready = vkGetQueryPoolResults(device, queries, 0, 1, sizeof(values), values,
                                               sizeof(values), VK_QUERY_RESULT_64_BIT);
  if (ready == VK_NOT_READY) {
    vkCheck(vkGetQueryPoolResults(device, queries, 0, 1, sizeof(values), values, sizeof(values),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
  } else {
    vkCheck(ready, "vkGetQueryPoolResults");
  }
  stats->vs_invocations += values[0];
  stats->clipping_invocations += values[1];
  stats->clipping_primitives += values[2];
  stats->tcs_patches += values[3];
  stats->tes_invocations += values[4];
}

// Appends the vertices the last submission captured (room for `capacity`), read in place
// from the mapped buffer.
void readCapture(const Buffer& capture, const GpuPatchProgram& program, uint64_t capacity,
                 std::vector<CapturedVertex>* vertices) {
  uint32_t written = 0;
  capture.read(&written, sizeof(written));
  if (written > capacity) {
    throw GpuError("patch program " + program.evaluation_shader + ": capture overflowed (" +
                   std::to_string(written) + " vertices, room for " + std::to_string(capacity) +
                   ")");
  }
  const std::span<const uint32_t> words = capture.as<const uint32_t>().subspan(
      kCaptureHeaderBytes / 4, size_t(written) * kCaptureWords);
  appendCaptureRecords(words, program.patch_ids, vertices);
}

// kTbCaptureBoundary for these options.
uint32_t captureBoundary(const GpuPatchProgram& program, const PatchProgramOptions& options) {
  if (!options.capture || !options.boundary_only) return kCaptureEvery;
  switch (program.domain) {
    case tess::Domain::kQuad:
      return kCaptureQuadBoundary;
    case tess::Domain::kTriangle:
      return kCaptureTriangleBoundary;
    default:
      throw GpuError("patch program " + program.evaluation_shader +
                     ": an isoline patch has no boundary to capture");
  }
}

void checkProgram(const Context& context, const GpuPatchProgram& program, size_t level_count,
                  const TcsFactorPolicy* policy, const TcsCullPolicy* cull) {
  if (program.input_vertices_per_patch == 0 ||
      program.input_vertices_per_patch > context.limits().maxTessellationPatchSize) {
    throw GpuError("patch program " + program.control_shader + ": " +
                   std::to_string(program.input_vertices_per_patch) +
                   " input vertices per patch is outside the device's patch size");
  }
  if (policy != nullptr &&
      policy->corner_words.size() != size_t(program.patch_count) * kTcsFactorPatchWords) {
    throw GpuError("patch program " + program.control_shader + ": factor policy corners for " +
                   std::to_string(policy->corner_words.size() / kTcsFactorPatchWords) +
                   " patches, the program has " + std::to_string(program.patch_count));
  }
  if (cull != nullptr &&
      cull->patch_words.size() != size_t(program.patch_count) * kTcsCullPatchWords) {
    throw GpuError("patch program " + program.control_shader + ": culling bounds for " +
                   std::to_string(cull->patch_words.size() / kTcsCullPatchWords) +
                   " patches, the program has " + std::to_string(program.patch_count));
  }
  if (level_count != program.patch_count) {
    throw GpuError("patch program " + program.control_shader + ": " + std::to_string(level_count) +
                   " per-patch levels for " + std::to_string(program.patch_count) + " patches");
  }
}

// The levels the device is given for each patch (deviceLevels).
std::vector<tess::Levels> deviceLevelsOf(const GpuPatchProgram& program, tess::Spacing spacing,
                                         std::span<const tess::Levels> patch_levels) {
  std::vector<tess::Levels> device_levels;
  device_levels.reserve(patch_levels.size());
  for (const tess::Levels& levels : patch_levels) {
    device_levels.push_back(deviceLevels(program.domain, spacing, levels));
  }
  return device_levels;
}

// The call's sets 0 and 1 for `pipeline`, allocated the first time these resources draw
// with it.
const CallResources::PipelineSets& pipelineSets(VkDevice device, const ProgramPipeline& pipeline,
                                                CallResources& resources) {
  auto [sets, first_use] = resources.sets.try_emplace(&pipeline);
  if (first_use) {
    sets->second.data = StorageBufferSet(device, pipeline.set_layout.get(), pipeline.binding_count);
    sets->second.levels =
        StorageBufferSet(device, pipeline.levels_set_layout.get(), kLevelsSetBindings);
  }
  return sets->second;
}

// Set 1: uploads the per-patch levels, the factor policy's corners and parameters, a zeroed
// output for the levels the TCS writes (`out_words`), and the culling policy's words; binds
// them.
void bindLevelsSet(Context& context, CallResources& resources, const StorageBufferSet& set,
                   std::span<const tess::Levels> device_levels, const TcsFactorPolicy* policy,
                   const TcsCullPolicy* cull, size_t out_words) {
  const VkDeviceSize levels_range = uploadPatchLevels(context, device_levels, &resources.levels);
  const std::span<const uint32_t> no_words;
  const VkDeviceSize corners_range = uploadWords(
      context, policy ? std::span(policy->corner_words) : no_words, &resources.factor_corners);
  const VkDeviceSize params_range = uploadWords(
      context, policy ? std::span(policy->param_words) : no_words, &resources.factor_params);
  const std::vector<uint32_t> zero_out(out_words, 0u);
  const VkDeviceSize out_range = uploadWords(context, zero_out, &resources.factor_out);
  const VkDeviceSize cull_params_range =
      uploadWords(context, cull ? std::span(cull->param_words) : no_words, &resources.cull_params);
  const VkDeviceSize cull_patches_range =
      uploadWords(context, cull ? std::span(cull->patch_words) : no_words, &resources.cull_patches);
  const VkDeviceSize cull_tangent_range = uploadWords(
      context, cull ? std::span(cull->tangent_words) : no_words, &resources.cull_tangent);
  VkBuffer handles[kLevelsSetBindings] = {};
  VkDeviceSize ranges[kLevelsSetBindings] = {};
  const auto put = [&](layout::Binding binding, const Buffer& buffer, VkDeviceSize range) {
    handles[binding] = buffer.handle();
    ranges[binding] = range;
  };
  put(layout::kBindingLevels, resources.levels, levels_range);
  put(layout::kBindingFactorPatches, resources.factor_corners, corners_range);
  put(layout::kBindingFactorParams, resources.factor_params, params_range);
  put(layout::kBindingFactorOut, resources.factor_out, out_range);
  put(layout::kBindingCullParams, resources.cull_params, cull_params_range);
  put(layout::kBindingCullPatches, resources.cull_patches, cull_patches_range);
  put(layout::kBindingCullTangentPlanes, resources.cull_tangent, cull_tangent_range);
  set.bind(context.device(), handles, ranges);
}

// Binds set 0 to the current capture buffer (again whenever it grows) and the program's
// storage buffers.
void bindDataSet(VkDevice device, const CallResources& resources, const StorageBufferSet& set,
                 std::span<const VkDeviceSize> data_ranges) {
  std::vector<VkBuffer> handles{resources.capture.handle()};
  std::vector<VkDeviceSize> ranges{VK_WHOLE_SIZE};
  for (size_t i = 0; i < data_ranges.size(); ++i) {
    handles.push_back(resources.data[i].handle());
    ranges.push_back(data_ranges[i]);
  }
  set.bind(device, handles, ranges);
}

// Set 2: the displacement map and its words, which live for one call only.
struct CallDisplacement {
  std::optional<SampledImage> image;
  Buffer words;
  DisplacementSet set;
};

void bindDisplacement(Context& context, const GpuPatchProgram& program,
                      const ProgramPipeline& pipeline, CallDisplacement* displacement) {
  if (!program.displacement) return;
  const GpuDisplacement& d = *program.displacement;
  if (!d.texels) throw GpuError("patch program " + program.evaluation_shader + ": no texels");
  displacement->image.emplace(context, floatImageFormat(d.channels, d.bytes_per_channel), d.width,
                              d.height, *d.texels);
  uploadWords(context, d.patch_words, &displacement->words);
  displacement->set = DisplacementSet(context.device(), pipeline.displacement_set_layout.get(),
                                      *displacement->image, displacement->words);
}

// Warm-up, once per pipeline (lavapipe compiles at the first draw): not captured and
// not counted.
void warmUp(Context& context, ProgramPipeline& pipeline, const DrawSetup& setup, uint32_t first,
            uint32_t end) {
  if (first < end && !pipeline.warmed.load()) {
    context.submitAndWait(
        [&](VkCommandBuffer cmd) { recordDraws(cmd, setup, first, first + 1, false); });
    pipeline.warmed.store(true);
  }
}

// The patches one draw takes: `requested`, fewer under AddressSanitizer when their capture
// bounds would pass kMaxCaptureBoundPerDraw. Mesa's draw module (lavapipe's tessellation)
// grows a draw's output with one realloc per patch; ASan's realloc never grows in place, so
// there a draw's host work grows with the square of its output, and once the output passes
// the allocator's 128 KiB size classes each realloc maps fresh pages (Culling's acceptance
// test: 1001 s with 64 patches a draw, 193 s with this cap). How patches are split into
// draws changes no figure: each draw carries its first patch's index (tbPatchIndex).
uint32_t patchesPerDraw(uint32_t requested, std::span<const uint64_t> bounds) {
  if (!kSanitizedAllocator) return requested;
  constexpr uint64_t kMaxCaptureBoundPerDraw = 256;
  const uint64_t largest = bounds.empty() ? 1 : *std::max_element(bounds.begin(), bounds.end());
  return uint32_t(std::clamp<uint64_t>(kMaxCaptureBoundPerDraw / largest, 1, requested));
}

// Draws patches [first, end) in submissions whose captures fit, reading back each one's
// capture and statistics into `result`.
void drawPatches(Context& context, const GpuPatchProgram& program,
                 const PatchProgramOptions& options, const DrawSetup& setup_in,
                 std::span<const tess::Levels> device_levels, uint32_t first, uint32_t end,
                 bool boundary_only, CallResources& resources, const StorageBufferSet& data_set,
                 std::span<const VkDeviceSize> data_ranges, PatchProgramCapture* result) {
  const VkDevice device = context.device();
  const std::vector<uint64_t> bounds =
      captureBounds(program.domain, options.spacing, device_levels, first, end, boundary_only);
  DrawSetup setup = setup_in;
  setup.per_draw = patchesPerDraw(setup_in.per_draw, bounds);
  for (const SubmitRange& range : planSubmits(first, bounds, setup.per_draw, options.capture)) {
    const VkDeviceSize bytes = kCaptureHeaderBytes + range.capacity * kCaptureWords * 4;
    if (resources.capture.sizeBytes() < bytes) {
      ensureCapacity(context, resources.capture, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      bindDataSet(device, resources, data_set, data_ranges);
    }
    const uint32_t header[4] = {0, uint32_t(range.capacity), 0, 0};
    resources.capture.write(header, sizeof(header));
    result->submit_to_fence_s += context.submitAndWait([&](VkCommandBuffer cmd) {
      result->draws += recordDraws(cmd, setup, range.from, range.to, options.capture);
    });
    if (options.statistics) addStatistics(device, setup.queries, setup.primitives, &result->stats);
    if (options.capture) readCapture(resources.capture, program, range.capacity, &result->vertices);
  }
}

// The levels the TCS wrote, 6 of each patch's 8 words.
void readTcsLevels(const CallResources& resources, const GpuPatchProgram& program,
                   PatchProgramCapture* result) {
  std::vector<uint32_t> written(size_t(program.patch_count) * kFactorOutWords);
  resources.factor_out.read(written.data(), written.size() * 4);
  result->tcs_levels.resize(program.patch_count);
  for (size_t p = 0; p < program.patch_count; ++p) {
    std::copy_n(&written[p * kFactorOutWords], 6, result->tcs_levels[p].begin());
  }
}

}  // namespace

PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    std::span<const tess::Levels> patch_levels,
                                    const PatchProgramOptions& options) {
  context.requireFeatures(tessCaptureFeatures(), "patch program");
  const TcsFactorPolicy* policy = options.factor_policy;
  const TcsCullPolicy* cull = options.cull_policy;
  checkProgram(context, program, patch_levels.size(), policy, cull);
  const uint32_t boundary = captureBoundary(program, options);
  PatchProgramCache& cache = context.attachment<PatchProgramCache>();
  ProgramPipeline& pipeline =
      cache.get(program, options.spacing, boundary, policy ? 1u : 0u, cull ? 1u : 0u);
  const bool read_levels = policy != nullptr || cull != nullptr;
  const CallResourcesLease lease(cache);
  CallResources& resources = *lease;
  const VkDevice device = context.device();

  const std::vector<tess::Levels> device_levels =
      deviceLevelsOf(program, options.spacing, patch_levels);
  const std::vector<VkDeviceSize> data_ranges =
      uploadStorageBuffers(context, program, &resources.data);
  const CallResources::PipelineSets& sets = pipelineSets(device, pipeline, resources);
  bindLevelsSet(context, resources, sets.levels, device_levels, policy, cull,
                read_levels ? size_t(program.patch_count) * kFactorOutWords : 0);

  const uint32_t first = std::min(options.first_patch, program.patch_count);
  const uint32_t end =
      uint32_t(std::min<uint64_t>(program.patch_count, uint64_t(first) + options.patch_count));
  CallDisplacement displacement;
  bindDisplacement(context, program, pipeline, &displacement);
  DrawSetup setup{pipeline,
                  options.statistics ? resources.queries.get() : VK_NULL_HANDLE,
                  options.statistics ? resources.primitives.get() : VK_NULL_HANDLE,
                  {sets.data.set, sets.levels.set, displacement.set.set},
                  program.displacement ? 3u : 2u,
                  program.input_vertices_per_patch,
                  std::max(options.patches_per_draw, 1u),
                  {}};

  if (options.skip_culled) {
    for (const tess::Levels& levels : device_levels) {
      setup.culled.push_back(cullsPatch(program.domain, levels) ? 1 : 0);
    }
  }
  ensureCapacity(context, resources.capture, kCaptureHeaderBytes + 64,
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  bindDataSet(device, resources, sets.data, data_ranges);
  warmUp(context, pipeline, setup, first, end);

  PatchProgramCapture result;
  drawPatches(context, program, options, setup, device_levels, first, end,
              boundary != kCaptureEvery, resources, sets.data, data_ranges, &result);
  if (options.sort) sortUniqueVertices(&result.vertices);
  if (read_levels) readTcsLevels(resources, program, &result);
  return result;
}

PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    const tess::Levels& levels,
                                    const PatchProgramOptions& options) {
  const std::vector<tess::Levels> patch_levels(program.patch_count, levels);
  return runPatchProgram(context, program, patch_levels, options);
}

}  // namespace tb::gpu
