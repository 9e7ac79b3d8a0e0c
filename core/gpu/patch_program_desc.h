// A technique's GPU program as plain data: which embedded shaders, which buffers,
// which switches. Techniques fill it without touching Vulkan; core/gpu/patch_program.h
// runs it. No Vulkan header is needed to include this one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/tess/tessellator.h"
#include "shaders/common/layout/bindings.h"

namespace tb::gpu {

// A displacement map the TES samples after evaluating the surface (shaders/common/
// displace.glsl, set 2): a real sampled image read with texelFetch, and the per-patch owner
// and direction words (techniques/common/displaced_patches.h).
struct GpuDisplacement {
  uint32_t width = 0, height = 0;  // texels
  uint32_t channels = 1;           // 1 (R, scalar map) or 4 (RGBA, vector map; A unused)
  uint32_t bytes_per_channel = 4;  // 2: 16-bit float channels, 4: 32-bit float
  std::shared_ptr<const std::vector<std::byte>> texels;  // rows from the top, packed
  std::vector<uint32_t> patch_words;                     // TbDisplacePatches at set 2, binding 1
  uint32_t kind = 1;                                     // kTbDisplaceKind: 1 scalar, 2 vector
  uint32_t sampling = 0;  // kTbDisplaceSampling: 0 naive, 1 watertight
};

struct GpuPatchProgram {
  std::string control_shader;     // embedded path, e.g. "acc/acc.tesc"
  std::string evaluation_shader;  // embedded path, e.g. "acc/acc.tese"
  // The compute twin of the control and evaluation shaders (core/gpu/compute_path.h): an
  // embedded .comp that includes the technique's surface functions and
  // shaders/common/compute_surface.glsl, so it runs the TCS's and TES's float operations
  // without the tessellator, e.g. "acc/acc.comp". Empty: the program has no compute path.
  std::string compute_shader;
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
  // Storage buffers at bindings 1..N, as 32-bit words (floats bit-cast); setStorageBuffer
  // fills them by binding.
  std::vector<std::vector<uint32_t>> storage_buffers;
  // Specialisation constants 0..M-1 of both stages (variant switches).
  std::vector<uint32_t> specialization;
  // Non-null: the evaluation shader is a "#displaced" build that samples this map.
  std::shared_ptr<const GpuDisplacement> displacement;
};

// Puts `words` at set 0, binding `binding` (>= layout::kBindingFirstTechnique) of `program`.
inline void setStorageBuffer(GpuPatchProgram& program, uint32_t binding,
                             std::vector<uint32_t> words) {
  const size_t index = binding - layout::kBindingFirstTechnique;
  if (program.storage_buffers.size() <= index) program.storage_buffers.resize(index + 1);
  program.storage_buffers[index] = std::move(words);
}

}  // namespace tb::gpu
