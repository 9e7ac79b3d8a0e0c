// Shared math for SurfacePatches::cullBounds (techniques/technique.h, PatchCullBounds): the
// normal patches of polynomial Bézier patches (Sederberg & Meyers 1988). N = p_s x p_t is a
// polynomial whose Bernstein control points are positive combinations of the pairwise cross
// products of p_s's and p_t's (bernstein_poly.h), so they generate a cone containing every
// normal. World units; generators only up to a positive factor. docs/derivations/normal_cones.md.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/mesh/vec.h"
#include "techniques/common/bernstein_poly.h"

namespace tb::techniques {

// Control points N[m + 6 n] (m along u, n along v; bi-degree 5 x 5) of the normal patch
// p_u x p_v of the bicubic Bézier patch b[i + 4 j] (i along u).
std::array<mesh::Vec3d, 36> bicubicNormalPatch(const std::array<mesh::Vec3d, 16>& b);

// Control points, in bernstein_poly.h's triangle net order, of the degree 2n - 2 normal
// patch D_1 x D_2 of the degree-n triangle patch `net` (n >= 1): D_1 = d/dv - d/du is the
// derivative toward corner 1 with corner 2's weight fixed, D_2 = d/dw - d/du toward
// corner 2. For corners 0, 1, 2 counter-clockwise seen from the front, the normals point
// to the front.
std::vector<mesh::Vec3d> triangleNormalPatch(int degree, std::span<const mesh::Vec3d> net);

// `vectors` without its exact zeros.
std::vector<mesh::Vec3d> withoutZeros(std::span<const mesh::Vec3d> vectors);

// Each vector negated: the generators of a patch whose parameterisation is mirrored
// against its control face's winding.
std::vector<mesh::Vec3d> negated(std::vector<mesh::Vec3d> vectors);

}  // namespace tb::techniques
