#include "techniques/gregory_acc/gregory_stencils.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <unordered_map>

#include "core/mesh/topology.h"
#include "techniques/common/quad_ring.h"
#include "techniques/gregory_acc/gregory_refine.h"
#include "techniques/technique.h"

namespace tb::gregory_acc {
namespace {

void add(Stencil& into, const Stencil& s, double scale) {
  for (const auto& [index, weight] : s) into[index] += weight * scale;
}
void add(Stencil& into, uint32_t index, double weight) { into[index] += weight; }

// cos and sin of 2 pi k / n, exact at quarter turns so regular vertices get no 1e-17
// weights (which would cost operations and make the sums order-dependent for nothing).
double cosTurn(uint32_t k, uint32_t n) {
  if ((4 * k) % n == 0) {
    const uint32_t q = (4 * k / n) % 4;
    return q == 0 ? 1.0 : (q == 2 ? -1.0 : 0.0);
  }
  return std::cos(2.0 * std::numbers::pi * double(k) / double(n));
}
double sinTurn(uint32_t k, uint32_t n) {
  if ((4 * k) % n == 0) {
    const uint32_t q = (4 * k / n) % 4;
    return q == 1 ? 1.0 : (q == 3 ? -1.0 : 0.0);
  }
  return std::sin(2.0 * std::numbers::pi * double(k) / double(n));
}

uint64_t directedKey(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

// The 1-ring of a vertex, counter-clockwise: face i follows the edge to neighbour[i]
// and precedes the edge to neighbour[i + 1] (indices modulo the valence inside). On a
// boundary, neighbour[0] and neighbour[faces] are the two boundary neighbours, and there
// is one more neighbour than faces. A sector (the faces between two consecutive sharp
// edges of a crease or corner vertex, Kovacs et al. 2009) is a Ring too, open like a
// boundary: neighbour[0] and neighbour[faces] are its sharp edges' other ends.
//
// diagonal[i] is face i's "diagonal" as a stencil: on a quad (v, e_i, d_i, e_{i+1}) the
// vertex d_i; on any other face 4 c_i - v - e_i - e_{i+1}, with c_i the face's
// centroid (on a triangle: the centroid itself). Loop et al. 2009 write every mask in
// terms of edge midpoints m_i and face centroids c_i, which is what makes them apply to
// rings with triangles; substituting this diagonal into the quad masks gives exactly
// those midpoint/centroid masks, and leaves all-quad rings bit-for-bit as before.
struct Ring {
  std::vector<uint32_t> neighbour;
  std::vector<Stencil> diagonal;  // one per face
  bool boundary = false;    // open: a mesh boundary, or a sector between sharp edges
  bool corner = false;      // the vertex is interpolated (SharpVertexKind::kCorner)
  bool quads_only = true;   // every face of the ring is a quad
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

VertexFrame vertexFrame(uint32_t v, const Ring& ring, TangentMask mask) {
  const uint32_t n = ring.valence();
  const double dn = double(n);
  VertexFrame frame;
  // Limit position: (n^2 v + 4 sum e_i + sum d_i) / (n (n + 5)).
  add(frame.position, v, dn * dn / (dn * (dn + 5)));
  for (uint32_t i = 0; i < n; ++i) {
    add(frame.position, ring.neighbour[i], 4.0 / (dn * (dn + 5)));
    add(frame.position, ring.diagonal[i], 1.0 / (dn * (dn + 5)));
  }
  // Tangents: sum_i cos_i (a e_i) + (cos_i + cos_{i+1}) d_i (sin likewise), times
  // 1 / (2 (n + 5) n lambda), lambda = (5 + c + sqrt((c + 9)(c + 1))) / 16 the subdominant
  // eigenvalue, c = cos(2 pi/n). kExactLimit: a = 1 + c + sqrt((1 + c)(9 + c)), the
  // Catmull-Clark limit tangent mask (Halstead et al. 1993), so the edge points span the
  // limit tangent plane. kPaper: a = 4 (1 + c), what averaging the ACC face
  // points f_i = (n v + 2 e_i + 2 e_{i+1} + d_i)/(n + 5) gives (OpenSubdiv Far's Gregory
  // basis); not the limit tangent plane for n != 4. Both are equal at n = 4.
  const double c = cosTurn(1, n);
  const double root = std::sqrt((c + 9) * (c + 1));
  const double scale = 16.0 / (dn * (c + 5 + root)) / (2 * (dn + 5));
  const double a = mask == TangentMask::kExactLimit ? 1 + c + root : 4 * (1 + c);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t ip = (i + 1) % n;
    add(frame.e0, ring.neighbour[i], scale * a * cosTurn(i, n));
    add(frame.e1, ring.neighbour[i], scale * a * sinTurn(i, n));
    add(frame.e0, ring.diagonal[i], scale * (cosTurn(i, n) + cosTurn(ip, n)));
    add(frame.e1, ring.diagonal[i], scale * (sinTurn(i, n) + sinTurn(ip, n)));
  }
  return frame;
}

// Crease vertex, one open ring of k >= 1 faces: a smooth mesh-boundary vertex (the
// boundary is an infinitely sharp crease) or one sector of a crease vertex. P is the
// crease B-spline's limit point, e0 its tangent (exact: both involve only the vertex and
// the two crease neighbours, so every patch along the crease agrees, whichever side it is
// on), e1 the cross-boundary tangent of Loop et al. 2009 (as in OpenSubdiv Far's Gregory
// basis; 0 for k = 1, where the limit folds); the edge point toward neighbour j is
// P + cos(pi j/k) e0 + sin(pi j/k) e1. Corners (interpolated) are not framed here: see
// cornerEdgePoint.
VertexFrame boundaryFrame(uint32_t v, const Ring& ring) {
  const uint32_t k = ring.faces();
  const double dk = double(k);
  const uint32_t b0 = ring.neighbour.front(), b1 = ring.neighbour.back();
  VertexFrame frame;
  add(frame.position, v, 4.0 / 6);
  add(frame.position, b0, 1.0 / 6);
  add(frame.position, b1, 1.0 / 6);
  add(frame.e0, b0, 1.0 / 6);
  add(frame.e0, b1, -1.0 / 6);
  // k = 1: cos(pi) = -1 exactly, sin(pi) = 1.2e-16 (its terms are dropped by emit).
  const double c = std::cos(std::numbers::pi / dk), s = std::sin(std::numbers::pi / dk);
  const double den = 3 * dk + c;
  add(frame.e1, v, -4 * s / den / 3);
  const double alpha_ends = -((1 + 2 * c) * std::sqrt(1 + c)) / (den * std::sqrt(1 - c));
  add(frame.e1, b0, alpha_ends / 3);
  add(frame.e1, b1, alpha_ends / 3);
  for (uint32_t x = 0; x < k; ++x) {
    const double sx = std::sin(std::numbers::pi * double(x) / dk);
    const double sx1 = x + 1 == k ? 0.0 : std::sin(std::numbers::pi * double(x + 1) / dk);
    if (x > 0) add(frame.e1, ring.neighbour[x], 4 * sx / den / 3);
    add(frame.e1, ring.diagonal[x], (sx + sx1) / den / 3);
  }
  return frame;
}

// Twist term r_i of Loop et al. 2009 (the cross-boundary difference across edge i):
// (e_{i+1} - e_{i-1})/3 + (d_i - d_{i-1})/6.
Stencil twist(const Ring& ring, uint32_t i) {
  const uint32_t n = ring.valence();
  Stencil r;
  add(r, ring.neighbour[(i + 1) % n], 1.0 / 3);
  add(r, ring.neighbour[(i + n - 1) % n], -1.0 / 3);
  add(r, ring.diagonal[i], 1.0 / 6);
  add(r, ring.diagonal[(i + n - 1) % n], -1.0 / 6);
  return r;
}

std::string prefix(const Mesh& mesh) { return "gregory_acc: " + mesh.source + ": "; }

Stencil composed(const Stencil& over_refined, const RefinedMesh& refined, double scale) {
  Stencil out;
  for (const auto& [index, weight] : over_refined)
    add(out, refined.stencils[index], weight * scale);
  return out;
}

// The frame of a vertex with a non-quad face in its ring, through one Catmull-Clark step:
// the vertex's refined copy has an all-quad ring of the same valence and the same limit
// point and tangent plane, so the quad masks there give the exact limit position (and,
// with kExactLimit, the exact tangent plane). The refined tangents are in the refined
// faces' half-size parameter; they are scaled back by 1/lambda, lambda the subdominant
// eigenvalue (exact for an eigenvector mask; 2 on a boundary, where lambda = 1/2).
// `refined_ring` must start at the edge point of the input ring's neighbour[0].
VertexFrame refinedFrame(uint32_t v, const Ring& refined_ring, const RefinedMesh& refined,
                         TangentMask mask) {
  double scale = 2;
  VertexFrame local;
  if (refined_ring.boundary) {
    local = boundaryFrame(v, refined_ring);
  } else {
    local = vertexFrame(v, refined_ring, mask);
    const double c = cosTurn(1, refined_ring.valence());
    scale = 16.0 / (5 + c + std::sqrt((c + 9) * (c + 1)));
  }
  return {composed(local.position, refined, 1.0), composed(local.e0, refined, scale),
          composed(local.e1, refined, scale)};
}

// Ring::diagonal of the face `fv` seen from its corner k.
Stencil faceDiagonal(std::span<const uint32_t> fv, uint32_t k) {
  const size_t size = fv.size();
  Stencil d;
  if (size == 4) {
    add(d, fv[(k + 2) % 4], 1.0);
    return d;
  }
  // 4 c - v - e_i - e_{i+1}, c = the mean of the face's vertices.
  for (uint32_t i = 0; i < size; ++i) add(d, fv[i], 4.0 / double(size));
  for (uint32_t i : {k, uint32_t((k + 1) % size), uint32_t((k + size - 1) % size)}) {
    add(d, fv[i], -1.0);
  }
  return d;
}

struct Rings {
  std::vector<Ring> rings;  // per position; empty for unused positions
  std::string error;
};

// Walks every vertex's faces counter-clockwise; reports a vertex whose faces do not form
// one closed fan (non-manifold vertex) or whose valence is out of range.
Rings buildRings(const Mesh& mesh) {
  Rings out;
  out.rings.resize(mesh.positions.size());
  std::unordered_map<uint64_t, uint32_t> face_of_directed;  // (a -> b) -> face
  std::vector<std::vector<uint32_t>> vertex_faces(mesh.positions.size());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (uint32_t k = 0; k < fv.size(); ++k) {
      const uint32_t a = fv[k], b = fv[(k + 1) % fv.size()];
      if (!face_of_directed.emplace(directedKey(a, b), uint32_t(f)).second) {
        out.error = prefix(mesh) + "edge (" + std::to_string(a) + ", " + std::to_string(b) +
                    ") is used twice in the same direction (" + describeFace(mesh, f) +
                    "); faces must be consistently oriented";
        return out;
      }
      vertex_faces[a].push_back(uint32_t(f));
    }
  }
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    if (vertex_faces[v].empty()) continue;
    const uint32_t face_count = uint32_t(vertex_faces[v].size());
    Ring& ring = out.rings[v];
    // Start a boundary vertex's walk at the face after its boundary edge: the face
    // whose edge (v, neighbour) has no face on the other side (no directed edge w -> v).
    uint32_t start_face = vertex_faces[v].front();
    for (uint32_t f : vertex_faces[v]) {
      const auto fv = mesh.facePositions(f);
      for (uint32_t k = 0; k < fv.size(); ++k) {
        if (fv[k] == v && !face_of_directed.count(directedKey(fv[(k + 1) % fv.size()], v))) {
          start_face = f;
          ring.boundary = true;
          break;
        }
      }
      if (ring.boundary) break;
    }
    uint32_t f = start_face;
    for (uint32_t step = 0; step <= face_count; ++step) {
      const auto fv = mesh.facePositions(f);
      const size_t size = fv.size();
      uint32_t k = 0;
      while (fv[k] != v) ++k;
      ring.neighbour.push_back(fv[(k + 1) % size]);
      ring.diagonal.push_back(faceDiagonal(fv, k));
      ring.quads_only &= size == 4;
      const uint32_t last = fv[(k + size - 1) % size];
      const auto next = face_of_directed.find(directedKey(v, last));
      if (next == face_of_directed.end()) {
        ring.neighbour.push_back(last);  // the second boundary neighbour
        break;
      }
      f = next->second;
      if (f == start_face) break;
    }
    if (ring.faces() != face_count) {
      out.error = prefix(mesh) + "vertex " + std::to_string(v) +
                  " is non-manifold (its faces form more than one fan)";
      return out;
    }
    const uint32_t low = ring.boundary ? 1 : 3;
    if (ring.faces() < low || ring.faces() > kMaxValence) {
      out.error = prefix(mesh) + (ring.boundary ? "boundary vertex " : "vertex ") +
                  std::to_string(v) + (ring.boundary ? " has " : " has valence ") +
                  std::to_string(ring.faces()) + (ring.boundary ? " faces" : "") +
                  "; gregory_acc needs " + std::to_string(low) + ".." + std::to_string(kMaxValence);
      return out;
    }
  }
  return out;
}

// The rings of vertex v as the patches use them (Kovacs et al. 2009: a sharp edge is a
// boundary for patch construction). Smooth vertices and darts keep their whole ring (a
// dart: smooth rules); crease and corner vertices get one open ring per sector, cut at
// their sharp edges (and, on a mesh boundary, at its two ends).
std::vector<Ring> sectorsOf(uint32_t v, const Ring& whole, const CreasePreparation& creases) {
  const SharpVertexKind kind = creases.vertex_kind[v];
  if (kind != SharpVertexKind::kCrease && kind != SharpVertexKind::kCorner) return {whole};
  const uint32_t n = whole.valence();
  std::vector<uint32_t> cuts;  // neighbour indices where a sector starts or ends, ascending
  for (uint32_t i = 0; i < n; ++i) {
    if (creases.isSharp(v, whole.neighbour[i]) || (whole.boundary && (i == 0 || i + 1 == n))) {
      cuts.push_back(i);
    }
  }
  Ring ring = whole;  // a closed ring rotated to start at a cut, then closed by repeating it
  if (!whole.boundary) {
    if (cuts.empty()) return {whole};  // not reached: crease and corner kinds have sharp edges
    std::rotate(ring.neighbour.begin(), ring.neighbour.begin() + cuts[0], ring.neighbour.end());
    std::rotate(ring.diagonal.begin(), ring.diagonal.begin() + cuts[0], ring.diagonal.end());
    const uint32_t shift = cuts[0];
    for (uint32_t& c : cuts) c -= shift;
    ring.neighbour.push_back(ring.neighbour.front());
    cuts.push_back(n);
  }
  std::vector<Ring> sectors;
  for (size_t s = 0; s + 1 < cuts.size(); ++s) {
    Ring sector;
    sector.boundary = true;
    sector.corner = kind == SharpVertexKind::kCorner;
    sector.quads_only = whole.quads_only;
    sector.neighbour.assign(ring.neighbour.begin() + cuts[s], ring.neighbour.begin() + cuts[s + 1] + 1);
    sector.diagonal.assign(ring.diagonal.begin() + cuts[s], ring.diagonal.begin() + cuts[s + 1]);
    sectors.push_back(std::move(sector));
  }
  return sectors;
}

// Corner sector (interpolated vertex v; its two sharp edges end at b0 = neighbour[0] and
// b1 = neighbour[k]): the edge points along the sharp edges are the B-spline end rule
// (2 v + b) / 3, which makes the crease curve the limit's. An interior edge j (0 < j < k)
// has no rule in Loop et al. 2009 or Kovacs et al. 2009; it gets the direction between the
// two crease tangents t0 = b0 - v, t1 = b1 - v that a regular corner's grid gives, the
// sector spread over a quarter turn: E_j = v + (sin((k - j) phi) t0 + sin(j phi) t1) / 3,
// phi = pi / (2k) (for k = 2 the diagonal direction). Affine; one stencil per directed edge.
Stencil cornerEdgePoint(uint32_t v, const Ring& sector, uint32_t w) {
  const uint32_t k = sector.faces(), j = sector.indexOf(w);
  Stencil e;
  if (j == 0 || j == k) {
    add(e, v, 2.0 / 3);
    add(e, w, 1.0 / 3);
    return e;
  }
  const double phi = std::numbers::pi / (2.0 * double(k));
  const double a = std::sin(double(k - j) * phi) / 3, b = std::sin(double(j) * phi) / 3;
  add(e, v, 1.0 - a - b);
  add(e, sector.neighbour.front(), a);
  add(e, sector.neighbour.back(), b);
  return e;
}

// A stencil without the terms emit drops (cancelled weights), for exact comparisons.
Stencil pruned(const Stencil& s) {
  Stencil out;
  for (const auto& [index, weight] : s) {
    if (std::abs(weight) >= 1e-14) out.emplace(index, weight);
  }
  return out;
}

bool nativeFaces(const Mesh& mesh, NonQuadFaces non_quads) {
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t size = mesh.faceSize(f);
    if (size != 4 && (size != 3 || non_quads != NonQuadFaces::kTrianglePatches)) return false;
  }
  return true;
}

