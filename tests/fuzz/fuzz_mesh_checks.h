// Checks shared by the mesh readers' fuzz targets (fuzz_obj_loader, fuzz_gltf_loader): what a
// loader promises of a Mesh it returns, and the tb_mesh work a run does with it.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/mesh/bounds.h"
#include "core/mesh/mesh.h"
#include "core/mesh/render_vertices.h"
#include "core/mesh/topology.h"
#include "core/mesh/triangulate.h"
#include "tests/fuzz/fuzz_support.h"

namespace tb::fuzz {

inline bool finite(const tb::mesh::Vec3d& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// An attribute index of a corner: -1 (absent) or an element of `count`.
inline bool attributeIndexOk(int32_t index, size_t count) {
  return index == -1 || (index >= 0 && size_t(index) < count);
}

// What obj_loader.h and gltf_loader.h promise of a mesh they return: finite coordinates, faces of
// >= 3 corners whose indices are in range, tags naming existing vertices and faces.
inline void checkLoadedMesh(const tb::mesh::Mesh& mesh) {
  require(mesh.faceCount() > 0, "a loaded mesh has faces");
  require(mesh.face_offsets.front() == 0 &&
              mesh.face_offsets.back() == mesh.corner_positions.size() &&
              mesh.corner_normals.size() == mesh.corner_positions.size() &&
              mesh.corner_uvs.size() == mesh.corner_positions.size() &&
              mesh.face_lines.size() == mesh.faceCount(),
          "face offsets and per-corner arrays agree");
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    require(mesh.face_offsets[f] < mesh.face_offsets[f + 1] && mesh.faceSize(f) >= 3,
            "every face has at least 3 corners");
  }
  for (const tb::mesh::Vec3d& p : mesh.positions) require(finite(p), "positions are finite");
  for (const tb::mesh::Vec3d& n : mesh.normals) require(finite(n), "normals are finite");
  for (const tb::mesh::Vec2d& uv : mesh.uvs) {
    require(std::isfinite(uv.x) && std::isfinite(uv.y), "texture coordinates are finite");
  }
  for (size_t c = 0; c < mesh.corner_positions.size(); ++c) {
    require(mesh.corner_positions[c] < mesh.positions.size(), "corner positions in range");
    require(attributeIndexOk(mesh.corner_normals[c], mesh.normals.size()),
            "corner normals in range");
    require(attributeIndexOk(mesh.corner_uvs[c], mesh.uvs.size()), "corner uvs in range");
    // The default LoadOptions compute normals for a mesh that lacks any.
    require(mesh.corner_normals[c] >= 0, "every corner has a normal (read or computed)");
  }
  for (const tb::mesh::Crease& crease : mesh.tags.creases) {
    require(crease.v0 < mesh.positions.size() && crease.v1 < mesh.positions.size(),
            "crease tags name existing vertices");
    require(std::isfinite(crease.sharpness), "crease sharpness is finite");
  }
  for (const tb::mesh::Corner& corner : mesh.tags.corners) {
    require(corner.vertex < mesh.positions.size(), "corner tags name existing vertices");
    require(std::isfinite(corner.sharpness), "corner sharpness is finite");
  }
  for (uint32_t hole : mesh.tags.holes) {
    require(hole < mesh.faceCount(), "hole tags name existing faces");
  }
}

// The tb_mesh work a run does with an asset (the suite's listing, the techniques' and
// measures' topology, welding and triangulation), with their own consistency checks.
inline void useMesh(const tb::mesh::Mesh& mesh) {
  const tb::mesh::Topology topology = tb::mesh::buildTopology(mesh);
  require(topology.corner_edges.size() == mesh.corner_positions.size(), "one edge per face corner");
  for (uint32_t edge : topology.corner_edges) {
    require(edge < topology.edges.size(), "corner edges in range");
  }
  require(topology.face_component.size() == mesh.faceCount() &&
              (topology.component_count > 0) == (mesh.faceCount() > 0),
          "every face has a component");
  (void)topology.boundaryEdgeCount();
  (void)topology.nonManifoldEdgeCount();
  (void)topology.extraordinaryVertices(mesh.allFacesOfSize(3) ? 6 : 4);
  if (!topology.edges.empty()) {
    const tb::mesh::MeshEdge& first = topology.edges.front();
    require(topology.findEdge(first.v1, first.v0) == 0, "findEdge finds an edge either way");
  }

  const tb::mesh::Welding welding = tb::mesh::weldByPosition(mesh);
  require(welding.canonical.size() == mesh.positions.size() &&
              welding.unique_count <= mesh.positions.size(),
          "welding maps every position");
  for (uint32_t v = 0; v < welding.canonical.size(); ++v) {
    require(welding.canonical[v] <= v, "a position welds to itself or an earlier one");
  }

  const tb::mesh::Aabb bounds = tb::mesh::boundsOf(mesh);
  require(!std::isnan(tb::mesh::diagonalOf(bounds)), "the bounding box has a diagonal");
  (void)tb::mesh::describeFace(mesh, mesh.faceCount() - 1);
  (void)mesh.maxFaceSize();

  const tb::mesh::Triangulation triangles = tb::mesh::fanTriangulate(mesh);
  require(triangles.mesh.allFacesOfSize(3) &&
              triangles.source_face.size() == triangles.mesh.faceCount(),
          "fan triangulation gives triangles, each with its source face");
  (void)tb::mesh::triangulationWarnings(triangles);
  const tb::mesh::RenderVertices render = tb::mesh::buildRenderVertices(mesh);
  require(render.vertex_count <= mesh.corner_positions.size(), "render vertices <= corners");
  (void)tb::mesh::triangleControlMeshBytes(triangles.mesh);
}

}  // namespace tb::fuzz
