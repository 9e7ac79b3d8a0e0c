// Oracles: closed-form limit masks at control vertices.
//  - Catmull-Clark: limit position (n^2 v + 4 sum e_i + sum f_i) / (n (n + 5)) and the
//    tangent masks of Halstead, Kass & DeRose, "Efficient, fair interpolation using
//    Catmull-Clark surfaces", SIGGRAPH 1993, appendix A.
//  - Loop: limit position (1 - n chi) v + chi sum e_i, chi = 1 / (n + 3 / (8 beta)), and
//    the tangents sum cos(2 pi i / n) e_i, sum sin(2 pi i / n) e_i (Loop 1987; Hoppe et
//    al., "Piecewise smooth surface reconstruction", SIGGRAPH 1994).
// Plus the sub-face convention of face_domain.h, checked through surface continuity.
#include "reference/limit_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "reference/triangle_mesh_ref.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

using testing::loadShape;
constexpr double kPi = std::numbers::pi;

// The one-ring of an interior control vertex with no tags, ordered counter-clockwise:
// face i holds v, edge neighbour e_i (after v), face neighbour f_i (quads only) and
// e_{i+1}.
struct VertexRing {
  uint32_t vertex = 0;
  std::vector<mesh::Vec3d> e, f;
  size_t face = 0;  // one incident face, and v's corner in it
  int corner = 0;
};

std::vector<VertexRing> untaggedInteriorRings(const mesh::Mesh& mesh, uint32_t face_size) {
  const mesh::Topology topology = mesh::buildTopology(mesh);
  std::set<uint32_t> tagged;
  for (const mesh::Crease& c : mesh.tags.creases) tagged.insert({c.v0, c.v1});
  for (const mesh::Corner& c : mesh.tags.corners) tagged.insert(c.vertex);
  std::vector<std::vector<std::pair<size_t, int>>> incident(mesh.positions.size());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto corners = mesh.facePositions(f);
    for (size_t k = 0; k < corners.size(); ++k) incident[corners[k]].push_back({f, int(k)});
  }
  std::vector<VertexRing> rings;
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const auto& faces = incident[v];
    if (faces.empty() || topology.on_boundary[v] || tagged.count(v)) continue;
    if (std::any_of(faces.begin(), faces.end(),
                    [&](auto fc) { return mesh.faceSize(fc.first) != face_size; })) {
      continue;
    }
    VertexRing ring{v, {}, {}, faces[0].first, faces[0].second};
    auto [f, k] = faces[0];
    for (size_t i = 0; i < faces.size(); ++i) {
      const auto c = mesh.facePositions(f);
      const uint32_t next = c[(size_t(k) + 1) % face_size],
                     prev = c[(size_t(k) + face_size - 1) % face_size];
      ring.e.push_back(mesh.positions[next]);
      if (face_size == 4) ring.f.push_back(mesh.positions[c[(size_t(k) + 2) % 4]]);
      // The next face counter-clockwise shares the edge (v, prev).
      for (auto [g, j] : faces) {
        if (mesh.facePositions(g)[(size_t(j) + 1) % face_size] == prev) f = g, k = j;
      }
    }
    rings.push_back(ring);
  }
  return rings;
}

mesh::Vec2d quadCornerUv(int k) { return {double(k == 1 || k == 2), double(k >= 2)}; }
mesh::Vec2d triangleCornerUv(int k) { return {double(k == 1), double(k == 2)}; }

struct MaskResult {
  mesh::Vec3d position, normal;
};

MaskResult catmullClarkMask(const VertexRing& ring, const mesh::Vec3d& v) {
  const int n = int(ring.e.size());
  mesh::Vec3d sum_e, sum_f, t1, t2;
  const double a =
      1 + std::cos(2 * kPi / n) + std::cos(kPi / n) * std::sqrt(2 * (9 + std::cos(2 * kPi / n)));
  for (int i = 0; i < n; ++i) {
    const double c0 = std::cos(2 * kPi * i / n), c1 = std::cos(2 * kPi * (i + 1) / n);
    const double s0 = std::sin(2 * kPi * i / n), s1 = std::sin(2 * kPi * (i + 1) / n);
    sum_e = sum_e + ring.e[size_t(i)];
    sum_f = sum_f + ring.f[size_t(i)];
    t1 = t1 + ring.e[size_t(i)] * (a * c0) + ring.f[size_t(i)] * (c0 + c1);
    t2 = t2 + ring.e[size_t(i)] * (a * s0) + ring.f[size_t(i)] * (s0 + s1);
  }
  return {(v * double(n * n) + sum_e * 4.0 + sum_f) * (1.0 / (n * (n + 5))),
          normalize(cross(t1, t2))};
}

