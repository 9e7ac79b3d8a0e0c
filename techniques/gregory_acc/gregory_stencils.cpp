#include "techniques/gregory_acc/gregory_stencils.h"

#include <cmath>
#include <map>
#include <numbers>
#include <unordered_map>

#include "harness/mesh/topology.h"
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

// The 1-ring of an interior vertex of an all-quad mesh, counter-clockwise: face i is
// (v, neighbour[i], diagonal[i], neighbour[i + 1]) in the face's own winding.
struct Ring {
  std::vector<uint32_t> neighbour;
  std::vector<uint32_t> diagonal;
  uint32_t valence() const { return uint32_t(neighbour.size()); }
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
  // limit tangent plane. kFarCompatible: a = 4 (1 + c), what averaging the ACC face
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
  std::vector<uint32_t> first_face(mesh.positions.size(), UINT32_MAX);
  std::vector<uint32_t> face_count(mesh.positions.size(), 0);
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
      if (first_face[a] == UINT32_MAX) first_face[a] = uint32_t(f);
      ++face_count[a];
    }
  }
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    if (first_face[v] == UINT32_MAX) continue;
    Ring& ring = out.rings[v];
    uint32_t f = first_face[v];
    for (uint32_t step = 0; step <= face_count[v]; ++step) {
      const auto fv = mesh.facePositions(f);
      const size_t size = fv.size();
      uint32_t k = 0;
      while (fv[k] != v) ++k;
      ring.neighbour.push_back(fv[(k + 1) % size]);
      ring.diagonal.push_back(fv[(k + 2) % size]);  // meaningful on quads only
      const auto next = face_of_directed.find(directedKey(v, fv[(k + size - 1) % size]));
      if (next == face_of_directed.end()) {
        out.error = prefix(mesh) + "vertex " + std::to_string(v) + " is on a boundary";
        return out;
      }
      f = next->second;
      if (f == first_face[v]) break;
    }
    if (ring.valence() != face_count[v]) {
      out.error = prefix(mesh) + "vertex " + std::to_string(v) +
                  " is non-manifold (its faces form more than one fan)";
      return out;
    }
    if (ring.valence() < 3 || ring.valence() > kMaxValence) {
      out.error = prefix(mesh) + "vertex " + std::to_string(v) + " has valence " +
                  std::to_string(ring.valence()) + "; gregory_acc needs 3.." +
                  std::to_string(kMaxValence);
      return out;
    }
  }
  return out;
}

}  // namespace

