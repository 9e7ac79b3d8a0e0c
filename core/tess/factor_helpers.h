// The D3D11 HLSL tessellation-factor helpers (Process*TessFactors*), as library
// functions for the factor policies, and the pow2 rounding the HLSL layer applies.
// Behaviour follows the HLSL intrinsic reference pages (learn.microsoft.com,
// "ProcessTriTessFactorsAvg" etc.) and the reference tessellator's HLSL layer that
// those intrinsics stand for. Edge order is the HLSL SV_TessFactor order, which is
// also gl_TessLevelOuter's: triangle u = 0, v = 0, w = 0; quad u = 0, v = 0, u = 1, v = 1.
#pragma once

#include <array>

#include "core/tess/tessellator.h"

namespace tb::tess {

struct ProcessedFactors {
  // RoundedEdgeTessFactors in outer, RoundedInsideTessFactor(s) in inner, ready for
  // tessellate() with the same spacing. Levels the domain does not use are 0; a culled
  // patch (any raw edge factor not > 0, NaN included) has every level 0.
  // Isoline: outer[0] = rounded density, outer[1] = rounded detail.
  Levels rounded{{0, 0, 0, 0}, {0, 0}};
  // UnroundedInsideTessFactor(s): the inside factor after reduction, InsideScale and
  // clamping but before rounding (0 for isolines and culled patches).
  std::array<float, 2> unrounded_inner{0, 0};
};

// Triangle: inside = average / maximum / minimum of the three edges, times InsideScale
// (clamped to [0, 1]). Edges are rounded per spacing (integer: up; pow2: up to a power
// of two) and clamped to the spacing's range.
ProcessedFactors processTriTessFactorsAvg(Spacing spacing, const std::array<float, 3>& raw_edges,
                                          float inside_scale);
ProcessedFactors processTriTessFactorsMax(Spacing spacing, const std::array<float, 3>& raw_edges,
                                          float inside_scale);
ProcessedFactors processTriTessFactorsMin(Spacing spacing, const std::array<float, 3>& raw_edges,
                                          float inside_scale);

// Quad, one inside factor for both axes from all four edges.
ProcessedFactors processQuadTessFactorsAvg(Spacing spacing, const std::array<float, 4>& raw_edges,
                                           float inside_scale);
ProcessedFactors processQuadTessFactorsMax(Spacing spacing, const std::array<float, 4>& raw_edges,
                                           float inside_scale);
ProcessedFactors processQuadTessFactorsMin(Spacing spacing, const std::array<float, 4>& raw_edges,
                                           float inside_scale);

// Quad, each inside axis from the two edges parallel to it (inside u from v = 0 and
// v = 1; inside v from u = 0 and u = 1), each with its own scale.
ProcessedFactors process2DQuadTessFactorsAvg(Spacing spacing, const std::array<float, 4>& raw_edges,
                                             const std::array<float, 2>& inside_scale);
ProcessedFactors process2DQuadTessFactorsMax(Spacing spacing, const std::array<float, 4>& raw_edges,
                                             const std::array<float, 2>& inside_scale);
ProcessedFactors process2DQuadTessFactorsMin(Spacing spacing, const std::array<float, 4>& raw_edges,
                                             const std::array<float, 2>& inside_scale);

// Isoline: the detail factor is clamped and rounded per spacing (pow2 included); the
// density is always clamped to [1, 64] and rounded up to an integer.
ProcessedFactors processIsolineTessFactors(Spacing spacing, float raw_detail, float raw_density);

// pow2 partitioning for the Vulkan path (which has no pow2 spacing): each level the
// domain uses is clamped to [1, 64] and rounded up to a power of two, so that
// equal_spacing then tessellates exactly like D3D pow2. Outer levels that cull
// (not > 0, NaN included) are passed through unchanged so the patch still culls; the
// isoline density (outer[0]) is left alone because the tessellator rounds it to an
// integer, not to a power of two. Unused levels are copied.
Levels roundPow2Levels(Domain domain, const Levels& levels);

}  // namespace tb::tess
