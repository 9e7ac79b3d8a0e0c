// Culling bounds (PatchCullBounds, techniques/technique.h) of the Gregory patches of
// gregory_eval.h, from their double control points, in world units.
//
// Hull: every control point (20 on a quad, 15 on a triangle). At each domain point the
// patch is the Bézier patch whose interior points are convex blends of the corner's Fp and
// Fm, and the triangle's boundary net points are convex combinations of P and E; so the
// patch lies in the convex hull of the Gregory points.
//
// Normal generators. A Gregory patch is rational: corner c's interior point is
// q_c = (a_c Fp_c + b_c Fm_c) / d_c, d_c = a_c + b_c, with a_c, b_c linear in the domain
// and >= 0 on it (gregory_eval.h's blendFace), d_c > 0 except at corner c. Along a domain
// direction t (u or v on a quad; toward corner 1 or 2 on a triangle), with B_c the
// Bernstein polynomial of q_c's slot and P~ the net with the interior points left out,
//   p_t = P~_t + Σ_c [B_c,t q_c + B_c (dα_c/dt) (Fp_c - Fm_c)],
//   α_c = a_c / d_c,  dα_c/dt = (a_c,t b_c - b_c,t a_c) / d_c²
// (the Bézier derivative with the interior points frozen, plus the blends' own motion).
// Times E = Π_c d_c², every term is a polynomial:
//   X_t = E p_t = E P~_t + Σ_c E_c [B_c,t d_c n_c + B_c (a_c,t b_c - b_c,t a_c) (Fp_c - Fm_c)],
//   E_c = Π_{c' != c} d_c'²,  n_c = a_c Fp_c + b_c Fm_c,
// and the normal p_1 x p_2 = (X_1 x X_2) / E² with E² > 0 inside the domain (at a corner
// the normal is the limit, in the closed cone). So the Bernstein coefficients of the
// polynomial X_1 x X_2 generate a cone containing every normal: bi-degree 21 x 21 on a
// quad (484 coefficients, 444 after dropping the exact zeros), degree 18 on a triangle
// (190, 160). Each term is a product of factors, so the coefficients that vanish at a
// corner (where E does) come out as exact zeros rather than rounding noise of random
// direction, which would open the cone.
//
// Not used: keeping p_1 and p_2 apart, each in the cone of its frozen-net differences and
// ±(Fp_c - Fm_c) by the sign of dα_c/dt, and taking all pairwise crosses. That is valid too
// but loses the blends' magnitudes; on the bundled assets it gave a cone of the whole space
// on 88% of the patches (every triangle patch, every catmark_cube patch).
//
// Orientation: the quad's (u, v) runs (0,0), (1,0), (1,1), (0,1) through corners 0..3, the
// triangle's directions point toward corners 1 and 2 from corner 0; corners are the control
// face's in its winding order, so both cross products face the front unchanged.
#pragma once

#include "techniques/gregory_acc/gregory_eval.h"
#include "techniques/technique.h"

namespace tb::gregory_acc {

techniques::PatchCullBounds gregoryQuadCullBounds(const GregoryPoints<double>& cp);
techniques::PatchCullBounds gregoryTriangleCullBounds(const GregoryPoints<double>& cp);

// Second-derivative bounds (CurvatureBounds), for every Gregory patch (face points equal or
// not): the Bezier net with the face points' midpoints M_c in its interior slots, bounded by
// its second differences (techniques/common/curvature_bounds.h), plus the rational blends'
// share Σ_c K_c |Fp_c - Fm_c| / 2 with the universal constants K_c derived there. Edges: the
// cubic boundary curve P, E, E, P (both domains, so a quad and a triangle sharing an edge
// agree), edge_hull its four points; hull: the control points.
techniques::CurvatureBounds gregoryQuadCurvatureBounds(const GregoryPoints<double>& cp);
techniques::CurvatureBounds gregoryTriangleCurvatureBounds(const GregoryPoints<double>& cp);

}  // namespace tb::gregory_acc
