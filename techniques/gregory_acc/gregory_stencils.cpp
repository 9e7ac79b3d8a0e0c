#include "techniques/gregory_acc/gregory_stencils.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "core/mesh/topology.h"
#include "techniques/common/quad_ring.h"
#include "techniques/gregory_acc/gregory_refine.h"
#include "techniques/gregory_acc/gregory_rings.h"
#include "techniques/technique.h"

namespace tb::gregory_acc {
namespace {

bool nativeFaces(const mesh::Mesh& mesh, NonQuadFaces non_quads) {
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t size = mesh.faceSize(f);
    if (size != 4 && (size != 3 || non_quads != NonQuadFaces::kTrianglePatches)) return false;
  }
  return true;
}

// What the plain rings (buildRings, refineOnce) do not represent: creases, corner tags,
// holes, a boundary with an interpolation other than edge-and-corner (a closed mesh's
// boundary tag changes nothing).
bool hasSharpFeatures(const mesh::Mesh& mesh) {
  for (const mesh::Crease& crease : mesh.tags.creases) {
    if (crease.sharpness > 0) return true;
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    if (corner.sharpness > 0) return true;
  }
  if (!mesh.tags.holes.empty()) return true;
  return mesh.tags.boundary != mesh::BoundaryInterpolation::kEdgeAndCorner &&
         mesh::buildTopology(mesh).boundaryEdgeCount() > 0;
}

// The input rules that need no crease preparation.
std::string checkInput(const mesh::Mesh& mesh) {
  if (mesh.faceCount() == 0) return prefix(mesh) + "has no faces";
  if (mesh.tags.smooth_triangles) {
    return prefix(mesh) + "`t smoothtriangles` is not supported (plain Catmull-Clark only)";
  }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t size = mesh.faceSize(f);
    if (size < 3 || size > kMaxFaceSize) {
      return prefix(mesh) + mesh::describeFace(mesh, f) + " has " + std::to_string(size) +
             " vertices; gregory_acc needs 3.." + std::to_string(kMaxFaceSize);
    }
    const auto fv = mesh.facePositions(f);
    for (uint32_t a = 0; a < size; ++a) {
      for (uint32_t b = a + 1; b < size; ++b) {
        if (fv[a] == fv[b]) {
          return prefix(mesh) + mesh::describeFace(mesh, f) + " repeats vertex " +
                 std::to_string(fv[a]);
        }
      }
    }
  }
  const mesh::Topology topology = mesh::buildTopology(mesh);
  for (const mesh::MeshEdge& edge : topology.edges) {
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
techniques::CreasePreparation prepareGregoryCreases(const mesh::Mesh& mesh, NonQuadFaces non_quads,
                                                    size_t face_budget) {
  const bool refine = !nativeFaces(mesh, non_quads) && hasSharpFeatures(mesh);
  techniques::CreasePreparation creases =
      techniques::prepareCreases(mesh, "gregory_acc", face_budget, refine ? 1 : 0);
  for (size_t v = 0; v < creases.vertex_kind.size(); ++v) {
    if (creases.vertex_kind[v] == techniques::SharpVertexKind::kCone) {
      throw techniques::UnsupportedInput(
          prefix(mesh) + techniques::describeVertex(creases.control, uint32_t(v)) +
          " is an infinitely sharp corner with fewer than two sharp edges "
          "(a cone point); Gregory patches cannot represent it");
    }
  }
  if (creases.patch_faces == 0) {
    throw techniques::UnsupportedInput(prefix(mesh) +
                                       "no face has a limit surface (all are holes)");
  }
  if (refine && creases.levels_needed == 0) {
    creases.notes.push_back(
        "non-quad faces with creases, corners, holes or edge-only/none boundaries: the mesh "
        "was refined once (OpenSubdiv) and patched with quads");
  }
  if (std::string error = buildRings(creases.control).error; !error.empty()) {
    throw techniques::UnsupportedInput(error);
  }
  return creases;
}

}  // namespace

std::string checkGregorySupport(const mesh::Mesh& mesh) {
  if (std::string error = checkInput(mesh); !error.empty()) return error;
  try {
    prepareGregoryCreases(mesh, NonQuadFaces::kTrianglePatches,
                          techniques::kDefaultCreaseFaceBudget);
  } catch (const techniques::UnsupportedInput& error) {
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
  StencilBuilder(const techniques::CreasePreparation& creases, TangentMask mask)
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
    // A crease sector, or a mesh-boundary ring (every boundary vertex is a crease or corner
    // vertex): its refined sector with the crease rules' points. Framing the whole refined
    // ring instead gave every sector the smooth limit point and its own rotation of the
    // smooth tangents, so the sectors disagreed on the edge points along the sharp edges.
    if (ring.boundary) return refinedCreaseFrame(v, ring, refined_rings_[v], *refined_);
    // A whole closed ring (a smooth vertex or a dart: smooth rules, as refineOnce has them),
    // started where the input ring starts.
    Ring local = refined_rings_[v];
    const uint32_t first = local.indexOf(refined_->edgePoint(v, ring.neighbour[0]));
    std::rotate(local.neighbour.begin(), local.neighbour.begin() + first, local.neighbour.end());
    std::rotate(local.diagonal.begin(), local.diagonal.begin() + first, local.diagonal.end());
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

  const mesh::Mesh& mesh_;
  const techniques::CreasePreparation& creases_;
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
techniques::CreasePreparation plainPreparation(const mesh::Mesh& mesh) {
  return techniques::prepareCreases(mesh, "gregory_acc", 0);
}

GregoryStencils stencilsOver(const techniques::CreasePreparation& creases, TangentMask mask) {
  for (size_t f = 0; f < creases.control.faceCount(); ++f) {
    if (creases.control.faceSize(f) != 3 && creases.control.faceSize(f) != 4) {
      throw techniques::UnsupportedInput(prefix(creases.control) +
                                         mesh::describeFace(creases.control, f) +
                                         ": buildGregoryStencils needs quads and triangles only");
    }
  }
  return StencilBuilder(creases, mask).build();
}

}  // namespace

GregoryStencils buildGregoryStencils(const mesh::Mesh& mesh, TangentMask mask) {
  if (std::string reason = checkInput(mesh); !reason.empty())
    throw techniques::UnsupportedInput(reason);
  return stencilsOver(plainPreparation(mesh), mask);
}

GregoryBuild buildGregory(const mesh::Mesh& mesh, TangentMask mask, NonQuadFaces non_quads,
                          size_t crease_face_budget) {
  if (std::string reason = checkInput(mesh); !reason.empty())
    throw techniques::UnsupportedInput(reason);
  GregoryBuild out;
  out.creases = prepareGregoryCreases(mesh, non_quads, crease_face_budget);
  const mesh::Mesh& base = out.creases.control;
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
  for (uint32_t face : refined.source_face)
    out.source_face.push_back(out.creases.source_face[face]);
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
