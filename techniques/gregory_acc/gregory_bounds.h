// Culling bounds (PatchCullBounds, techniques/technique.h) of the Gregory patches of
// gregory_eval.h, from their double control points, in world units: the hull is every
// control point; the normal generators are the Bernstein coefficients of the polynomial
// X_1 x X_2, the derivatives times the positive product of the blend denominators (bi-degree
// 21 x 21 on a quad, 18 on a triangle; exact zeros dropped). Derivation and the alternative
// not used: docs/derivations/normal_cones.md (Sederberg & Meyers 1988; Loop et al. 2009).
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
