// The tessellator's transition rings, measured once per domain and spacing for the
// error_bound factor policy (factor_policy.h): the widest triangle, in the domain, when one
// outer edge has level o and every other level is n. D3D11's stitch (core/tess/stitch.cpp)
// makes triangles up to ~3.5 edge segments wide, which a regular grid's bound (Filip,
// Magedson & Markot) misses; a triangle of extents du, dv has chord error at most
// ((M_uu + M_uv) du^2 + (M_vv + M_uv) dv^2) / 8. Derivation: docs/derivations/transition_rings.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tess/tessellator.h"

namespace tb::lod {

// Levels 1..kTransitionLevels index the table (fractional_odd's largest level is 63; its
// level-64 entries repeat 63's).
inline constexpr uint32_t kTransitionLevels = 64;
// Per (edge, o, n): the widest triangle's extent along u, along v, and the largest squared
// radius of a triangle's smallest enclosing circle in (u, v) (kTransitionCircle).
inline constexpr uint32_t kTransitionAxes = 3;
inline constexpr uint32_t kTransitionCircle = 2;

// The table's index of (edge e, axis, edge level o, inside level n): e in gl_TessLevelOuter
// order, axis 0 = u, 1 = v (a triangle's barycentric u and v), 2 = kTransitionCircle, o and
// n in 1..64.
inline constexpr size_t transitionIndex(uint32_t e, uint32_t axis, uint32_t o, uint32_t n) {
  return ((size_t(e) * kTransitionAxes + axis) * kTransitionLevels + (o - 1)) * kTransitionLevels +
         (n - 1);
}

// The whole levels at which `spacing`'s segments are all equal (integer: every one; pow2:
// powers of two; fractional_odd: odd; fractional_even: even): the levels error_bound takes.
// At other whole levels a fractional spacing has two short segments and stitches its rings
// to an equal edge with wider triangles.
bool equalSegmentLevel(uint32_t level, tess::Spacing spacing);

// The equalSegmentLevel levels error_bound gives an edge: a family in which any two levels
// stitch to a common inside level no wider than the coarser one's regular pattern (integer
// 1, 2, 3, 5, 9, 17, 33, 64; fractional_odd 1, 3, 5, 9, 17, 33, 63; fractional_even and
// pow2 the powers of two). With independent per-edge levels, no denser family has that.
bool narrowEdgeLevel(uint32_t level, tess::Spacing spacing);

// How much wider than 1 / o a regular pattern's triangles are, at most over every spacing
// and every equalSegmentLevel o (all outer and inner levels o): the widest extent along u
// and along v times o, and the largest enclosing circle's squared radius times o^2. Quad 1,
// 1, 1/2; the triangle domain's rings 4/3, 4/3 and 0.556. A shared edge's level takes them
// into its bound (error_bound.h), so a patch whose edges all have that level is within it.
struct RingFactors {
  double u = 1, v = 1, circle = 0.5;
};
RingFactors ringFactors(tess::Domain domain);

// After the extents: the longest segment of an edge at level o (1..64), entry
// transitionSegmentIndex(edges, o): 1 / o for integer levels; fractional_odd's even levels
// have a longer middle segment (level 2: 2 / 3).
inline constexpr size_t transitionSegmentIndex(uint32_t edges, uint32_t o) {
  return size_t(edges) * kTransitionAxes * kTransitionLevels * kTransitionLevels + (o - 1);
}

// The table for `domain` (quad: 4 edges, triangle: 3) and `spacing`: entry transitionIndex(e,
// axis, o, n) is the largest extent along `axis` (domain units, exact: a multiple of 2^-16)
// of any triangle emitted for levels outer = n except outer[e] = o, inner = n. Best 1 / n (a
// regular quad grid; the triangle domain's rings 4 / (3 n)); the transition rings reach
// about 3.5 / min(o, n). The circle entry: best 1 / (2 n^2) on a quad grid, 0.556 / n^2 on the
// triangle domain. Computed on first use
// (about 0.5 s for a quad spacing), then shared; thread-safe. std::invalid_argument for
// the isoline domain.
const std::vector<float>& transitionExtents(tess::Domain domain, tess::Spacing spacing);

}  // namespace tb::lod
