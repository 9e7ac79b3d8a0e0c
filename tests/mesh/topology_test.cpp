// Oracle: Euler's formula and hand-counted adjacency of small meshes.
#include "core/mesh/topology.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/obj_loader.h"
#include "core/mesh/render_vertices.h"
#include "core/mesh/triangulate.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// 3x3 grid of quads: 16 vertices, 9 faces, 24 edges, 12 on the boundary.
mesh::Mesh quadGrid() {
  std::string text;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) text += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
  }
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) {
      const int a = y * 4 + x + 1;
      text += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 5) +
              " " + std::to_string(a + 4) + "\n";
    }
  }
  return mesh::loadObjText(text, "grid.obj");
}

TEST(Topology, ClosedCubeSatisfiesEuler) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const mesh::Topology topology = mesh::buildTopology(mesh);
  EXPECT_EQ(topology.edges.size(), 12u);
  EXPECT_EQ(long(mesh.positions.size()) - long(topology.edges.size()) + long(mesh.faceCount()), 2);
  EXPECT_EQ(topology.boundaryEdgeCount(), 0u);
  EXPECT_EQ(topology.nonManifoldEdgeCount(), 0u);
  EXPECT_EQ(topology.component_count, 1u);
  // Every cube corner has valence 3: all eight are extraordinary for quads.
  EXPECT_EQ(topology.extraordinaryVertices(4).size(), 8u);
}

TEST(Topology, GridBoundaryAndRegularVertices) {
  const mesh::Mesh mesh = quadGrid();
  const mesh::Topology topology = mesh::buildTopology(mesh);
  EXPECT_EQ(topology.edges.size(), 24u);
  EXPECT_EQ(topology.boundaryEdgeCount(), 12u);
  EXPECT_EQ(topology.valence[5], 4u);  // interior
  EXPECT_EQ(topology.valence[1], 3u);  // boundary, regular for quads
  // The four grid corners have valence 2 on the boundary (regular is 3).
  EXPECT_EQ(topology.extraordinaryVertices(4), (std::vector<uint32_t>{0, 3, 12, 15}));
  EXPECT_GE(topology.findEdge(5, 6), 0);
  EXPECT_EQ(topology.findEdge(0, 5), -1);
  // Each interior edge lists both faces.
  const auto faces = topology.facesOfEdge(size_t(topology.findEdge(5, 6)));
  EXPECT_EQ(faces.size(), 2u);
}

TEST(Topology, NonManifoldEdgeAndComponents) {
  // Three triangles on edge (1,2), plus a separate triangle.
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nv 5 5 5\nv 6 5 5\nv 5 6 5\n"
      "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 6 7 8\n",
      "nm.obj");
  const mesh::Topology topology = mesh::buildTopology(mesh);
  EXPECT_EQ(topology.nonManifoldEdgeCount(), 1u);
  EXPECT_EQ(topology.facesOfEdge(size_t(topology.findEdge(0, 1))).size(), 3u);
  EXPECT_EQ(topology.component_count, 2u);
  EXPECT_EQ(topology.face_component[3], 1u);
}

TEST(Topology, WeldingMergesDuplicatedPositions) {
  // Two triangles that share an edge only through duplicated positions.
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 4 6 5\n", "dup.obj");
  EXPECT_EQ(mesh::buildTopology(mesh).boundaryEdgeCount(), 6u);
  const mesh::Welding welding = mesh::weldByPosition(mesh);
  EXPECT_EQ(welding.unique_count, 4u);
  EXPECT_EQ(welding.canonical[3], 1u);
  EXPECT_EQ(welding.canonical[4], 2u);
  EXPECT_EQ(welding.canonical[5], 5u);
}

TEST(Triangulate, FanSplitsPolygonsAndKeepsCornerAttributes) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_nonquads.obj"));
  const mesh::Triangulation tri = mesh::fanTriangulate(mesh);
  size_t expected = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) expected += mesh.faceSize(f) - 2;
  EXPECT_EQ(tri.mesh.faceCount(), expected);
  EXPECT_TRUE(tri.mesh.allFacesOfSize(3));
  EXPECT_GT(tri.polygons_split, 0u);
  // Triangulating adds no vertices and keeps Euler's characteristic.
  const mesh::Topology before = mesh::buildTopology(mesh), after = mesh::buildTopology(tri.mesh);
  EXPECT_EQ(
      long(mesh.positions.size()) - long(before.edges.size()) + long(mesh.faceCount()),
      long(tri.mesh.positions.size()) - long(after.edges.size()) + long(tri.mesh.faceCount()));
}

TEST(RenderVertices, SplitNormalsDuplicateVertices) {
  // catmark_cube has a normal per face corner: 24 render vertices, and each of
  // the 12 cube edges appears once per side.
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const mesh::RenderVertices render = mesh::buildRenderVertices(mesh);
  EXPECT_EQ(render.vertex_count, 24u);
  EXPECT_EQ(render.edge_count, 24u);
  // loop_cube: normals computed per position, so only its UV seams split
  // vertices (20 render vertices for 14 positions); without UVs none are split.
  mesh::Mesh smooth = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_cube.obj"));
  EXPECT_EQ(mesh::buildRenderVertices(smooth).vertex_count, 20u);
  std::fill(smooth.corner_uvs.begin(), smooth.corner_uvs.end(), -1);
  EXPECT_EQ(mesh::buildRenderVertices(smooth).vertex_count, smooth.positions.size());
}

}  // namespace
}  // namespace tb
