// Second-derivative bounds (CurvatureBounds, techniques/technique.h) of polynomial patches
// in Bernstein form: a Bezier net's second differences bound its second derivatives (the
// derivative of a Bernstein polynomial is a Bernstein polynomial of the differences, and a
// Bernstein polynomial lies in the hull of its coefficients), and of Gregory patches (the
// polynomial patch of the face-point midpoints plus a universal bound on the rational
// blends, curvature_bounds.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/mesh/vec.h"
#include "techniques/technique.h"

namespace tb::techniques {

// The bounds of the polynomial patch cullBounds() describes (PatchCullBounds::bezier_net of
// bezier_degree on `domain`), or nullopt when it gives no net. hull = bounds.hull.
std::optional<CurvatureBounds> curvatureBoundsFromNet(const PatchCullBounds& bounds,
                                                      PatchDomain domain);

// A Bezier quad of bi-degree d x d, net c[i + (d + 1) j] (i along u): uu, uv, vv, edge[0..3]
// and edge_hull[0..3] (the boundary rows); hull = the net. Precondition: (d + 1)^2 points.
CurvatureBounds quadNetCurvatureBounds(const std::vector<mesh::Vec3d>& net, int degree);

// A Bezier triangle of total degree d in bernstein_poly.h's order (b_ijk, i + j + k = d, the
// powers of the net's corners 0, 1, 2): uu, uv, vv with respect to the domain's (u, v), w =
// 1 - u - v dependent, edge[0..2] (u = 0, v = 0, w = 0) and their rows; hull = the net.
// labels[k]: the net corner of the domain's corner k, whose weight is DomainCoord[k] (identity
// when the net is in domain order; pn_triangles' nets are in label order). Preconditions:
// triangleNetSize(d) points, d >= 1, labels a permutation of 0, 1, 2.
CurvatureBounds triangleNetCurvatureBounds(const std::vector<mesh::Vec3d>& net, int degree,
                                           const std::array<int, 3>& labels = {0, 1, 2});

// sup |C''| over [0, 1] of the Bezier curve of `points` (degree points.size() - 1):
// d (d - 1) max_i |P_i - 2 P_{i+1} + P_{i+2}|; 0 for fewer than three points.
double bezierCurveSecondDerivativeBound(const std::vector<mesh::Vec3d>& points);

// Universal constants of the Gregory blends (curvature_bounds.cpp derives them): corner c's
// interior point is M_c + t_c δ_c with t_c = (a_c - b_c) / (a_c + b_c) in [-1, 1], so the
// patch is the polynomial patch of the midpoints M_c plus Σ_c g_c δ_c, g_c = B_c t_c. These
// are upper bounds of sup |∂uu g_c|, sup |∂uv g_c|, sup |∂vv g_c| over the domain.
struct GregoryBlendConstants {
  double uu, uv, vv;
};
// Quad (bicubic weights, blends of gregory_eval.h and Far's Gregory basis), corner 0's g_0
// over the quadrant [qa / 2, (qa + 1) / 2] x [qb / 2, (qb + 1) / 2] of the domain:
// kGregoryQuadBlend[qa][qb]. Corner c's g_c is g_0 reflected (u -> 1 - u for corners 1 and
// 2, v -> 1 - v for corners 2 and 3), so it reads the reflected quadrant.
extern const std::array<std::array<GregoryBlendConstants, 2>, 2> kGregoryQuadBlend;
// Triangle (quartic weights, blends b211 (v, w), b121 (w, u), b112 (u, v)), per corner and
// region of the domain cut at its edges' midpoints: kGregoryTriangleBlend[c][r], r = 0, 1, 2
// the corner triangles where u, v or w >= 1/2, 3 the middle one. Corner c's own region
// holds the whole domain's suprema (limits at the corner); elsewhere its blend is smooth.
extern const std::array<std::array<GregoryBlendConstants, 4>, 3> kGregoryTriangleBlend;

// A quad Gregory patch from the bicubic net `mid_net` (16 points, c[i + 4 j]) with the face
// points' midpoints in its interior slots and `half_gaps[c]` = |Fp_c - Fm_c| / 2 (world
// units): per quadrant of the domain, the midpoint patch's bound on its de Casteljau half
// net (times 4, the quadrant's parameter being twice the domain's) plus Σ_c K_c |δ_c| with
// the quadrant's constants; uu, uv, vv the largest over the quadrants. Edges and edge_hull
// from the net's boundary rows (the polynomial boundary curves), hull = mid_net (the caller
// replaces it by the control points).
CurvatureBounds gregoryQuadNetCurvatureBounds(const std::vector<mesh::Vec3d>& mid_net,
                                              const std::array<double, 4>& half_gaps);
// Adds the largest over the four regions of Σ_c K_c |δ_c| (the region's constants) to uu,
// uv and vv: `half_gaps[c]` = |Fp_c - Fm_c| / 2 (world units).
// Edges are untouched (a Gregory patch's boundary curves are polynomial).
void addGregoryTriangleBlends(CurvatureBounds& bounds, const std::array<double, 3>& half_gaps);

}  // namespace tb::techniques
