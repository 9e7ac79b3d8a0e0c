// Internal to gregory_acc: the 1-ring of each vertex (whole, or cut into sectors at sharp
// edges) and the vertex frames (limit position and tangents) the Gregory control points are
// built from, as stencils over the control mesh (Loop, Schaefer, Ni, Castano 2009; Kovacs,
// Mitchell, Drone & Zorin 2009). gregory_stencils.cpp assembles the patches' stencils
// from them.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/gregory_acc/gregory_refine.h"
#include "techniques/gregory_acc/gregory_stencils.h"

namespace tb::gregory_acc {

// into += scale * s; into[index] += weight.
void add(Stencil& into, const Stencil& s, double scale);
void add(Stencil& into, uint32_t index, double weight);

// cos and sin of 2 pi k / n, exact at quarter turns so regular vertices get no 1e-17
// weights (which would cost operations and make the sums order-dependent for nothing).
double cosTurn(uint32_t k, uint32_t n);
double sinTurn(uint32_t k, uint32_t n);

// The key of the directed edge a -> b.
uint64_t directedKey(uint32_t a, uint32_t b);

// The 1-ring of a vertex, counter-clockwise: face i follows the edge to neighbour[i] and
// precedes the edge to neighbour[i + 1]. On a boundary, or for a sector of a crease or corner
// vertex (Kovacs et al. 2009), neighbour[0] and neighbour[faces] are the open ends, one more
// neighbour than faces. diagonal[i] is face i's diagonal as a stencil (a quad's far vertex;
// otherwise 4 c_i - v - e_i - e_{i+1}), which turns the quad masks into Loop et al. 2009's
// midpoint/centroid masks (docs/derivations/acc_gregory.md).
struct Ring {
  std::vector<uint32_t> neighbour;
  std::vector<Stencil> diagonal;  // one per face
  bool boundary = false;          // open: a mesh boundary, or a sector between sharp edges
  bool corner = false;            // the vertex is interpolated (SharpVertexKind::kCorner)
  bool quads_only = true;         // every face of the ring is a quad
  uint32_t valence() const { return uint32_t(neighbour.size()); }  // edges at the vertex
  uint32_t faces() const { return uint32_t(diagonal.size()); }
  // The valence used in the face-point weights cos(2 pi / n): a boundary vertex with k
  // faces counts as 2k (Loop et al. 2009; a regular boundary vertex then counts as 4).
  uint32_t effectiveValence() const { return boundary ? 2 * faces() : valence(); }
  uint32_t indexOf(uint32_t w) const {
    for (uint32_t i = 0; i < neighbour.size(); ++i) {
      if (neighbour[i] == w) return i;
    }
    return UINT32_MAX;
  }
};

// Per vertex: limit position P and the two tangent stencils e0, e1 such that the edge
// point toward neighbour k is P + cos(2 pi k/n) e0 + sin(2 pi k/n) e1 (Loop et al. 2009
// §3), scaled so valence 4 gives the B-spline's Bézier edge points.
struct VertexFrame {
  Stencil position, e0, e1;
};

// The frame of an interior vertex with an all-quad ring (the tangent masks: see
// gregory_rings.cpp).
VertexFrame vertexFrame(uint32_t v, const Ring& ring, TangentMask mask);

// Crease vertex, one open ring of k >= 1 faces: a smooth mesh-boundary vertex (the
// boundary is an infinitely sharp crease) or one sector of a crease vertex. P is the
// crease B-spline's limit point, e0 its tangent (exact: both involve only the vertex and
// the two crease neighbours, so every patch along the crease agrees, whichever side it is
// on), e1 the cross-boundary tangent of Loop et al. 2009 (as in OpenSubdiv Far's Gregory
// basis; 0 for k = 1, where the limit folds); the edge point toward neighbour j is
// P + cos(pi j/k) e0 + sin(pi j/k) e1. Corners (interpolated) are not framed here: see
// cornerEdgePoint.
VertexFrame boundaryFrame(uint32_t v, const Ring& ring);

// Twist term r_i of Loop et al. 2009 (the cross-boundary difference across edge i):
// (e_{i+1} - e_{i-1})/3 + (d_i - d_{i-1})/6.
Stencil twist(const Ring& ring, uint32_t i);

// "gregory_acc: <file>: ", the start of every message.
std::string prefix(const mesh::Mesh& mesh);

// A stencil over refineOnce's positions as one over the input's, times `scale`.
Stencil composed(const Stencil& over_refined, const RefinedMesh& refined, double scale);

// The frame of an interior vertex with a non-quad face in its ring, through one Catmull-Clark
// step: the vertex's refined copy has an all-quad ring of the same valence and the same limit
// point and tangent plane, so the quad masks there give the exact limit position (and,
// with kExactLimit, the exact tangent plane). The refined tangents are in the refined
// faces' half-size parameter; they are scaled back by 1/lambda, lambda the subdominant
// eigenvalue (exact for an eigenvector mask). `refined_ring` must be closed (an interior
// vertex; boundary rings and crease sectors: refinedCreaseFrame) and start at the edge point
// of the input ring's neighbour[0].
VertexFrame refinedFrame(uint32_t v, const Ring& refined_ring, const RefinedMesh& refined,
                         TangentMask mask);

// The frame of one crease sector (Ring::boundary; a crease vertex's sector or a mesh-boundary
// vertex's ring) with a non-quad face in it, through one Catmull-Clark step as refinedFrame:
// the sector of v's refined copy is all quads, framed by boundaryFrame there. refineOnce
// knows only the smooth rules (and makes a one-face boundary vertex a corner), so the points
// the crease rules place differently are its own here: v' = (b0 + 6 v + b1) / 8 and the
// midpoints of its two sharp edges (v, b0), (v, b1). P is then the crease B-spline's limit
// point (4 v + b0 + b1) / 6 and e0 its tangent (b0 - b1) / 6, the same terms from every
// sector, as the quad sectors' boundaryFrame gives them. `whole_refined` is v's refined ring.
VertexFrame refinedCreaseFrame(uint32_t v, const Ring& sector, const Ring& whole_refined,
                               const RefinedMesh& refined);

// Ring::diagonal of the face `fv` seen from its corner k.
Stencil faceDiagonal(std::span<const uint32_t> fv, uint32_t k);

struct Rings {
  std::vector<Ring> rings;  // per position; empty for unused positions
  std::string error;
};

// Walks every vertex's faces counter-clockwise; reports a vertex whose faces do not form
// one closed fan (non-manifold vertex) or whose valence is out of range.
Rings buildRings(const mesh::Mesh& mesh);

// The rings of vertex v as the patches use them (Kovacs et al. 2009: a sharp edge is a
// boundary for patch construction). Smooth vertices and darts keep their whole ring (a
// dart: smooth rules); crease and corner vertices get one open ring per sector, cut at
// their sharp edges (and, on a mesh boundary, at its two ends).
std::vector<Ring> sectorsOf(uint32_t v, const Ring& whole,
                            const techniques::CreasePreparation& creases);

// Corner sector (interpolated vertex v; its two sharp edges end at b0 = neighbour[0] and
// b1 = neighbour[k]): the edge points along the sharp edges are the B-spline end rule
// (2 v + b) / 3, which makes the crease curve the limit's. An interior edge j (0 < j < k)
// has no rule in Loop et al. 2009 or Kovacs et al. 2009; it gets the direction between the
// two crease tangents t0 = b0 - v, t1 = b1 - v that a regular corner's grid gives, the
// sector spread over a quarter turn: E_j = v + (sin((k - j) phi) t0 + sin(j phi) t1) / 3,
// phi = pi / (2k) (for k = 2 the diagonal direction). Affine; one stencil per directed edge.
Stencil cornerEdgePoint(uint32_t v, const Ring& sector, uint32_t w);

// A stencil without the terms emit drops (cancelled weights), for exact comparisons.
Stencil pruned(const Stencil& s);

}  // namespace tb::gregory_acc