// What the plain rings (buildRings, refineOnce) do not represent: creases, corner tags,
// holes, a boundary with an interpolation other than edge-and-corner (a closed mesh's
// boundary tag changes nothing).
bool hasSharpFeatures(const Mesh& mesh) {
  for (const Crease& crease : mesh.tags.creases) {
    if (crease.sharpness > 0) return true;
  }
  for (const Corner& corner : mesh.tags.corners) {
    if (corner.sharpness > 0) return true;
  }
  if (!mesh.tags.holes.empty()) return true;
  return mesh.tags.boundary != BoundaryInterpolation::kEdgeAndCorner &&
         buildTopology(mesh).boundaryEdgeCount() > 0;
}

// The input rules that need no crease preparation.
std::string checkInput(const Mesh& mesh) {
  if (mesh.faceCount() == 0) return prefix(mesh) + "has no faces";
  if (mesh.tags.smooth_triangles) {
    return prefix(mesh) + "`t smoothtriangles` is not supported (plain Catmull-Clark only)";
  }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t size = mesh.faceSize(f);
    if (size < 3 || size > kMaxFaceSize) {
      return prefix(mesh) + describeFace(mesh, f) + " has " + std::to_string(size) +
             " vertices; gregory_acc needs 3.." + std::to_string(kMaxFaceSize);
    }
    const auto fv = mesh.facePositions(f);
    for (uint32_t a = 0; a < size; ++a) {
      for (uint32_t b = a + 1; b < size; ++b) {
        if (fv[a] == fv[b]) {
          return prefix(mesh) + describeFace(mesh, f) + " repeats vertex " + std::to_string(fv[a]);
        }
      }
    }
  }
  const Topology topology = buildTopology(mesh);
  for (const MeshEdge& edge : topology.edges) {
    if (edge.face_count > 2) {
      return prefix(mesh) + "edge (" + std::to_string(edge.v0) + ", " + std::to_string(edge.v1) +
             ") is non-manifold (" + std::to_string(edge.face_count) + " faces)";
    }
  }
  return buildRings(mesh).error;
}

