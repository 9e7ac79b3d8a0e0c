// Oracles:
//  - counts from the grid formulas documented in limit_tessellation.h;
//  - topology: the limit surface of a closed control mesh is closed, so the dense
//    tessellation, once coincident vertices are welded, is a closed 2-manifold with
//    the control mesh's Euler characteristic (2 for a sphere, 0 for a torus);
//  - orientation: each triangle's geometric normal agrees with the limit normal.
#include "reference/limit_tessellation.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/mesh/input_error.h"
#include "core/mesh/topology.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

using testing::loadShape;

struct Welded {
  size_t vertices = 0, edges = 0, faces = 0;
  size_t open_edges = 0;  // edges with other than two triangles
  long euler() const { return long(vertices) - long(edges) + long(faces); }
};

// Welds vertices closer than `tolerance` (a hash on a grid of that size would split
// pairs straddling a cell; sorting by x and comparing neighbours does not).
Welded weld(const LimitTessellation& t, double tolerance) {
  std::vector<uint32_t> order(t.positions.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return t.positions[a].x < t.positions[b].x; });
  constexpr uint32_t kUnset = ~0u;
  std::vector<uint32_t> canonical(t.positions.size(), kUnset);
  for (size_t i = 0; i < order.size(); ++i) {
    if (canonical[order[i]] != kUnset) continue;
    canonical[order[i]] = order[i];
    for (size_t j = i + 1;
         j < order.size() && t.positions[order[j]].x - t.positions[order[i]].x <= tolerance; ++j) {
      if (canonical[order[j]] == kUnset &&
          length(t.positions[order[j]] - t.positions[order[i]]) <= tolerance) {
        canonical[order[j]] = order[i];
      }
    }
  }
  Welded w;
  std::set<uint32_t> unique(canonical.begin(), canonical.end());
  w.vertices = unique.size();
  std::map<std::pair<uint32_t, uint32_t>, int> edge_use;
  for (const Triangle& tri : t.triangles) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = canonical[tri[size_t(k)]], b = canonical[tri[size_t((k + 1) % 3)]];
      ++edge_use[std::minmax(a, b)];
    }
  }
  w.edges = edge_use.size();
  w.faces = t.triangles.size();
  for (const auto& [edge, uses] : edge_use) w.open_edges += uses != 2;
  return w;
}

TEST(LimitTessellation, CountsFollowTheGridFormulas) {
  const LimitSurface cube(loadShape("catmark_cube.obj"), osd::Scheme::kCatmullClark);
  const LimitTessellation quads = tessellateLimit(cube, 5);
  EXPECT_EQ(quads.triangles.size(), 6u * 2 * 5 * 5);
  EXPECT_EQ(quads.positions.size(), 6u * 6 * 6);

  const LimitSurface pyramid(loadShape("catmark_pyramid.obj"), osd::Scheme::kCatmullClark);
  const LimitTessellation mixed = tessellateLimit(pyramid, 6);  // 4 triangles + 1 quad
  EXPECT_EQ(mixed.triangles.size(), 4u * 3 * 2 * 3 * 3 + 2 * 6 * 6);

  const LimitSurface loop(loadShape("loop_icosahedron.obj"), osd::Scheme::kLoop);
  const LimitTessellation triangles = tessellateLimit(loop, 4);
  EXPECT_EQ(triangles.triangles.size(), 20u * 16);
  EXPECT_EQ(triangles.positions.size(), 20u * 15);
}

TEST(LimitTessellation, ClosedControlMeshGivesClosedSurface) {
  for (const auto& [name, scheme] :
       {std::pair{"catmark_cube.obj", osd::Scheme::kCatmullClark},
        std::pair{"catmark_smoothtris0.obj", osd::Scheme::kCatmullClark},
        std::pair{"catmark_torus.obj", osd::Scheme::kCatmullClark},
        std::pair{"catmark_toroidal_tet.obj", osd::Scheme::kCatmullClark},
        std::pair{"loop_icosahedron.obj", osd::Scheme::kLoop}}) {
    const mesh::Mesh mesh = loadShape(name);
    const mesh::Topology topology = mesh::buildTopology(mesh);
    ASSERT_EQ(topology.boundaryEdgeCount(), 0u) << name;
    const long control_euler =
        long(mesh.positions.size()) - long(topology.edges.size()) + long(mesh.faceCount());
    const LimitTessellation t = tessellateLimit(LimitSurface(mesh, scheme), 4);
    const Welded w = weld(t, 1e-12 * boundingBoxDiagonal(mesh.positions));
    EXPECT_EQ(w.open_edges, 0u) << name;
    EXPECT_EQ(w.euler(), control_euler) << name;
  }
}

TEST(LimitTessellation, TrianglesFaceAlongTheLimitNormal) {
  for (const char* name : {"catmark_nonquads.obj", "catmark_pawn.obj"}) {
    const LimitSurface surface(loadShape(name), osd::Scheme::kCatmullClark);
    const LimitTessellation t = tessellateLimit(surface, 4);
    size_t against = 0;
    for (const Triangle& tri : t.triangles) {
      const mesh::Vec3d n = cross(t.positions[tri[1]] - t.positions[tri[0]],
                                  t.positions[tri[2]] - t.positions[tri[0]]);
      const mesh::Vec3d limit = t.normals[tri[0]] + t.normals[tri[1]] + t.normals[tri[2]];
      against += dot(n, limit) <= 0;
    }
    EXPECT_EQ(against, 0u) << name;
  }
}

TEST(LimitTessellation, VerticesRecordWhereTheyWereEvaluated) {
  const LimitSurface surface(loadShape("catmark_nonquads.obj"), osd::Scheme::kCatmullClark);
  const LimitTessellation t = tessellateLimit(surface, 4);
  for (size_t i = 0; i < t.positions.size(); i += 7) {
    const LimitPoint p = surface.evaluate(t.vertex_face[i], t.vertex_uv[i].x, t.vertex_uv[i].y);
    EXPECT_EQ(p.position, t.positions[i]);
  }
  for (size_t i = 0; i < t.triangles.size(); ++i) {
    for (uint32_t v : t.triangles[i]) EXPECT_EQ(t.vertex_face[v], t.triangle_face[i]);
  }
}

TEST(LimitTessellation, SkipsFacesWithoutLimitSurface) {
  mesh::Mesh mesh = loadShape("catmark_torus.obj");
  mesh.tags.holes = {0, 5};
  const LimitTessellation t = tessellateLimit(LimitSurface(mesh, osd::Scheme::kCatmullClark), 2);
  EXPECT_EQ(t.faces_skipped, 2u);
  EXPECT_EQ(t.triangles.size(), (mesh.faceCount() - 2) * 8);
}

}  // namespace
}  // namespace tb::ref
