// The crack measure's GPU half: the technique's own TCS + TES on the Vulkan device,
// capturing by SSBO only what pairing needs, the boundary points of every patch
// (core/gpu/patch_program.h, boundary_only), into the flat PatchBoundaries order.
//
// Cost, on lavapipe: the shaders' and the tessellator's work, a few percent more for the
// capture writes and the host's reading, never a CPU evaluation per vertex. By default
// the device runs each patch under its BoundaryTessellation::capture_levels (the same
// boundary points, fewer interior ones): at level 64 about 16 times fewer invocations.
// bench/technique_gpu_bench.cpp times this function against the shaders without capture.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpu/patch_program_desc.h"
#include "core/mesh/vec.h"
#include "harness/measures/common/cracks/crack_boundaries.h"
#include "techniques/technique.h"

namespace tb::measures {

struct CrackCaptureOptions {
  // Run the device under each patch's capture_levels; false: under its own levels (the
  // full interior too, for comparison; the captured boundary is the same either way).
  bool lower_inner_levels = true;
  // Captured vertices held on the host at once (one runPatchProgram call per chunk of
  // patches): bounds memory whatever the patch count.
  uint64_t max_vertices_per_call = 1u << 20;
  // The compute path (core/gpu/compute_path.h) in place of the TCS + TES: every domain point
  // under the same levels is evaluated by the technique's compute shader, and the boundary
  // points among them are kept.
  bool compute_path = false;
};

struct BoundaryCapture {
  std::vector<mesh::Vec3f> positions;  // per boundary point, [boundaries.at(patch, k)]
  uint64_t points_captured = 0;  // distinct (patch, gl_TessCoord) captured = boundaries.size()
  // Domain points the device tessellated, summed over patches: the CPU tessellator's
  // count under the levels the device ran, which lavapipe's TES invocation statistic
  // matches (docs/ARCHITECTURE.md §6; the capture runs without a statistics query, whose
  // read-back costs more than a small draw).
  uint64_t tes_invocations = 0;
  double submit_to_fence_s = 0;  // host seconds from submit to fence, summed
  uint32_t draws = 0;
  uint32_t calls = 0;  // runPatchProgram calls (chunks)
};

// Runs `programs` (patches.gpuPrograms(), built once by the caller) over their patches
// under `patch_levels` (one per patch) and `spacing`, and stores each captured boundary
// position. `boundaries` must be patchBoundaries(patches, spacing, patch_levels); a culled
// patch (the crack sample's left-out patches) has no boundary point to capture. Throws
// gpu::GpuError when the device fails, and std::runtime_error when the capture lacks a boundary
// point the CPU tessellator emits or holds one it does not.
BoundaryCapture captureBoundaryPositions(const techniques::SurfacePatches& patches,
                                         std::span<const gpu::GpuPatchProgram> programs,
                                         const PatchBoundaries& boundaries, tess::Spacing spacing,
                                         std::span<const tess::Levels> patch_levels,
                                         gpu::Context& context,
                                         const CrackCaptureOptions& options = {});

}  // namespace tb::measures