// The crease preparation gregory_acc builds on (checkInput(mesh) must be empty): a mesh
// with faces the patches cannot take natively (5+ vertices, or non-quads in quads_only)
// and sharp features is refined once by OpenSubdiv, since refineOnce knows only smooth
// rules and edge-and-corner boundaries. Throws UnsupportedInput for a cone point and for a
// mesh with no face that has a limit surface.
CreasePreparation prepareGregoryCreases(const Mesh& mesh, NonQuadFaces non_quads,
                                        size_t face_budget) {
  const bool refine = !nativeFaces(mesh, non_quads) && hasSharpFeatures(mesh);
  CreasePreparation creases = prepareCreases(mesh, "gregory_acc", face_budget, refine ? 1 : 0);
  for (size_t v = 0; v < creases.vertex_kind.size(); ++v) {
    if (creases.vertex_kind[v] == SharpVertexKind::kCone) {
      throw UnsupportedInput(prefix(mesh) + describeVertex(creases.control, uint32_t(v)) +
                             " is an infinitely sharp corner with fewer than two sharp edges "
                             "(a cone point); Gregory patches cannot represent it");
    }
  }
  if (creases.patch_faces == 0) {
    throw UnsupportedInput(prefix(mesh) + "no face has a limit surface (all are holes)");
  }
  if (refine && creases.levels_needed == 0) {
    creases.notes.push_back(
        "non-quad faces with creases, corners, holes or edge-only/none boundaries: the mesh "
        "was refined once (OpenSubdiv) and patched with quads");
  }
  if (std::string error = buildRings(creases.control).error; !error.empty()) {
    throw UnsupportedInput(error);
  }
  return creases;
}

}  // namespace

