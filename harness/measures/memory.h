// Measure 2 (DESIGN.md): memory footprint against plain triangle meshes.
#pragma once

#include <cstdint>
#include <vector>

#include "techniques/technique.h"

namespace tb {

inline const std::vector<uint32_t> kMemoryLevels{8, 16, 32, 64};

// One uniform tessellation level. All byte counts are resident GPU buffer sizes.
struct MemoryFigures {
  uint32_t level = 0;
  // The equivalent plain triangle mesh: the technique's output at this level,
  // welded (points on shared edges stored once, seams duplicated), each vertex
  // float3 position + float3 normal + float2 uv (32 B), 32-bit indices.
  uint64_t plain_vertices = 0;
  uint64_t plain_triangles = 0;
  uint64_t plain_bytes = 0;
  // The technique's own data (control mesh + patch data + stencils), independent
  // of the level.
  DataFootprint technique;
  // A 16-bit scalar displacement map sized for the level: one texel per
  // tessellated point of each patch, (n+1)^2 per quad, (n+1)(n+2)/2 per triangle
  // (two triangles share a square tile), no mip chain.
  uint64_t displacement_bytes = 0;
  uint64_t technique_with_displacement_bytes = 0;
  // plain_bytes / technique_with_displacement_bytes: above 1 the technique is the
  // smaller one. Seed 000 reports about 8 (943 MB against 118 MB at level 64).
  double plain_over_technique = 0;
};

MemoryFigures measureMemory(const SurfacePatches& patches, uint32_t level);

}  // namespace tb
