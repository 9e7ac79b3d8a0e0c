#include "harness/lod/edge_pattern_levels.h"

#include <algorithm>
#include <array>
#include <iterator>

#include "core/mesh/topology.h"
#include "core/tess/factor_helpers.h"

namespace tb::lod {

size_t edgePatternScaleIndex(uint32_t a, uint32_t b) {
  const uint32_t lo = std::min(a, b), hi = std::max(a, b);
  // A small integer mix (golden-ratio multipliers) so neighbouring edges differ.
  uint32_t h = lo * 0x9E3779B1u ^ (hi + 0x7F4A7C15u) * 0x85EBCA77u;
  h ^= h >> 16;
  return h % std::size(kEdgePatternScales);
}

std::vector<tess::Levels> edgePatternLevels(const techniques::SurfacePatches& patches,
                                            tess::Spacing spacing, float base_level) {
  const mesh::Welding welding = mesh::weldByPosition(patches.controlMesh());
  std::vector<tess::Levels> levels(patches.patchCount());
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const std::array<uint32_t, 4> raw = patches.patchCorners(p);
    const bool quad = patches.patchDomain(p) == techniques::PatchDomain::kQuad;
    const uint32_t corners = quad ? 4 : 3;
    std::array<float, 4> edges{};  // gl_TessLevelOuter order
    for (uint32_t k = 0; k < corners; ++k) {
      const uint32_t a = welding.canonical.at(raw[k]);
      const uint32_t b = welding.canonical.at(raw[(k + 1) % corners]);
      const float scale = a == b ? 1.0f : kEdgePatternScales[edgePatternScaleIndex(a, b)];
      edges[quad ? (k + 1) % 4 : (k + 2) % 3] = base_level * scale;
    }
    levels[p] =
        quad
            ? tess::processQuadTessFactorsAvg(spacing, edges, 1.0f).rounded
            : tess::processTriTessFactorsAvg(spacing, {edges[0], edges[1], edges[2]}, 1.0f).rounded;
  }
  return levels;
}

}  // namespace tb::lod
