#include "core/gpu/tess_capture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>

#include "core/gpu/buffer.h"
#include "core/gpu/tess_pipelines.h"
#include "core/gpu/tess_weld.h"
#include "core/gpu/vk_handle.h"
#include "core/tess/factor_helpers.h"

namespace tb::gpu {
namespace {

constexpr VkDeviceSize kCaptureStrideBytes = sizeof(CoordBits);  // uvec3 per TES vertex
// A submission's capture space and draw count; bounded so memory stays small and a
// batch of level-64 patches still submits ~150 draws at a time.
constexpr VkDeviceSize kMaxCaptureBytesPerSubmit = 48ull << 20;
constexpr uint32_t kMaxDrawsPerSubmit = 1024;
constexpr uint32_t kCounterNotWritten = 0xffffffffu;

// Per-device buffers and queries, reused by every call; `mutex` makes calls from several
// threads take turns.
struct CaptureResources {
  explicit CaptureResources(Context& context) {
    auto info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    info.queryCount = kMaxDrawsPerSubmit;
    info.pipelineStatistics = kTessStatisticFlags;
    VkQueryPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateQueryPool(context.device(), &info, nullptr, &pool), "vkCreateQueryPool");
    queries = VkQueryPoolOwner(context.device(), pool);
    counters = Buffer(context, kMaxDrawsPerSubmit * sizeof(uint32_t),
                      VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT);
  }
  std::mutex mutex;  // held for a whole call
  Buffer capture;
  Buffer counters;  // bytes written per draw, from vkCmdEndTransformFeedbackEXT
  VkQueryPoolOwner queries;
};

std::span<const float> relevantLevels(tess::Domain domain, const tess::Levels& levels,
                                      float (&scratch)[6]) {
  switch (domain) {
    case tess::Domain::kTriangle:
      std::copy_n(levels.outer.begin(), 3, scratch);
      scratch[3] = levels.inner[0];
      return {scratch, 4};
    case tess::Domain::kQuad:
      std::copy_n(levels.outer.begin(), 4, scratch);
      std::copy_n(levels.inner.begin(), 2, scratch + 4);
      return {scratch, 6};
    case tess::Domain::kIsoline:
      std::copy_n(levels.outer.begin(), 2, scratch);
      return {scratch, 2};
  }
  return {};
}

// Upper bound of one patch's captured bytes. With at most S segments on any edge or ring
// (S = clamped level rounded up, +2 for the odd/even parity and inner-level fix-ups), a
// quad emits <= 2 S^2 triangles, a triangle fewer, an isoline <= S^2 lines and point mode
// <= (S+1)^2 points; 6 S^2 vertices cover all of them for S >= 3.
VkDeviceSize captureCapacityBytes(tess::Domain domain, const tess::Levels& levels) {
  float scratch[6];
  float max_level = 1.0f;
  for (float level : relevantLevels(domain, levels, scratch)) {
    if (level > max_level) max_level = level;  // false for NaN
  }
  const VkDeviceSize segments =
      static_cast<VkDeviceSize>(std::ceil(std::min(max_level, 64.0f))) + 2;
  return 6 * segments * segments * kCaptureStrideBytes;
}

uint32_t verticesPerPrimitive(tess::Domain domain, const tess::Options& options) {
  if (options.point_mode) return 1;
  return domain == tess::Domain::kIsoline ? 2 : 3;
}

PipelineStatistics toStatistics(const uint64_t* values) {
  return {values[0], values[1], values[2], values[3], values[4]};
}

void barrierCaptureToHost(VkCommandBuffer cmd) {
  auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT |
                          VK_ACCESS_TRANSFORM_FEEDBACK_COUNTER_WRITE_BIT_EXT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

std::vector<uint64_t> readStatistics(Context& context, VkQueryPool pool, uint32_t count) {
  std::vector<uint64_t> values(size_t{count} * kTessStatisticCount);
  vkCheck(vkGetQueryPoolResults(context.device(), pool, 0, count, values.size() * sizeof(uint64_t),
                                values.data(), kTessStatisticCount * sizeof(uint64_t),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
  return values;
}

// One submission: draws [0, levels.size()) each into its own capture range.
struct Submission {
  std::span<const tess::Levels> levels;
  std::vector<VkDeviceSize> offsets;     // into CaptureResources::capture
  std::vector<VkDeviceSize> capacities;  // bytes
};

double recordAndSubmit(Context& context, TessPipelines& pipelines, CaptureResources& resources,
                       VkPipeline pipeline, const Submission& submission) {
  const uint32_t draws = static_cast<uint32_t>(submission.levels.size());
  std::memset(resources.counters.data(), 0xff, draws * sizeof(uint32_t));
  const XfbCommands& xfb = pipelines.xfb();
  return context.submitAndWait([&](VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, resources.queries.get(), 0, draws);
    beginDiscardRendering(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const VkBuffer capture = resources.capture.handle();
    const VkBuffer counters = resources.counters.handle();
    for (uint32_t i = 0; i < draws; ++i) {
      pipelines.pushLevels(cmd, submission.levels[i]);
      xfb.bind(cmd, 0, 1, &capture, &submission.offsets[i], &submission.capacities[i]);
      vkCmdBeginQuery(cmd, resources.queries.get(), i, 0);
      xfb.begin(cmd, 0, 0, nullptr, nullptr);
      vkCmdDraw(cmd, 1, 1, 0, 0);
      const VkDeviceSize counter_offset = i * sizeof(uint32_t);
      xfb.end(cmd, 0, 1, &counters, &counter_offset);
      vkCmdEndQuery(cmd, resources.queries.get(), i);
    }
    vkCmdEndRendering(cmd);
    barrierCaptureToHost(cmd);
  });
}

GpuTessellation readPatch(const CaptureResources& resources, const Submission& submission,
                          uint32_t draw, uint32_t vertices_per_primitive,
                          std::vector<CoordBits>& scratch) {
  const uint32_t bytes = resources.counters.as<uint32_t>()[draw];
  if (bytes == kCounterNotWritten || bytes >= submission.capacities[draw]) {
    throw GpuError("transform-feedback capture overflowed or was not written");
  }
  scratch.resize(bytes / kCaptureStrideBytes);
  resources.capture.read(scratch.data(), scratch.size() * kCaptureStrideBytes,
                         submission.offsets[draw]);
  GpuTessellation patch;
  static_cast<tess::Tessellation&>(patch) = weldCapture(scratch, vertices_per_primitive);
  return patch;
}

}  // namespace

GpuTessellationBatch tessellateOnGpuBatch(Context& context, tess::Domain domain,
                                          tess::Spacing spacing,
                                          std::span<const tess::Levels> levels,
                                          const tess::Options& options) {
  CaptureResources& resources = context.attachment<CaptureResources>();
  const std::lock_guard lock(resources.mutex);
  TessPipelines& pipelines = context.attachment<TessPipelines>();
  const VkPipeline pipeline =
      pipelines.get({domain, spacing, options.ccw, options.point_mode}, TessOutput::kCapture);
  std::vector<tess::Levels> device_levels(levels.begin(), levels.end());
  if (spacing == tess::Spacing::kPow2) {
    for (tess::Levels& l : device_levels) l = tess::roundPow2Levels(domain, l);
  }
  const uint32_t vertices_per_primitive = verticesPerPrimitive(domain, options);

  GpuTessellationBatch batch;
  batch.patches.reserve(levels.size());
  std::vector<CoordBits> scratch;
  for (size_t first = 0; first < device_levels.size();) {
    Submission submission;
    VkDeviceSize total = 0;
    size_t end = first;
    while (end < device_levels.size() && end - first < kMaxDrawsPerSubmit) {
      const VkDeviceSize capacity = captureCapacityBytes(domain, device_levels[end]);
      if (end > first && total + capacity > kMaxCaptureBytesPerSubmit) break;
      submission.offsets.push_back(total);
      submission.capacities.push_back(capacity);
      total += capacity;
      ++end;
    }
    submission.levels = std::span(device_levels).subspan(first, end - first);
    ensureCapacity(context, resources.capture, total,
                   VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT);

    const double seconds = recordAndSubmit(context, pipelines, resources, pipeline, submission);
    const uint32_t draws = static_cast<uint32_t>(end - first);
    const std::vector<uint64_t> stats = readStatistics(context, resources.queries.get(), draws);
    for (uint32_t i = 0; i < draws; ++i) {
      GpuTessellation patch = readPatch(resources, submission, i, vertices_per_primitive, scratch);
      patch.stats = toStatistics(&stats[size_t{i} * kTessStatisticCount]);
      patch.culled = patch.stats.tes_invocations == 0;
      patch.submit_to_fence_s = seconds;
      batch.patches.push_back(std::move(patch));
    }
    batch.submit_to_fence_s += seconds;
    ++batch.submissions;
    first = end;
  }
  return batch;
}

GpuTessellation tessellateOnGpu(Context& context, tess::Domain domain, tess::Spacing spacing,
                                const tess::Levels& levels, const tess::Options& options) {
  GpuTessellationBatch batch =
      tessellateOnGpuBatch(context, domain, spacing, std::span(&levels, 1), options);
  return std::move(batch.patches.front());
}

TessThroughput measureTessThroughput(Context& context, tess::Domain domain, tess::Spacing spacing,
                                     const tess::Levels& levels, uint32_t draw_count,
                                     const tess::Options& options) {
  CaptureResources& resources = context.attachment<CaptureResources>();
  const std::lock_guard lock(resources.mutex);
  TessPipelines& pipelines = context.attachment<TessPipelines>();
  const VkPipeline pipeline =
      pipelines.get({domain, spacing, options.ccw, options.point_mode}, TessOutput::kPlain);
  const tess::Levels device_levels =
      spacing == tess::Spacing::kPow2 ? tess::roundPow2Levels(domain, levels) : levels;
  const VkQueryPool pool = resources.queries.get();

  TessThroughput result;
  result.draws = draw_count;
  result.submit_to_fence_s = context.submitAndWait([&](VkCommandBuffer cmd) {
    vkCmdResetQueryPool(cmd, pool, 0, 1);
    beginDiscardRendering(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    pipelines.pushLevels(cmd, device_levels);
    vkCmdBeginQuery(cmd, pool, 0, 0);
    for (uint32_t i = 0; i < draw_count; ++i) vkCmdDraw(cmd, 1, 1, 0, 0);
    vkCmdEndQuery(cmd, pool, 0);
    vkCmdEndRendering(cmd);
  });
  result.stats = toStatistics(readStatistics(context, pool, 1).data());
  return result;
}

}  // namespace tb::gpu
