// Tessellation without the tessellator: a technique's surface on the compute path. One
// submission runs the compute tessellator's passes (compute_tessellator.h), a pass writing
// the indirect commands, the technique's compute shader as a build pass (one invocation a
// patch: the TCS's work) and an evaluate pass (one a domain point: the TES's), then an
// indexed indirect draw counted by a statistics query, with no read-back between them. The
// stages and the compute shader include the same surface code, so the vertices are bitwise
// the TES capture's (docs/ARCHITECTURE.md §6, "The compute path").
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/gpu/patch_program.h"

namespace tb::gpu {

class Context;

struct ComputePathOptions {
  tess::Spacing spacing = tess::Spacing::kInteger;
  bool draw = true;  // record the indirect draw and its statistics query
  // The tests' broken control (compute_surface.glsl): 0 none; 1 evaluate at u one float ulp
  // up inside the domain (the records keep the true coordinate), as a conversion from
  // 16.16 that rounds differently would.
  uint32_t control = 0;
};

struct ComputePathResult {
  // As PatchProgramCapture::vertices: SurfacePatches patch (patch_ids applied), coordinate
  // bits, position, normal; sorted by (patch, coordinate bits), duplicates kept once.
  std::vector<CapturedVertex> vertices;
  uint64_t points = 0;           // domain points evaluated (records in the vertex buffer)
  uint64_t index_words = 0;      // in the index buffer: 3 a triangle
  bool draw_counted = false;     // the device counted the draw (pipeline statistics)
  uint64_t drawn_triangles = 0;  // the draw's input-assembly primitives
  uint64_t drawn_vertices = 0;   // the draw's vertex-shader invocations (post-transform
                                 // cache reuse makes it at most index_words)
  // Transient device bytes the path allocated for its output, sized by the levels' upper
  // bounds: the vertex buffer (40 bytes a point) and the index buffer (4 a word).
  uint64_t vertex_buffer_bytes = 0;
  uint64_t index_buffer_bytes = 0;
  double submit_to_fence_s = 0;  // host seconds of the one submission
};

// The pipelines and buffers of one program at fixed levels, made once; run() re-runs the
// whole submission (for benchmarks), read() reads the vertices back.
class ComputePath {
 public:
  // Throws GpuError when the program has no compute shader, is a displaced build (the
  // compute path does not displace yet), has more than 7 storage buffers,
  // patch_levels.size() != program.patch_count, the levels' point or index bound exceeds the
  // device's storage buffer range (no splitting into batches yet), or the device lacks a
  // feature.
  ComputePath(Context& context, const GpuPatchProgram& program,
              std::span<const tess::Levels> patch_levels, const ComputePathOptions& options = {});
  ~ComputePath();
  ComputePath(const ComputePath&) = delete;
  ComputePath& operator=(const ComputePath&) = delete;

  // One submission: every pass and the draw. Returns host seconds, submit to fence.
  double run();
  // The last run's vertices, counts and statistics. Throws GpuError when a tessellator
  // kernel raised an error bit.
  ComputePathResult read() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Builds, runs once and reads back.
ComputePathResult runComputePath(Context& context, const GpuPatchProgram& program,
                                 std::span<const tess::Levels> patch_levels,
                                 const ComputePathOptions& options = {});
// Uniform levels: the same `levels` for every patch.
ComputePathResult runComputePath(Context& context, const GpuPatchProgram& program,
                                 const tess::Levels& levels,
                                 const ComputePathOptions& options = {});

}  // namespace tb::gpu