std::string checkGregorySupport(const Mesh& mesh) {
  if (std::string error = checkInput(mesh); !error.empty()) return error;
  try {
    prepareGregoryCreases(mesh, NonQuadFaces::kTrianglePatches, kDefaultCreaseFaceBudget);
  } catch (const UnsupportedInput& error) {
    return error.what();
  }
  return {};
}

namespace {

// Builds the stencil table of buildGregoryStencils. Stencils are emitted in a fixed order
// (vertex positions, then edge points in face order, then face points per face and
// corner) so that every shared point is one stencil computed once: both patches that
// use it read the same weights (docs/ARCHITECTURE.md §5, rule 1). Around crease and
// corner vertices each face uses its own sector's ring; a P or E(v->w) that more than one
// sector could form (P of a crease or corner vertex, E along a sharp edge) is formed from
// every such sector and required to come out identical before it is shared.
class StencilBuilder {
 public:
  StencilBuilder(const CreasePreparation& creases, TangentMask mask)
      : mesh_(creases.control), creases_(creases), mask_(mask) {
    const std::vector<Ring> whole = buildRings(mesh_).rings;
    sectors_.resize(whole.size());
    for (uint32_t v = 0; v < whole.size(); ++v) {
      if (whole[v].valence() > 0) sectors_[v] = sectorsOf(v, whole[v], creases_);
    }
    // Vertices with a non-quad face around them take their frame from the mesh refined
    // once (refinedFrame); all-quad rings keep the direct masks. (Non-quad faces come
    // with the plain rules only: prepareGregoryCreases refines the rest.)
    if (!mesh_.allFacesOfSize(4)) {
      refined_ = refineOnce(mesh_);
      refined_rings_ = buildRings(refined_->mesh).rings;
    }
  }

