// A fixed, non-uniform set of per-patch tessellation levels for the crack measure: every
// edge gets its own level, yet two patches that share an edge always give it the same
// one, so a watertight technique must stay watertight under it (docs/ARCHITECTURE.md,
// the watertightness rules). It stands in for the adaptive factors of later measures.
#pragma once

#include <vector>

#include "core/tess/tessellator.h"
#include "techniques/technique.h"

namespace tb::lod {

// The pattern. Edge level: base_level times one of kEdgePatternScales, by a hash of the
// edge's two welded end vertices taken unordered, so it depends only on what both sides hold
// bitwise (a degenerate edge gets base_level). tess::process{Quad,Tri}TessFactorsAvg then
// rounds and clamps each edge for `spacing` and averages the inside. Returns one tess::Levels
// per patch in gl_TessLevelOuter order: local edge k is outer[(k + 1) % 4] of a quad and
// outer[(k + 2) % 3] of a triangle (unused levels 0).
std::vector<tess::Levels> edgePatternLevels(const techniques::SurfacePatches& patches,
                                            tess::Spacing spacing, float base_level);

// The edge-level multipliers (exact in float, so base 7 gives 3.5, 5.25, 7, 9.625, 12.25:
// fractional levels for the fractional spacings).
inline constexpr float kEdgePatternScales[] = {0.5f, 0.75f, 1.0f, 1.375f, 1.75f};

// The scale index of the edge between welded vertices a and b (symmetric in a, b).
size_t edgePatternScaleIndex(uint32_t a, uint32_t b);

}  // namespace tb::lod