MaskResult loopMask(const VertexRing& ring, const mesh::Vec3d& v) {
  const int n = int(ring.e.size());
  const double inner = 3.0 / 8 + std::cos(2 * kPi / n) / 4;
  const double beta = (5.0 / 8 - inner * inner) / n;
  const double chi = 1 / (n + 3 / (8 * beta));
  mesh::Vec3d sum_e, t1, t2;
  for (int i = 0; i < n; ++i) {
    sum_e = sum_e + ring.e[size_t(i)];
    t1 = t1 + ring.e[size_t(i)] * std::cos(2 * kPi * i / n);
    t2 = t2 + ring.e[size_t(i)] * std::sin(2 * kPi * i / n);
  }
  return {v * (1 - n * chi) + sum_e * chi, normalize(cross(t1, t2))};
}

// Compares Bfr at every qualifying control vertex of the shape with the mask;
// returns how many vertices were checked and of which valences.
std::set<size_t> checkVertexLimits(const std::string& name, osd::Scheme scheme) {
  const mesh::Mesh mesh = loadShape(name);
  const LimitSurface surface(mesh, scheme);
  const double diagonal = boundingBoxDiagonal(mesh.positions);
  const uint32_t face_size = scheme == osd::Scheme::kLoop ? 3 : 4;
  std::set<size_t> valences;
  for (const VertexRing& ring : untaggedInteriorRings(mesh, face_size)) {
    const mesh::Vec3d& v = mesh.positions[ring.vertex];
    const MaskResult mask =
        scheme == osd::Scheme::kLoop ? loopMask(ring, v) : catmullClarkMask(ring, v);
    const mesh::Vec2d uv =
        scheme == osd::Scheme::kLoop ? triangleCornerUv(ring.corner) : quadCornerUv(ring.corner);
    const LimitPoint bfr = surface.evaluate(ring.face, uv.x, uv.y);
    EXPECT_LT(length(bfr.position - mask.position), 1e-12 * diagonal)
        << name << " vertex " << ring.vertex << " valence " << ring.e.size();
    EXPECT_GT(dot(bfr.normal, mask.normal), 1 - 1e-12)
        << name << " vertex " << ring.vertex << " valence " << ring.e.size();
    valences.insert(ring.e.size());
  }
  return valences;
}

TEST(LimitSurface, CatmullClarkVertexLimitsMatchHalsteadMasks) {
  std::set<size_t> valences;
  for (const char* name : {"catmark_cube.obj", "catmark_torus.obj", "catmark_pawn.obj",
                           "catmark_xord_interior.obj", "catmark_toroidal_tet.obj"}) {
    const std::set<size_t> checked = checkVertexLimits(name, osd::Scheme::kCatmullClark);
    valences.insert(checked.begin(), checked.end());
  }
  // Regular and extraordinary valences, low and high, must all have been exercised.
  for (size_t n : {3u, 4u, 5u, 6u}) EXPECT_TRUE(valences.count(n)) << "valence " << n;
  EXPECT_GE(*valences.rbegin(), 8u);
}

TEST(LimitSurface, LoopVertexLimitsMatchLoopMasks) {
  std::set<size_t> valences;
  for (const char* name : {"loop_icosahedron.obj", "loop_cube.obj", "loop_xord_interior.obj",
                           "loop_toroidal_tet.obj"}) {
    const std::set<size_t> checked = checkVertexLimits(name, osd::Scheme::kLoop);
    valences.insert(checked.begin(), checked.end());
  }
  for (size_t n : {4u, 5u, 6u}) EXPECT_TRUE(valences.count(n)) << "valence " << n;
}

// Oracle: the limit surface is continuous, so the sub-face convention documented in
// face_domain.h must make neighbouring sub-faces meet: sub-face k's edge s = 1 is
// sub-face k+1's edge t = 1 (edge midpoint k to the centre), every sub-face reaches
// the same centre at (1,1), and sub-face k's (0,0) is the limit of corner k as seen
// from the neighbouring quad.
TEST(LimitSurface, NgonSubFacesFollowTheDocumentedConvention) {
  const mesh::Mesh mesh = loadShape("catmark_nonquads.obj");
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  const double tolerance = 1e-12 * boundingBoxDiagonal(mesh.positions);
  int ngons = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const int n = int(mesh.faceSize(f));
    if (n == 4) continue;
    ++ngons;
    const LimitFace face = surface.face(f);
    ASSERT_EQ(face.subFaceCount(), n);
    const mesh::Vec3d centre = face.evaluateSubFace(0, 1, 1).position;
    for (int k = 0; k < n; ++k) {
      const int next = (k + 1) % n;
      EXPECT_LT(length(face.evaluateSubFace(k, 1, 1).position - centre), tolerance);
      for (double x : {0.0, 0.25, 0.5, 0.9}) {
        EXPECT_LT(length(face.evaluateSubFace(k, 1, x).position -
                         face.evaluateSubFace(next, x, 1).position),
                  tolerance)
            << "face " << f << " sub-faces " << k << ", " << next << " at " << x;
      }
    }
  }
  EXPECT_GE(ngons, 3);
  // Corner k of an N-gon against the same vertex seen from every other face.
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const int n = int(mesh.faceSize(f));
    if (n == 4) continue;
    for (int k = 0; k < n; ++k) {
      const uint32_t v = mesh.facePositions(f)[size_t(k)];
      const mesh::Vec3d p = surface.face(f).evaluateSubFace(k, 0, 0).position;
      for (size_t g = 0; g < mesh.faceCount(); ++g) {
        const auto corners = mesh.facePositions(g);
        for (int j = 0; j < int(corners.size()); ++j) {
          if (corners[size_t(j)] != v || corners.size() != 4) continue;
          const mesh::Vec2d uv = quadCornerUv(j);
          EXPECT_LT(length(surface.evaluate(g, uv.x, uv.y).position - p), tolerance);
        }
      }
    }
  }
}