std::string checkGregorySupport(const Mesh& mesh) {
  if (mesh.faceCount() == 0) return prefix(mesh) + "has no faces";
  for (const Crease& crease : mesh.tags.creases) {
    if (crease.sharpness > 0) {
      return prefix(mesh) + "crease edge (" + std::to_string(crease.v0) + ", " +
             std::to_string(crease.v1) + ") has sharpness " + std::to_string(crease.sharpness) +
             "; creases are not supported";
    }
  }
  for (const Corner& corner : mesh.tags.corners) {
    if (corner.sharpness > 0) {
      return prefix(mesh) + "corner vertex " + std::to_string(corner.vertex) +
             " is tagged sharp; corner tags are not supported";
    }
  }
  if (!mesh.tags.holes.empty()) {
    return prefix(mesh) + "face " + std::to_string(mesh.tags.holes.front()) +
           " is tagged as a hole; holes are not supported";
  }
  if (mesh.tags.smooth_triangles) {
    return prefix(mesh) + "`t smoothtriangles` is not supported (plain Catmull-Clark only)";
  }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t size = mesh.faceSize(f);
    if (size < 3 || size > kMaxValence) {
      return prefix(mesh) + describeFace(mesh, f) + " has " + std::to_string(size) +
             " vertices; gregory_acc needs 3.." + std::to_string(kMaxValence);
    }
    const auto fv = mesh.facePositions(f);
    for (uint32_t a = 0; a < size; ++a) {
      for (uint32_t b = a + 1; b < size; ++b) {
        if (fv[a] == fv[b]) {
          return prefix(mesh) + describeFace(mesh, f) + " repeats vertex " +
                 std::to_string(fv[a]);
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
  for (const MeshEdge& edge : topology.edges) {
    if (edge.face_count == 1) {
      return prefix(mesh) + "boundary edge (" + std::to_string(edge.v0) + ", " +
             std::to_string(edge.v1) + "); boundaries are not supported";
    }
  }
  return buildRings(mesh).error;
}

GregoryStencils buildGregoryStencils(const Mesh& mesh, TangentMask mask) {
  if (std::string reason = checkGregorySupport(mesh); !reason.empty()) {
    throw UnsupportedInput(reason);
  }
  if (!mesh.allFacesOfSize(4)) {
    throw UnsupportedInput(prefix(mesh) + "buildGregoryStencils needs an all-quad mesh");
  }
  const std::vector<Ring> rings = buildRings(mesh).rings;
  GregoryStencils out;
  auto emit = [&out](const Stencil& s) {
    for (const auto& [index, weight] : s) {
      if (std::abs(weight) < 1e-14) continue;  // cancelled terms (e.g. r on a regular ring)
      out.indices.push_back(index);
      out.weights.push_back(weight);
    }
    out.offsets.push_back(uint32_t(out.indices.size()));
    return uint32_t(out.offsets.size() - 2);
  };

  std::vector<VertexFrame> frames(rings.size());
  std::vector<uint32_t> position_id(rings.size(), UINT32_MAX);
  std::unordered_map<uint64_t, uint32_t> edge_id;
  for (uint32_t v = 0; v < rings.size(); ++v) {
    if (rings[v].valence() == 0) continue;
    frames[v] = vertexFrame(v, rings[v], mask);
    position_id[v] = emit(frames[v].position);
  }
  auto edgePoint = [&](uint32_t v, uint32_t w) {
    const Ring& ring = rings[v];
    const uint32_t k = ring.indexOf(w);
    Stencil e = frames[v].position;
    add(e, frames[v].e0, cosTurn(k, ring.valence()));
    add(e, frames[v].e1, sinTurn(k, ring.valence()));
    return e;
  };
  auto edgeId = [&](uint32_t v, uint32_t w) {
    const auto [it, inserted] = edge_id.emplace(directedKey(v, w), 0);
    if (inserted) it->second = emit(edgePoint(v, w));
    return it->second;
  };
  // Edge stencils first, in face order, so all shared stencils precede the face points.
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (uint32_t c = 0; c < 4; ++c) {
      edgeId(fv[c], fv[(c + 1) % 4]);
      edgeId(fv[c], fv[(c + 3) % 4]);
    }
  }
  out.sharedStencilCount = out.stencilCount();

  out.patch_points.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    auto& points = out.patch_points[f];
    for (uint32_t c = 0; c < 4; ++c) {
      const uint32_t v = fv[c], ip = fv[(c + 1) % 4], im = fv[(c + 3) % 4];
      const Ring& ring = rings[v];
      const uint32_t n = ring.valence(), np = rings[ip].valence(), nm = rings[im].valence();
      const uint32_t start = ring.indexOf(ip);  // face f is ring face `start`
      const uint32_t prev = (start + 1) % n;    // ring index of im
      // Face points, Loop et al. 2009 eq. for the interior Gregory points (as in
      // OpenSubdiv Far's Gregory basis): with c_n = cos(2 pi/n),
      //   Fp = (c_np P + (3 - 2 c_n - c_np) Ep + 2 c_n Em(ip) + r_start) / 3,
      //   Fm = (c_nm P + (3 - 2 c_n - c_nm) Em + 2 c_n Ep(im) - r_prev) / 3.
      const double cn = cosTurn(1, n), cnp = cosTurn(1, np), cnm = cosTurn(1, nm);
      const Stencil ep = edgePoint(v, ip), em = edgePoint(v, im);
      Stencil fp, fm;
      add(fp, frames[v].position, cnp / 3);
      add(fp, ep, (3 - 2 * cn - cnp) / 3);
      add(fp, edgePoint(ip, v), 2 * cn / 3);
      add(fp, twist(ring, start), 1.0 / 3);
      add(fm, frames[v].position, cnm / 3);
      add(fm, em, (3 - 2 * cn - cnm) / 3);
      add(fm, edgePoint(im, v), 2 * cn / 3);
      add(fm, twist(ring, prev), -1.0 / 3);
      points[c * 5 + kP] = position_id[v];
      points[c * 5 + kEp] = edgeId(v, ip);
      points[c * 5 + kEm] = edgeId(v, im);
      points[c * 5 + kFp] = emit(fp);
      points[c * 5 + kFm] = emit(fm);
    }
  }
  return out;
}

GregoryBuild buildGregory(const Mesh& mesh, TangentMask mask) {
  if (std::string reason = checkGregorySupport(mesh); !reason.empty()) {
    throw UnsupportedInput(reason);
  }
  GregoryBuild out;
  if (mesh.allFacesOfSize(4)) {
    out.control = mesh;
    out.stencils = buildGregoryStencils(mesh, mask);
    out.source_face.resize(mesh.faceCount());
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) out.source_face[f] = f;
    return out;
  }
  RefinedMesh refined = refineOnce(mesh);
  const GregoryStencils level1 = buildGregoryStencils(refined.mesh, mask);
  out.refined = true;
  out.control = std::move(refined.mesh);
  out.source_face = std::move(refined.source_face);
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