  GregoryStencils build() {
    const size_t patches = creases_.patch_faces;
    frames_.resize(sectors_.size());
    position_id_.assign(sectors_.size(), UINT32_MAX);
    std::vector<uint8_t> used(sectors_.size(), 0);
    for (size_t f = 0; f < patches; ++f) {
      for (uint32_t v : mesh_.facePositions(f)) used[v] = 1;
    }
    for (uint32_t v = 0; v < sectors_.size(); ++v) {
      if (!used[v]) continue;  // only on holes: no patch reads it
      for (const Ring& ring : sectors_[v]) frames_[v].push_back(frameOf(v, ring));
      position_id_[v] = emit(sharedPosition(v));
    }
    // Edge stencils first, in face order, so all shared stencils precede the face points.
    for (size_t f = 0; f < patches; ++f) {
      const auto fv = mesh_.facePositions(f);
      const uint32_t size = uint32_t(fv.size());
      for (uint32_t c = 0; c < size; ++c) {
        edgeId(fv[c], fv[(c + 1) % size]);
        edgeId(fv[c], fv[(c + size - 1) % size]);
      }
    }
    out_.sharedStencilCount = out_.stencilCount();
    out_.patch_points.resize(patches);
    for (size_t f = 0; f < patches; ++f) emitFacePoints(f);
    return std::move(out_);
  }