// Oracle: symmetry and orientation. The cube (centred at the origin) is symmetric
// under its rotation group, so each face's limit centre lies on the ray through the
// control face's centroid, with the normal along that ray, pointing out of the
// counter-clockwise faces.
TEST(LimitSurface, CubeFaceCentresAndNormalsFollowSymmetry) {
  const mesh::Mesh mesh = loadShape("catmark_cube.obj");
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    mesh::Vec3d centroid;
    for (uint32_t v : mesh.facePositions(f)) centroid = centroid + mesh.positions[v] * 0.25;
    const LimitPoint p = surface.evaluate(f, 0.5, 0.5);
    EXPECT_NEAR(length(p.normal), 1.0, 1e-15);
    EXPECT_NEAR(dot(normalize(p.position), normalize(centroid)), 1.0, 1e-12) << f;
    EXPECT_NEAR(dot(p.normal, normalize(centroid)), 1.0, 1e-12) << f;
    EXPECT_FALSE(surface.isRegular(f));  // every cube face touches valence-3 vertices
  }
}

// Oracle: orientation. With infinitely sharp corners and a sharp crease, normals
// must stay unit length everywhere and point out of the (convex) surface wherever it
// has a tangent plane: everywhere but the corner vertices themselves, which are cone
// points.
TEST(LimitSurface, NormalsStayUnitAtSharpFeatures) {
  mesh::Mesh mesh = loadShape("catmark_cube.obj");
  for (uint32_t v = 0; v < 8; ++v) mesh.tags.corners.push_back({v, 10.0});
  const uint32_t first = mesh.facePositions(0)[0], second = mesh.facePositions(0)[1];
  mesh.tags.creases.push_back({first, second, 10.0});
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    for (const mesh::Vec2d& uv : testing::clusteredFacePoints(osd::Scheme::kCatmullClark, 4, 6)) {
      const LimitPoint p = surface.evaluate(f, uv.x, uv.y);
      EXPECT_NEAR(length(p.normal), 1.0, 1e-12) << f << " " << uv.x << " " << uv.y;
      const bool cone_point = (uv.x == 0 || uv.x == 1) && (uv.y == 0 || uv.y == 1);
      if (cone_point) continue;
      EXPECT_GT(dot(p.normal, p.position), 0.0) << f << " " << uv.x << " " << uv.y;
    }
  }
}

// Oracle: a planar control mesh has a planar limit, with normal +z for these
// counter-clockwise faces. Collapsing an edge makes dP/du vanish along it, and the
// normal there is taken just inside the face rather than left undefined.
TEST(LimitSurface, NormalIsTakenBesideACollapsedEdge) {
  const mesh::Mesh mesh =
      mesh::loadObjText("v 0 0 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "collapsed.obj");
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  const LimitPoint corner = surface.evaluate(0, 0.5, 0.0);
  EXPECT_LT(length(corner.du), 1e-12);  // the degenerate case is really reached
  for (double u : {0.0, 0.5, 1.0}) {
    const LimitPoint p = surface.evaluate(0, u, 0.0);
    EXPECT_NEAR(p.normal.z, 1.0, 1e-12) << u;
  }
}

TEST(LimitSurface, TorusFacesAreRegularPatches) {
  const mesh::Mesh mesh = loadShape("catmark_torus.obj");
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_TRUE(surface.isRegular(f)) << f;
}

// Oracle: the limit passes through no hole. A hole face has no limit surface, its
// neighbours keep theirs.
TEST(LimitSurface, HoleFacesHaveNoLimitSurface) {
  mesh::Mesh mesh = loadShape("catmark_torus.obj");
  mesh.tags.holes = {3};
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_EQ(surface.hasLimitSurface(f), f != 3) << f;
}

}  // namespace
}  // namespace tb::ref
