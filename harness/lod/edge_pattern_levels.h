// A fixed, non-uniform set of per-patch tessellation levels for the crack measure: every
// edge gets its own level, yet two patches that share an edge always give it the same
// one, so a watertight technique must stay watertight under it (docs/ARCHITECTURE.md,
// the watertightness rules). It stands in for the adaptive factors of later measures.
#pragma once

#include <vector>

#include "core/tess/tessellator.h"
#include "techniques/technique.h"

namespace tb::lod {

// The pattern. Edge level: base_level times one of kEdgePatternScales, chosen by a hash
// of the edge's two welded end vertices (weldByPosition of the control mesh, applied to
// patchCorners(), as findSharedBoundaries does), taken unordered: the level depends only
// on what the patches on both sides of the edge hold bitwise, never on the patch, its
// corner order or an unwelded seam index. A degenerate edge (both ends weld together)
// gets base_level. The D3D11 helper tess::process{Quad,Tri}TessFactorsAvg (inside scale
// 1) then rounds and clamps the edge levels for `spacing` (a function of each edge's own
// level, so shared edges still agree) and sets the inner level(s) to their average.
// Returns one tess::Levels per patch (levels the domain does not use are 0), in the
// gl_TessLevelOuter order: local edge k (corner k to k + 1, technique.h) is outer[(k + 1)
// % 4] of a quad (u = 0, v = 0, u = 1, v = 1) and outer[(k + 2) % 3] of a triangle.
std::vector<tess::Levels> edgePatternLevels(const techniques::SurfacePatches& patches,
                                            tess::Spacing spacing, float base_level);

// The edge-level multipliers (exact in float, so base 7 gives 3.5, 5.25, 7, 9.625, 12.25:
// fractional levels for the fractional spacings).
inline constexpr float kEdgePatternScales[] = {0.5f, 0.75f, 1.0f, 1.375f, 1.75f};

// The scale index of the edge between welded vertices a and b (symmetric in a, b).
size_t edgePatternScaleIndex(uint32_t a, uint32_t b);

}  // namespace tb::lod
