// The parametric tangent plane of a polynomial patch in Bernstein form, for the
// tangent_plane culling policy (Loop, Nießner & Eisenacher, "Effective Back-Patch Culling
// for Hardware Tessellation", VMV 2011).
//
// For a patch P(u,v) with geometric normal N = P_u x P_v (a triangle: D_1 x D_2), the eye E
// sees the front at (u,v) when f(u,v) = (E - P) . N > 0. f is a polynomial of the patch's
// degree times three minus one (bicubic: bi-degree 8 x 8, 81 coefficients; cubic triangle:
// degree 7, 36; quadratic triangle: degree 4, 15), and linear in E:
//   f = (E - O) . N - (P - O) . N,
// with O a point of the patch's choosing (its first corner, so the float sums stay small).
// Its Bernstein coefficients are c_k = (E - O) . n_k + w_k, with n_k the coefficients of N
// degree-raised to f's degree and w_k those of -(P - O) . N: computed once per patch, in
// double, so a frame costs one dot product per coefficient. Where every c_k < 0, f < 0 on
// the whole domain (the Bernstein basis is non-negative and sums to 1): the patch faces
// away everywhere.
//
// The surface facing away is not yet the rendered triangles facing away: a triangle's
// corners lie on the surface, but its plane is a chord, which on a strongly curved patch at
// a low level can face the eye while every tangent plane faces away (Phong's quadratic
// triangles on catmark_smoothtris0 at level 4: surface cosines <= -0.2, a chord triangle's
// +0.43). The chord margin bounds that: for a tessellation triangle with domain corners
// x0, x0 + a, x0 + b,
//   f_tri = det(a, b) f(x0) + (E - P(x0)) . r,
//   |r| <= |a|_1 |b|_1 (G1 G2 (|a|_1 + |b|_1) / 2 + G2^2 |a|_1 |b|_1 / 4),
// G1 and G2 the largest first and second derivative coefficients of the net (Taylor with
// the integral remainder; the convex-hull property bounds each derivative by its
// coefficients). So every triangle faces away when f < -(|E - O| + R) (G1 G2 K2 + G2^2 K3)
// with R the net's reach from O and K2, K3 the worst over the tessellation pattern's
// triangles of rho (|a|_1 + |b|_1) / 2 and rho |a|_1 |b|_1 / 4, rho = |a|_1 |b|_1 / det(a, b)
// (chordFactors: they shrink as 1/L and 1/L^2 with the level L).
#pragma once

#include <array>
#include <vector>

#include "core/mesh/vec.h"
#include "core/tess/tessellator.h"
#include "techniques/technique.h"

namespace tb::lod {

// One coefficient of f: {n_k x, y, z, w_k}, world units squared (n_k) and cubed (w_k).
using TangentPlaneCoefficient = std::array<double, 4>;

// The coefficients of f for the patch `bounds` describes (domain `domain`), relative to the
// origin `origin`, oriented so that f > 0 where the front faces the eye; empty when the
// patch has no Bézier net (PatchCullBounds::bezier_net). Throws std::invalid_argument when
// the net's size does not match its degree and domain.
std::vector<TangentPlaneCoefficient> tangentPlaneCoefficients(
    techniques::PatchDomain domain, const techniques::PatchCullBounds& bounds,
    const mesh::Vec3d& origin);

// The patch's chord-margin constants: R = max |q - O| over the net (world units),
// G1 G2 (world units squared) and G2^2, from the net's first and second differences.
struct TangentPlaneChordBound {
  double reach = 0;
  double first_times_second = 0;
  double second_squared = 0;
};
TangentPlaneChordBound tangentPlaneChordBound(techniques::PatchDomain domain,
                                              const techniques::PatchCullBounds& bounds,
                                              const mesh::Vec3d& origin);

// {K2, K3} of the CPU tessellator's pattern on `domain` at uniform level `level` (integer
// spacing), in the domain coordinates the derivatives use: (u, v) on a quad, the weights of
// corners 1 and 2 on a triangle. Level 4: quad {2, 1}, triangle about {1.5, 0.38}.
std::array<double, 2> chordFactors(tess::Domain domain, float level);

}  // namespace tb::lod
