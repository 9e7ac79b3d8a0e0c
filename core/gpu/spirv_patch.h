// Rewrites a tessellation evaluation shader's execution modes in its SPIR-V. Domain,
// spacing and winding cannot be specialisation constants, and compiling 36 GLSL variants
// at build time would couple the shader list to this harness; the modes are single
// words in OpExecutionMode instructions, so one compiled TES serves every pipeline.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/tess/tessellator.h"

namespace tb::gpu {

struct TessModes {
  tess::Domain domain = tess::Domain::kTriangle;
  // kPow2 maps to SpacingEqual: the host rounds the levels (tess::roundPow2Levels).
  tess::Spacing spacing = tess::Spacing::kInteger;
  bool ccw = true;
  bool point_mode = false;
};

// `spirv` must be a TES declaring exactly one domain, one spacing and one vertex-order
// mode (glslang always emits them for `layout(triangles, equal_spacing, ccw) in;`).
// Any PointMode is dropped and re-added per `modes`. Throws GpuError otherwise.
std::vector<uint32_t> withTessModes(std::span<const uint32_t> spirv, const TessModes& modes);

}  // namespace tb::gpu