 private:
  VertexFrame frameOf(uint32_t v, const Ring& ring) const {
    if (ring.corner) {  // interpolated; edge points from cornerEdgePoint
      VertexFrame frame;
      add(frame.position, v, 1.0);
      return frame;
    }
    if (ring.quads_only) {
      return ring.boundary ? boundaryFrame(v, ring) : vertexFrame(v, ring, mask_);
    }
    // A whole ring here (rings with non-quad faces are never cut into sectors).
    Ring local = refined_rings_[v];
    if (!local.boundary) {  // start where the input ring starts (boundary rings already do)
      const uint32_t first = local.indexOf(refined_->edgePoint(v, ring.neighbour[0]));
      std::rotate(local.neighbour.begin(), local.neighbour.begin() + first, local.neighbour.end());
      std::rotate(local.diagonal.begin(), local.diagonal.begin() + first, local.diagonal.end());
    }
    return refinedFrame(v, local, *refined_, mask_);
  }

  // P of v: every sector's (a crease vertex's sectors all give the crease curve's limit
  // point, a corner's all give v), checked equal term by term.
  Stencil sharedPosition(uint32_t v) const {
    const Stencil first = pruned(frames_[v].front().position);
    for (const VertexFrame& frame : frames_[v]) {
      if (pruned(frame.position) != first) {
        throw std::logic_error(prefix(mesh_) + "the sectors of vertex " + std::to_string(v) +
                               " disagree on its limit position");
      }
    }
    return first;
  }

  // The sector of v whose face follows the edge v -> w (counter-clockwise).
  uint32_t sectorWithFaceAfter(uint32_t v, uint32_t w) const {
    const std::vector<Ring>& sectors = sectors_[v];
    for (uint32_t s = 0; s < sectors.size(); ++s) {
      if (sectors[s].indexOf(w) < sectors[s].faces()) return s;
    }
    throw std::logic_error(prefix(mesh_) + "no sector of vertex " + std::to_string(v) +
                           " has a face after its edge to " + std::to_string(w));
  }

  uint32_t emit(const Stencil& s) {
    for (const auto& [index, weight] : s) {
      if (std::abs(weight) < 1e-14) continue;  // cancelled terms (e.g. r on a regular ring)
      out_.indices.push_back(index);
      out_.weights.push_back(weight);
    }
    out_.offsets.push_back(uint32_t(out_.indices.size()));
    return uint32_t(out_.offsets.size() - 2);
  }

  // E(v -> w) as sector s of v forms it.
  Stencil edgePointIn(uint32_t v, uint32_t s, uint32_t w) const {
    const Ring& ring = sectors_[v][s];
    if (ring.corner) return cornerEdgePoint(v, ring, w);
    const VertexFrame& frame = frames_[v][s];
    const uint32_t j = ring.indexOf(w);
    Stencil e = frame.position;
    // Interior: angle 2 pi j / n; boundary or sector with k faces: pi j / k = 2 pi j / (2k).
    const uint32_t n = ring.effectiveValence();
    add(e, frame.e0, cosTurn(j, n));
    add(e, frame.e1, sinTurn(j, n));
    return e;
  }

