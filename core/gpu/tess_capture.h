// Runs the fixed-function tessellator of the Vulkan device on single patches and
// captures what the TES sees, as the same struct the CPU tessellator returns
// (core/tess/tessellator.h), so the two compare field by field.
//
// Capture is by transform feedback of gl_TessCoord bits; each draw is one patch with its
// own levels (push constants), because lavapipe's single-threaded tessellator slows down
// super-linearly with many patches per draw. Batches put many draws in one submission.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/gpu/context.h"
#include "core/tess/tessellator.h"

namespace tb::gpu {

// Pipeline statistics of one draw (or of all draws of a throughput run).
struct PipelineStatistics {
  uint64_t vs_invocations = 0;        // one per patch here
  uint64_t clipping_invocations = 0;  // 0 under rasterizer discard on lavapipe
  uint64_t clipping_primitives = 0;   // 0 under rasterizer discard on lavapipe
  uint64_t tcs_patches = 0;           // patches reaching the TCS
  uint64_t tes_invocations = 0;       // = tessellator vertices; 0 when culled. Usually the
                                      // distinct points, but more where fractional spacing
                                      // puts vertices on one 2^-16 coordinate (see below)
  // Triangles the tessellator emitted (VK_EXT_primitives_generated_query), with
  // primitives_counted; 0 and false where the device lacks the query.
  uint64_t primitives_generated = 0;
  bool primitives_counted = false;
};

// points are the distinct gl_TessCoord values (bitwise). Vertices the tessellator emits on
// the same coordinate cannot be told apart in the capture and become one point; then
// stats.tes_invocations > points.size() and some triangles repeat an index. On lavapipe
// this happens with fractional_odd and an inner level <= 1 (the inner ring collapses),
// and with fractional levels just above an even/odd integer (segments < 2^-16 long).
struct GpuTessellation : tess::Tessellation {
  PipelineStatistics stats;      // this patch's draw alone
  double submit_to_fence_s = 0;  // host seconds, submit to fence, of the submission holding
                                 // this draw (shared by all draws of a batched submission)
};

struct GpuTessellationBatch {
  std::vector<GpuTessellation> patches;  // in the order of the levels given
  double submit_to_fence_s = 0;          // all submissions, host seconds
  uint32_t submissions = 0;
};

// Levels are written to gl_TessLevelOuter/Inner bit for bit (NaN and negatives too).
// options.ccw has the CPU tessellator's meaning, counter-clockwise in (u, v) with v up:
// the pipeline uses VK_TESSELLATION_DOMAIN_ORIGIN_LOWER_LEFT (Vulkan's default upper-left
// origin reverses every triangle; the coordinates are the same either way).
// Spacing kPow2 tessellates the levels rounded by tess::roundPow2Levels with equal
// spacing. `culled` is set when the device ran no TES invocation. Throws GpuError if the
// context lacks tessCaptureFeatures() or a Vulkan call fails.
GpuTessellation tessellateOnGpu(Context& context, tess::Domain domain, tess::Spacing spacing,
                                const tess::Levels& levels, const tess::Options& options = {});

// The same for many patches: one draw each, many draws per submission.
GpuTessellationBatch tessellateOnGpuBatch(Context& context, tess::Domain domain,
                                          tess::Spacing spacing,
                                          std::span<const tess::Levels> levels,
                                          const tess::Options& options = {});

struct TessThroughput {
  PipelineStatistics stats;      // summed over all draws
  double submit_to_fence_s = 0;  // host seconds for the one submission
  uint32_t draws = 0;
};

// Draws the same patch draw_count times in one submission with the cheapest TES and no
// capture: the device's tessellation throughput (TES invocations / second).
TessThroughput measureTessThroughput(Context& context, tess::Domain domain, tess::Spacing spacing,
                                     const tess::Levels& levels, uint32_t draw_count,
                                     const tess::Options& options = {});

}  // namespace tb::gpu
