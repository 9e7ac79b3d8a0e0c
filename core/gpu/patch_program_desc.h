// A technique's GPU program as plain data: which embedded shaders, which buffers,
// which switches. Techniques fill it without touching Vulkan; core/gpu/patch_program.h
// runs it. No Vulkan header is needed to include this one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/tess/tessellator.h"

namespace tb::gpu {

struct GpuPatchProgram {
  std::string control_shader;     // embedded path, e.g. "acc/acc.tesc"
  std::string evaluation_shader;  // embedded path, e.g. "acc/acc.tese"
  tess::Domain domain = tess::Domain::kQuad;
  uint32_t patch_count = 0;
  // The SurfacePatches patch of each of this program's patches, when a technique splits
  // its patches over several programs (one per domain: gregory_acc's quads and
  // triangles). Empty: program patch p is SurfacePatches patch p. The shaders still
  // index their own buffers by program patch (tbPatchIndex()); runPatchProgram reports
  // captured vertices under the SurfacePatches patch.
  std::vector<uint32_t> patch_ids;
  // VS invocations per patch (the pipeline's patchControlPoints); the shared vertex
  // shader writes nothing, so the TCS reads its inputs from the storage buffers.
  uint32_t input_vertices_per_patch = 1;
  // Storage buffers at bindings 1..N, as 32-bit words (floats bit-cast).
  std::vector<std::vector<uint32_t>> storage_buffers;
  // Specialisation constants 0..M-1 of both stages (variant switches).
  std::vector<uint32_t> specialization;
};

}  // namespace tb::gpu