  // E(v -> w): along a sharp edge of a crease or corner vertex both sectors at the edge
  // form it (the crease curve's Bézier point); they must agree term by term.
  Stencil edgePoint(uint32_t v, uint32_t w) const {
    std::optional<Stencil> e;
    for (uint32_t s = 0; s < sectors_[v].size(); ++s) {
      if (sectors_[v][s].indexOf(w) == UINT32_MAX) continue;
      Stencil candidate = pruned(edgePointIn(v, s, w));
      if (!e) {
        e = std::move(candidate);
      } else if (*e != candidate) {
        throw std::logic_error(prefix(mesh_) + "the sectors of vertex " + std::to_string(v) +
                               " disagree on the edge point toward " + std::to_string(w));
      }
    }
    if (!e) {
      throw std::logic_error(prefix(mesh_) + "vertex " + std::to_string(w) +
                             " is not a neighbour of " + std::to_string(v));
    }
    return *e;
  }

  uint32_t edgeId(uint32_t v, uint32_t w) {
    const auto [it, inserted] = edge_id_.emplace(directedKey(v, w), 0);
    if (inserted) it->second = emit(edgePoint(v, w));
    return it->second;
  }

  // Face points, Loop et al. 2009 eq. for the interior Gregory points (as in OpenSubdiv
  // Far's Gregory basis): with c_n = cos(2 pi/n),
  //   Fp = (c_np P + (3 - 2 c_n - c_np) Ep + 2 c_n Em(ip) + r_start) / 3,
  //   Fm = (c_nm P + (3 - 2 c_n - c_nm) Em + 2 c_n Ep(im) - r_prev) / 3,
  // for corner v of a face with next corner ip and previous corner im; `after_ip` is the
  // corner after ip (im on a triangle). Each of v, ip, im uses its sector holding the face.
  std::pair<Stencil, Stencil> facePoints(uint32_t v, uint32_t ip, uint32_t im,
                                         uint32_t after_ip) const {
    const uint32_t sector = sectorWithFaceAfter(v, ip);
    const Ring& ring = sectors_[v][sector];
    const Ring& ring_ip = sectors_[ip][sectorWithFaceAfter(ip, after_ip)];
    const Ring& ring_im = sectors_[im][sectorWithFaceAfter(im, v)];
    const uint32_t n = ring.effectiveValence(), np = ring_ip.effectiveValence(),
                   nm = ring_im.effectiveValence();
    const uint32_t start = ring.indexOf(ip);             // the face is ring face `start`
    const uint32_t prev = (start + 1) % ring.valence();  // ring index of im
    const double cn = cosTurn(1, n), cnp = cosTurn(1, np), cnm = cosTurn(1, nm);
    const Stencil& position = frames_[v][sector].position;
    // On a boundary or a sharp edge there is no continuity to keep across the edge: the
    // face point next to it takes the other one's value (as Far's Gregory basis does),
    // and the twist across it is never formed. With both edges open (a one-face corner or
    // crease sector) the face point is the bicubic B-spline's, (4 v + 2 ip + 2 im + d) / 9.
    const bool ip_edge_open = ring.boundary && start == 0;
    const bool im_edge_open = ring.boundary && prev + 1 == ring.valence();
    auto plusPoint = [&] {
      Stencil fp;
      add(fp, position, cnp / 3);
      add(fp, edgePoint(v, ip), (3 - 2 * cn - cnp) / 3);
      add(fp, edgePoint(ip, v), 2 * cn / 3);
      add(fp, twist(ring, start), 1.0 / 3);
      return fp;
    };
    auto minusPoint = [&] {
      Stencil fm;
      add(fm, position, cnm / 3);
      add(fm, edgePoint(v, im), (3 - 2 * cn - cnm) / 3);
      add(fm, edgePoint(im, v), 2 * cn / 3);
      add(fm, twist(ring, prev), -1.0 / 3);
      return fm;
    };
    Stencil fp, fm;
    if (ip_edge_open && im_edge_open) {
      add(fp, v, 4.0 / 9);
      add(fp, ring.diagonal[0], 1.0 / 9);
      add(fp, ip, 2.0 / 9);
      add(fp, im, 2.0 / 9);
      fm = fp;
    } else if (ip_edge_open) {
      fp = fm = minusPoint();
    } else if (im_edge_open) {
      fp = fm = plusPoint();
    } else {
      fp = plusPoint();
      fm = minusPoint();
    }
    return {std::move(fp), std::move(fm)};
  }

  // Triangle: the quartic interior points. The patch's derivative along its edge toward
  // the opposite corner equals that of a quad with face points F (the triangle "is a
  // quad" to each of its neighbours), which holds when G = (E + 3 F) / 4 for the edge
  // point E and face point F at the same corner.
  Stencil triangleInteriorPoint(const Stencil& edge_point, const Stencil& face_point) const {
    Stencil g;
    add(g, edge_point, 0.25);
    add(g, face_point, 0.75);
    return g;
  }

