#include "techniques/common/quad_ring.h"

#include <sstream>
#include <unordered_map>

#include "techniques/technique.h"

namespace tb {
namespace {

uint64_t directedKey(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

struct CornerRef {
  uint32_t face;
  uint32_t corner;  // 0..3
};

}  // namespace

std::string describeVertex(const Mesh& mesh, uint32_t vertex) {
  std::ostringstream text;
  text << "vertex " << vertex;
  if (vertex < mesh.positions.size()) {
    const Vec3d& p = mesh.positions[vertex];
    text << " (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  return text.str();
}

QuadRings buildQuadRings(const Mesh& mesh, const std::string& technique, uint32_t max_valence) {
  const auto fail = [&](const std::string& what) { throw UnsupportedInput(technique + ": " + what); };
  const size_t face_count = mesh.faceCount();
  std::unordered_map<uint64_t, CornerRef> outgoing;  // directed edge c_k -> c_{k+1}
  outgoing.reserve(face_count * 4);
  std::vector<std::vector<CornerRef>> corners_of(mesh.positions.size());
  for (uint32_t f = 0; f < face_count; ++f) {
    if (mesh.faceSize(f) != 4) {
      fail(describeFace(mesh, f) + " has " + std::to_string(mesh.faceSize(f)) +
           " vertices; needs quads");
    }
    const auto c = mesh.facePositions(f);
    for (uint32_t k = 0; k < 4; ++k) {
      for (uint32_t j = k + 1; j < 4; ++j) {
        if (c[k] == c[j]) fail(describeFace(mesh, f) + " repeats a vertex; needs proper quads");
      }
    }
    for (uint32_t k = 0; k < 4; ++k) {
      const auto [it, inserted] = outgoing.emplace(directedKey(c[k], c[(k + 1) % 4]), CornerRef{f, k});
      if (!inserted) {
        fail("edge " + std::to_string(c[k]) + "-" + std::to_string(c[(k + 1) % 4]) + " of " +
             describeFace(mesh, f) + " is also used by " + describeFace(mesh, it->second.face) +
             " in the same direction (non-manifold or inconsistently oriented)");
      }
      corners_of[c[k]].push_back({f, k});
    }
  }
  const auto cornerVertex = [&](CornerRef r, uint32_t step) {
    return mesh.facePositions(r.face)[(r.corner + step) % 4];
  };

  QuadRings rings;
  rings.rings.resize(mesh.positions.size());
  rings.face_slots.assign(face_count, {0, 0, 0, 0});
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const std::vector<CornerRef>& corners = corners_of[v];
    if (corners.empty()) continue;
    // The corner whose e_i edge has no face on the other side starts a boundary fan;
    // the face before corner r is the one with the directed edge e_i -> v.
    int start = -1;
    for (size_t c = 0; c < corners.size(); ++c) {
      if (!outgoing.count(directedKey(cornerVertex(corners[c], 1), v))) {
        if (start >= 0) fail(describeVertex(mesh, v) + " has faces in more than one fan (non-manifold vertex)");
        start = int(c);
      }
    }
    const bool boundary = start >= 0;
    CornerRef r = corners[boundary ? size_t(start) : 0];
    VertexRing ring;
    ring.offset = uint32_t(rings.edge_neighbours.size());
    ring.boundary = boundary;
    for (;;) {
      rings.face_slots[r.face][r.corner] = ring.face_count;
      rings.edge_neighbours.push_back(cornerVertex(r, 1));
      rings.diagonals.push_back(cornerVertex(r, 2));
      ++ring.face_count;
      // Next face: the one holding the directed edge v -> e_{i+1}.
      const auto next = outgoing.find(directedKey(v, cornerVertex(r, 3)));
      if (next == outgoing.end()) {
        rings.edge_neighbours.push_back(cornerVertex(r, 3));
        rings.diagonals.push_back(UINT32_MAX);
        break;
      }
      r = next->second;
      if (!boundary && r.face == corners[0].face && r.corner == corners[0].corner) break;
      if (ring.face_count > corners.size()) break;  // cannot happen on a consistent mesh
    }
    ring.valence = boundary ? ring.face_count + 1 : ring.face_count;
    if (ring.face_count != corners.size()) {
      fail(describeVertex(mesh, v) + " has faces in more than one fan (non-manifold vertex)");
    }
    if (ring.valence > max_valence) {
      fail(describeVertex(mesh, v) + " has valence " + std::to_string(ring.valence) +
           " above the maximum " + std::to_string(max_valence));
    }
    rings.rings[v] = ring;
  }
  return rings;
}

}  // namespace tb
