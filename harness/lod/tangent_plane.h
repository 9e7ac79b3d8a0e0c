// The parametric tangent plane of a polynomial patch in Bernstein form, for the tangent_plane
// culling policy (Loop, Nießner & Eisenacher, "Effective Back-Patch Culling for Hardware
// Tessellation", VMV 2011): f = (E - P) . N has coefficients c_k = (E - O) . n_k + w_k,
// precomputed per patch in double; every c_k < 0 means the patch faces away everywhere. The
// chord margin (chordFactors) extends that to the tessellated triangles. Derivation:
// docs/derivations/chord_margins.md.
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