  void emitFacePoints(size_t f) {
    const auto fv = mesh_.facePositions(f);
    const uint32_t size = uint32_t(fv.size());
    auto& points = out_.patch_points[f];
    points.fill(kNoStencil);
    for (uint32_t c = 0; c < size; ++c) {
      const uint32_t v = fv[c], ip = fv[(c + 1) % size], im = fv[(c + size - 1) % size];
      auto [fp, fm] = facePoints(v, ip, im, fv[(c + 2) % size]);
      if (size == 3) {
        fp = triangleInteriorPoint(edgePoint(v, ip), fp);
        fm = triangleInteriorPoint(edgePoint(v, im), fm);
      }
      points[c * 5 + kP] = position_id_[v];
      points[c * 5 + kEp] = edgeId(v, ip);
      points[c * 5 + kEm] = edgeId(v, im);
      points[c * 5 + kFp] = emit(fp);
      points[c * 5 + kFm] = emit(fm);
    }
  }

  const Mesh& mesh_;
  const CreasePreparation& creases_;
  const TangentMask mask_;
  std::vector<std::vector<Ring>> sectors_;  // per position: its whole ring or its sectors
  std::optional<RefinedMesh> refined_;
  std::vector<Ring> refined_rings_;
  std::vector<std::vector<VertexFrame>> frames_;  // per position, per sector
  std::vector<uint32_t> position_id_;
  std::unordered_map<uint64_t, uint32_t> edge_id_;
  GregoryStencils out_;
};

// The plain rules' preparation of a mesh that has no sharp features beyond its
// edge-and-corner boundary (refineOnce's output, buildGregoryStencils' input): never refined.
CreasePreparation plainPreparation(const Mesh& mesh) {
  return prepareCreases(mesh, "gregory_acc", 0);
}

GregoryStencils stencilsOver(const CreasePreparation& creases, TangentMask mask) {
  for (size_t f = 0; f < creases.control.faceCount(); ++f) {
    if (creases.control.faceSize(f) != 3 && creases.control.faceSize(f) != 4) {
      throw UnsupportedInput(prefix(creases.control) + describeFace(creases.control, f) +
                             ": buildGregoryStencils needs quads and triangles only");
    }
  }
  return StencilBuilder(creases, mask).build();
}

}  // namespace

GregoryStencils buildGregoryStencils(const Mesh& mesh, TangentMask mask) {
  if (std::string reason = checkInput(mesh); !reason.empty()) throw UnsupportedInput(reason);
  return stencilsOver(plainPreparation(mesh), mask);
}

GregoryBuild buildGregory(const Mesh& mesh, TangentMask mask, NonQuadFaces non_quads,
                          size_t crease_face_budget) {
  if (std::string reason = checkInput(mesh); !reason.empty()) throw UnsupportedInput(reason);
  GregoryBuild out;
  out.creases = prepareGregoryCreases(mesh, non_quads, crease_face_budget);
  const Mesh& base = out.creases.control;
  if (nativeFaces(base, non_quads)) {
    out.control = base;
    out.stencils = stencilsOver(out.creases, mask);
    out.patch_count = out.creases.patch_faces;
    out.source_face.assign(out.creases.source_face.begin(),
                           out.creases.source_face.begin() + ptrdiff_t(out.patch_count));
    return out;
  }
  // Here `base` is the input itself with its plain rules (prepareGregoryCreases refines a
  // mesh with non-native faces and sharp features), so refineOnce is exact.
  RefinedMesh refined = refineOnce(base);
  const GregoryStencils level1 = stencilsOver(plainPreparation(refined.mesh), mask);
  out.refined = true;
  out.control = std::move(refined.mesh);
  out.patch_count = out.control.faceCount();
  for (uint32_t face : refined.source_face) out.source_face.push_back(out.creases.source_face[face]);
  out.stencils.patch_points = level1.patch_points;
  out.stencils.sharedStencilCount = level1.sharedStencilCount;
  // Compose: each Gregory stencil over refined vertices becomes one over input vertices,
  // still ascending by vertex index; stencils keep their ids, so sharing is unchanged.
  for (size_t s = 0; s < level1.stencilCount(); ++s) {
    Stencil composed;
    for (uint32_t k = level1.offsets[s]; k < level1.offsets[s + 1]; ++k) {
      add(composed, refined.stencils[level1.indices[k]], level1.weights[k]);
    }
    for (const auto& [index, weight] : composed) {
      if (std::abs(weight) < 1e-14) continue;
      out.stencils.indices.push_back(index);
      out.stencils.weights.push_back(weight);
    }
    out.stencils.offsets.push_back(uint32_t(out.stencils.indices.size()));
  }
  return out;
}

}  // namespace tb::gregory_acc
