#include "techniques/common/quad_ring.h"

#include <sstream>
#include <unordered_map>

#include "core/mesh/topology.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/technique.h"

namespace tb::techniques {
namespace {

uint64_t directedKey(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

struct CornerRef {
  uint32_t face;
  uint32_t corner;  // 0..3
};

[[noreturn]] void failInput(const std::string& technique, const std::string& what) {
  throw UnsupportedInput(technique + ": " + what);
}

// Every directed edge c_k -> c_{k+1} of the quads, and the corners at each vertex.
struct CornerIndex {
  std::unordered_map<uint64_t, CornerRef> outgoing;
  std::vector<std::vector<CornerRef>> corners_of;
};

CornerIndex indexCorners(const mesh::Mesh& mesh, const std::string& technique) {
  const auto fail = [&](const std::string& what) { failInput(technique, what); };
  const size_t face_count = mesh.faceCount();
  CornerIndex index;
  std::unordered_map<uint64_t, CornerRef>& outgoing =
      index.outgoing;  // directed edge c_k -> c_{k+1}
  outgoing.reserve(face_count * 4);
  index.corners_of.resize(mesh.positions.size());
  for (uint32_t f = 0; f < face_count; ++f) {
    if (mesh.faceSize(f) != 4) {
      fail(mesh::describeFace(mesh, f) + " has " + std::to_string(mesh.faceSize(f)) +
           " vertices; needs quads");
    }
    const auto c = mesh.facePositions(f);
    for (uint32_t k = 0; k < 4; ++k) {
      for (uint32_t j = k + 1; j < 4; ++j) {
        if (c[k] == c[j])
          fail(mesh::describeFace(mesh, f) + " repeats a vertex; needs proper quads");
      }
    }
    for (uint32_t k = 0; k < 4; ++k) {
      const auto [it, inserted] =
          outgoing.emplace(directedKey(c[k], c[(k + 1) % 4]), CornerRef{f, k});
      if (!inserted) {
        fail("edge " + std::to_string(c[k]) + "-" + std::to_string(c[(k + 1) % 4]) + " of " +
             mesh::describeFace(mesh, f) + " is also used by " +
             mesh::describeFace(mesh, it->second.face) +
             " in the same direction (non-manifold or inconsistently oriented)");
      }
      index.corners_of[c[k]].push_back({f, k});
    }
  }
  return index;
}

// Walks the faces around each vertex, one ring per sector, into `rings`.
class RingWalker {
 public:
  RingWalker(const mesh::Mesh& mesh, const std::string& technique, uint32_t max_valence,
             const CreasePreparation* creases, const CornerIndex& index, QuadRings& rings)
      : mesh_(mesh),
        technique_(technique),
        max_valence_(max_valence),
        creases_(creases),
        outgoing_(index.outgoing),
        rings_(rings) {}

  void walkVertex(uint32_t v, const std::vector<CornerRef>& corners) {
    // Sector starts: the corners whose e_i edge ends a sector (no face on the other side,
    // or sharp at a splitting vertex). None: one interior ring.
    std::vector<size_t> starts;
    size_t boundary_starts = 0;
    for (size_t c = 0; c < corners.size(); ++c) {
      const uint32_t e = cornerVertex(corners[c], 1);
      const bool open = !outgoing_.count(directedKey(e, v));
      boundary_starts += open;
      if (open || (splits(v) && creases_->isSharp(v, e))) starts.push_back(c);
    }
    if (boundary_starts > 1)
      fail(describeVertex(mesh_, v) + " has faces in more than one fan (non-manifold vertex)");
    const bool interior = starts.empty();
    if (interior) starts.push_back(0);
    size_t walked = 0;
    for (size_t s = 0; s < starts.size(); ++s) {
      const VertexRing ring = walkSector(v, corners, starts[s], s, interior);
      walked += ring.face_count;
      if (ring.valence > max_valence_) {
        fail(describeVertex(mesh_, v) + " has valence " + std::to_string(ring.valence) +
             " above the maximum " + std::to_string(max_valence_));
      }
      if (s == 0) {
        rings_.rings[v] = ring;
      } else {
        rings_.rings.push_back(ring);
      }
    }
    if (walked != corners.size()) {
      fail(describeVertex(mesh_, v) + " has faces in more than one fan (non-manifold vertex)");
    }
  }

 private:
  void fail(const std::string& what) const { failInput(technique_, what); }

  uint32_t cornerVertex(CornerRef r, uint32_t step) const {
    return mesh_.facePositions(r.face)[(r.corner + step) % 4];
  }
  bool splits(uint32_t v) const {
    if (creases_ == nullptr) return false;
    const SharpVertexKind kind = creases_->vertex_kind[v];
    return kind == SharpVertexKind::kCrease || kind == SharpVertexKind::kCorner;
  }
  // A sector ends at an edge with no face beyond it or, at a splitting vertex, a sharp one.
  bool endsSector(uint32_t v, uint32_t w) const {
    return !outgoing_.count(directedKey(v, w)) || !outgoing_.count(directedKey(w, v)) ||
           (splits(v) && creases_->isSharp(v, w));
  }

  // The ring of sector `s` of `v`, from corner `start`: its slots, neighbours and diagonals.
  VertexRing walkSector(uint32_t v, const std::vector<CornerRef>& corners, size_t start, size_t s,
                        bool interior) {
    CornerRef r = corners[start];
    VertexRing ring;
    ring.vertex = v;
    ring.offset = uint32_t(rings_.edge_neighbours.size());
    ring.boundary = !interior;
    ring.corner =
        creases_ != nullptr ? creases_->vertex_kind[v] == SharpVertexKind::kCorner : false;
    const uint32_t index = s == 0 ? v : uint32_t(rings_.rings.size());
    for (;;) {
      rings_.face_slots[r.face][r.corner] = ring.face_count;
      rings_.face_rings[r.face][r.corner] = index;
      rings_.edge_neighbours.push_back(cornerVertex(r, 1));
      rings_.diagonals.push_back(cornerVertex(r, 2));
      ++ring.face_count;
      const uint32_t next_edge = cornerVertex(r, 3);
      if (!interior && endsSector(v, next_edge)) {
        rings_.edge_neighbours.push_back(next_edge);
        rings_.diagonals.push_back(UINT32_MAX);
        break;
      }
      // Next face: the one holding the directed edge v -> e_{i+1}.
      const auto next = outgoing_.find(directedKey(v, next_edge));
      if (next == outgoing_.end()) break;  // cannot happen: endsSector caught it
      r = next->second;
      if (interior && r.face == corners[0].face && r.corner == corners[0].corner) break;
      if (ring.face_count > corners.size()) break;  // cannot happen on a consistent mesh
    }
    ring.valence = ring.boundary ? ring.face_count + 1 : ring.face_count;
    if (creases_ == nullptr && ring.boundary && ring.valence == 2) ring.corner = true;
    return ring;
  }

  const mesh::Mesh& mesh_;
  const std::string& technique_;
  uint32_t max_valence_;
  const CreasePreparation* creases_;
  const std::unordered_map<uint64_t, CornerRef>& outgoing_;
  QuadRings& rings_;
};

}  // namespace

void requireManifoldQuads(const mesh::Mesh& mesh, const std::string& technique,
                          const std::string& why_quads, const std::string& why_manifold) {
  const auto fail = [&](const std::string& what) {
    throw UnsupportedInput(technique + ": " + what);
  };
  if (mesh.faceCount() == 0) fail(mesh.source + " has no faces");
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.faceSize(f) != 4) {
      fail(mesh::describeFace(mesh, f) + " has " + std::to_string(mesh.faceSize(f)) +
           " vertices; " + why_quads);
    }
  }
  for (const mesh::MeshEdge& edge : mesh::buildTopology(mesh).edges) {
    if (edge.face_count > 2) {
      fail("edge " + std::to_string(edge.v0) + "-" + std::to_string(edge.v1) + " is shared by " +
           std::to_string(edge.face_count) + " faces; " + why_manifold);
    }
  }
}

std::string describeVertex(const mesh::Mesh& mesh, uint32_t vertex) {
  std::ostringstream text;
  text << "vertex " << vertex;
  if (vertex < mesh.positions.size()) {
    const mesh::Vec3d& p = mesh.positions[vertex];
    text << " (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  return text.str();
}

QuadRings buildQuadRings(const mesh::Mesh& mesh, const std::string& technique, uint32_t max_valence,
                         const CreasePreparation* creases) {
  const size_t face_count = mesh.faceCount();
  const CornerIndex index = indexCorners(mesh, technique);
  QuadRings rings;
  rings.rings.resize(mesh.positions.size());
  rings.face_slots.assign(face_count, {0, 0, 0, 0});
  rings.face_rings.assign(face_count, {0, 0, 0, 0});
  RingWalker walker(mesh, technique, max_valence, creases, index, rings);
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const std::vector<CornerRef>& corners = index.corners_of[v];
    if (corners.empty()) continue;
    walker.walkVertex(v, corners);
  }
  return rings;
}

}  // namespace tb::techniques
