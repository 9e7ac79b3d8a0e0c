// The domain points the crack measure pairs (cracks.h): the boundary points of each
// patch's tessellation, i.e. its corners and the points strictly inside each local edge.
//
// A tessellation depends only on (domain, spacing, levels), never on the technique or
// the asset, so its boundary is computed once per process and shared: a thread-safe
// cache serves every record, spacing and level of a run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/tess/tessellator.h"
#include "techniques/technique.h"

namespace tb::measures {

// The tessellator's 16.16 fixed point: edge parameters are exact multiples of 2^-16.
inline constexpr int64_t kEdgeParameterOne = 1 << 16;

// Edge parameter of domain point `p` on local edge `edge` (from corner edge, t = 0, to
// corner edge + 1, t = 1) in 16.16 fixed point (exact: tessellator coordinates are
// multiples of 2^-16), or -1 when `p` is not on that edge.
int64_t domainEdgeParameter(techniques::PatchDomain domain, uint32_t edge,
                            const tess::DomainPoint& p);
// True when `p` is corner `corner` of the domain.
bool isDomainCorner(techniques::PatchDomain domain, uint32_t corner, const tess::DomainPoint& p);

// The boundary of one tessellation, in a fixed order: corners first (index = corner),
// then each local edge's interior points by ascending edge parameter t.
struct BoundaryTessellation {
  bool culled = false;  // no points at all (some outer level culls the patch)
  std::vector<tess::DomainPoint> points;
  // Edge e's interior points are points[edge_begin[e], edge_begin[e + 1]); corners() =
  // edge_begin[0].
  std::vector<uint32_t> edge_begin;
  std::vector<int64_t> edge_t;      // per point: its edge parameter in 16.16 (0 for corners)
  uint64_t tessellated_points = 0;  // every domain point (the TES invocations at these levels)
  // Levels that give exactly the same boundary points (bit for bit, same order) with
  // fewer interior ones: each inner level lowered to at most 1 (integer, pow2), 2
  // (fractional_even) or 3 (fractional_odd) when the CPU tessellator (bit-exact with
  // lavapipe) shows the boundary unchanged, else the levels themselves. The edge points
  // follow the outer levels alone except in the degenerate fractional_odd rings, which
  // the check catches.
  tess::Levels capture_levels;
  uint64_t capture_points = 0;  // every domain point under capture_levels

  uint32_t corners() const { return edge_begin.empty() ? 0 : edge_begin.front(); }
  // Index of edge e's interior point at edge parameter t, or -1.
  int64_t edgePoint(uint32_t edge, int64_t t) const;
  // Index of boundary point `p` (a corner or an edge point, bitwise), or -1.
  int64_t indexOf(techniques::PatchDomain domain, const tess::DomainPoint& p) const;
};

// The boundary of tessellate(domain, spacing, levels), from the process-wide cache.
// Thread-safe. Throws std::logic_error when a tessellation lacks one of its corners.
std::shared_ptr<const BoundaryTessellation> boundaryTessellation(techniques::PatchDomain domain,
                                                                 tess::Spacing spacing,
                                                                 const tess::Levels& levels);

// Every patch's boundary points under its own levels, and where each patch's points start
// in one flat array (positions are stored per boundary point: [at(patch, k)]).
struct PatchBoundaries {
  std::vector<std::shared_ptr<const BoundaryTessellation>> tessellations;  // distinct ones
  std::vector<uint32_t> tessellation;           // per patch: index into tessellations
  std::vector<techniques::PatchDomain> domain;  // per patch
  std::vector<size_t> offset;                   // per patch, then the total
  size_t culled_patches = 0;                    // patches whose levels cull them

  const BoundaryTessellation& of(size_t patch) const { return *tessellations[tessellation[patch]]; }
  size_t at(size_t patch, size_t k) const { return offset[patch] + k; }
  size_t size() const { return offset.back(); }
};

// patch_levels: one per patch (patch_levels.size() == patches.patchCount()).
PatchBoundaries patchBoundaries(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                                std::span<const tess::Levels> patch_levels);

}  // namespace tb::measures
