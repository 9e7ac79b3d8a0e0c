// Oracle: Embree 3's subdivision surfaces (rtcInterpolate), an implementation of the
// Catmull-Clark limit written independently of OpenSubdiv, on the meshes where both
// follow the same rules (crossCheckIneligibility). Embree evaluates in float, which
// bounds the agreement.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "core/mesh/topology.h"
#include "reference/embree_subdivision.h"
#include "reference/limit_surface.h"
#include "reference/triangle_mesh_ref.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

using testing::bundledShapes;
using testing::clusteredSubFacePoints;
using testing::loadShape;

constexpr size_t kMinPointsPerShape = 1000;
// Positions agree to 1e-5 of the bounding-box diagonal (docs/ARCHITECTURE.md); float evaluation
// alone would allow ~1e-6.
constexpr double kPositionTolerance = 1e-5;
// Away from extraordinary points the derivatives agree to float precision amplified by
// the patch evaluation; measured <= 3.3e-5 (catmark_pawn, next to its valence-12 pole).
constexpr double kDerivativeTolerance = 1e-4;

// Derivatives are compared away from extraordinary points only: there the
// parameterisation is singular (the derivatives tend to 0 or infinity with the
// subdominant eigenvalue), and Embree's values depend on which face it is asked from
// (the tests of limit_surface_test pin Bfr's normals there to the exact tangent masks).
constexpr double kExtraordinaryExclusion = 1.0 / 16;  // in normalised (s,t) of the (sub-)face

struct Agreement {
  size_t points = 0;
  double position = 0;  // max |P_bfr - P_embree| / diagonal
  size_t derivative_points = 0;
  double derivative = 0;  // max |D_bfr - D_embree| / max(|D_bfr|, diagonal), over du and dv
};

// Corners of the sub-face where the control mesh is extraordinary: a vertex of valence
// other than 4 (3 on a boundary), and the centre of an N-gon (valence N).
std::vector<mesh::Vec2d> extraordinaryCorners(const mesh::Mesh& mesh,
                                              const mesh::Topology& topology, size_t f,
                                              int sub_face) {
  std::vector<mesh::Vec2d> corners;
  const int size = int(mesh.faceSize(f));
  const uint32_t v = mesh.facePositions(f)[size_t(sub_face)];
  const uint32_t regular = topology.on_boundary[v] ? 3 : 4;
  if (topology.valence[v] != regular) corners.push_back({0, 0});
  if (size == 4) {
    for (int k = 1; k < 4; ++k) {
      const uint32_t w = mesh.facePositions(f)[size_t(k)];
      if (topology.valence[w] != (topology.on_boundary[w] ? 3u : 4u)) {
        corners.push_back({double(k == 1 || k == 2), double(k >= 2)});
      }
    }
  } else {
    corners.push_back({1, 1});
  }
  return corners;
}

Agreement compareShape(const mesh::Mesh& mesh) {
  const LimitSurface bfr(mesh, osd::Scheme::kCatmullClark);
  const EmbreeSubdivision embree(mesh);
  const mesh::Topology topology = mesh::buildTopology(mesh);
  const double diagonal = boundingBoxDiagonal(mesh.positions);
  size_t sub_faces = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    sub_faces += size_t(subFaceCount(osd::Scheme::kCatmullClark, int(mesh.faceSize(f))));
  }
  const int g = std::max(4, int(std::ceil(std::sqrt(double(kMinPointsPerShape) / sub_faces))) + 1);
  Agreement agreement;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!bfr.hasLimitSurface(f)) continue;
    const LimitFace face = bfr.face(f);
    const int size = face.faceSize();
    for (int k = 0; k < face.subFaceCount(); ++k) {
      const std::vector<mesh::Vec2d> singular = extraordinaryCorners(mesh, topology, f, k);
      for (const mesh::Vec2d& st : clusteredSubFacePoints(g)) {
        const mesh::Vec2d uv = subFaceToFaceUv(osd::Scheme::kCatmullClark, size, k, st);
        const LimitPoint a = face.evaluate(uv.x, uv.y);
        const LimitPoint b = embree.evaluate(f, uv.x, uv.y);
        agreement.position =
            std::max(agreement.position, length(a.position - b.position) / diagonal);
        ++agreement.points;
        const bool near_singular =
            std::any_of(singular.begin(), singular.end(), [&](mesh::Vec2d c) {
              return std::max(std::abs(st.x - c.x), std::abs(st.y - c.y)) < kExtraordinaryExclusion;
            });
        if (near_singular) continue;
        agreement.derivative =
            std::max({agreement.derivative, length(a.du - b.du) / std::max(length(a.du), diagonal),
                      length(a.dv - b.dv) / std::max(length(a.dv), diagonal)});
        ++agreement.derivative_points;
      }
    }
  }
  return agreement;
}

TEST(EmbreeCrossCheck, BfrMatchesEmbreeOnEveryEligibleCatmarkShape) {
  std::ostringstream skipped, measured;
  int compared = 0;
  for (const std::string& name : bundledShapes("catmark_")) {
    const mesh::Mesh mesh = loadShape(name);
    const std::string reason = crossCheckIneligibility(mesh, osd::Scheme::kCatmullClark);
    if (!reason.empty()) {
      skipped << "  " << name << ": " << reason << "\n";
      continue;
    }
    const Agreement agreement = compareShape(mesh);
    measured << "  " << name << ": " << agreement.points << " points, max position diff "
             << agreement.position << " x diagonal; " << agreement.derivative_points
             << " away from extraordinary points, max derivative diff " << agreement.derivative
             << "\n";
    EXPECT_GE(agreement.points, kMinPointsPerShape) << name;
    EXPECT_LE(agreement.position, kPositionTolerance) << name;
    EXPECT_LE(agreement.derivative, kDerivativeTolerance) << name;
    EXPECT_GT(agreement.derivative_points, agreement.points / 2) << name;
    ++compared;
  }
  std::cout << "Bfr vs Embree, per shape:\n" << measured.str() << "Skipped:\n" << skipped.str();
  // Most bundled shapes must take part, or the check says little.
  EXPECT_GE(compared, 12);
}

// An open tube: boundary vertices of valence 3 only, no corners.
mesh::Mesh openTube() {
  constexpr int kAround = 8, kRings = 4;
  std::string text;
  for (int j = 0; j < kRings; ++j) {
    for (int i = 0; i < kAround; ++i) {
      const double a = i * 2 * 3.14159265358979 / kAround;
      text += "v " + std::to_string(std::cos(a) * (1 + 0.1 * j)) + " " +
              std::to_string(std::sin(a)) + " " + std::to_string(0.5 * j + 0.1 * (i % 3)) + "\n";
    }
  }
  for (int j = 0; j + 1 < kRings; ++j) {
    for (int i = 0; i < kAround; ++i) {
      const int a = j * kAround + i + 1, b = j * kAround + (i + 1) % kAround + 1;
      text += "f " + std::to_string(a) + " " + std::to_string(b) + " " +
              std::to_string(b + kAround) + " " + std::to_string(a + kAround) + "\n";
    }
  }
  return mesh::loadObjText(text, "tube.obj");
}

// Oracle: Embree again, on open meshes under each boundary mode: EDGE_AND_CORNER ->
// PIN_CORNERS, EDGE_ONLY -> SMOOTH_BOUNDARY, NONE -> NO_BOUNDARY (faces without a
// limit surface skipped). EDGE_ONLY at valence-2 corners is the one known mismatch.
TEST(EmbreeCrossCheck, BoundaryModesMapToEmbreeSubdivisionModes) {
  struct Case {
    mesh::Mesh mesh;
    mesh::BoundaryInterpolation boundary;
  };
  std::vector<Case> cases;
  for (mesh::BoundaryInterpolation boundary :
       {mesh::BoundaryInterpolation::kEdgeAndCorner, mesh::BoundaryInterpolation::kEdgeOnly,
        mesh::BoundaryInterpolation::kNone}) {
    cases.push_back({loadShape("catmark_edgecorner.obj"), boundary});
    cases.push_back({openTube(), boundary});
  }
  for (Case& c : cases) {
    c.mesh.tags.boundary = c.boundary;
    const std::string label = c.mesh.source + " mode " + std::to_string(int(c.boundary));
    const std::string reason = crossCheckIneligibility(c.mesh, osd::Scheme::kCatmullClark);
    if (c.boundary == mesh::BoundaryInterpolation::kEdgeOnly && c.mesh.source != "tube.obj") {
      EXPECT_NE(reason.find("valence-2 corner"), std::string::npos) << label;
      continue;
    }
    ASSERT_EQ(reason, "") << label;
    const Agreement agreement = compareShape(c.mesh);
    EXPECT_LE(agreement.position, kPositionTolerance) << label;
    EXPECT_GT(agreement.points, 100u) << label;
  }
  // The modes give different surfaces, so the agreement above pins each mapping.
  const LimitSurface corner(cases[0].mesh, osd::Scheme::kCatmullClark);
  const LimitSurface edge(cases[2].mesh, osd::Scheme::kCatmullClark);
  EXPECT_GT(length(corner.evaluate(0, 0, 0).position - edge.evaluate(0, 0, 0).position), 1e-3);
}

// Oracle: the documented conventions, held against Embree. Quads: Bfr (u,v) is
// Embree (u,v); swapping u and v must not agree, so the comparison above has teeth.
TEST(EmbreeCrossCheck, QuadOrientationIsOneToOne) {
  const mesh::Mesh mesh = loadShape("catmark_cube.obj");
  const LimitSurface bfr(mesh, osd::Scheme::kCatmullClark);
  const EmbreeSubdivision embree(mesh);
  const double diagonal = boundingBoxDiagonal(mesh.positions);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const mesh::Vec3d p = bfr.evaluate(f, 0.2, 0.7).position;
    EXPECT_LT(length(p - embree.evaluateNative(f, 0.2f, 0.7f).position), 1e-6 * diagonal);
    EXPECT_GT(length(p - embree.evaluateNative(f, 0.7f, 0.2f).position), 1e-2 * diagonal);
  }
}

// Oracle: Embree's documented sub-patch encoding (rtcInterpolate man page) against
// Bfr's sub-faces: sub-face k at (s,t) is U = 2(k%4) + s + 0.5, V = 2(k/4) + t + 0.5.
// The transposed (s,t) must disagree.
TEST(EmbreeCrossCheck, NgonSubFacesMapToEmbreeSubPatches) {
  const mesh::Mesh mesh = loadShape("catmark_nonquads.obj");
  const LimitSurface bfr(mesh, osd::Scheme::kCatmullClark);
  const EmbreeSubdivision embree(mesh);
  const double diagonal = boundingBoxDiagonal(mesh.positions);
  int ngons = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const int size = int(mesh.faceSize(f));
    if (size == 4) continue;
    ++ngons;
    for (int k = 0; k < size; ++k) {
      const mesh::Vec3d p = bfr.face(f).evaluateSubFace(k, 0.3, 0.8).position;
      const float u = float(2 * (k % 4) + 0.3 + 0.5), v = float(2 * (k / 4) + 0.8 + 0.5);
      EXPECT_LT(length(p - embree.evaluateNative(f, u, v).position), 1e-6 * diagonal)
          << "face " << f << " sub-face " << k;
      const float ut = float(2 * (k % 4) + 0.8 + 0.5), vt = float(2 * (k / 4) + 0.3 + 0.5);
      EXPECT_GT(length(p - embree.evaluateNative(f, ut, vt).position), 1e-3 * diagonal)
          << "face " << f << " sub-face " << k;
    }
  }
  EXPECT_GE(ngons, 3);
}

mesh::Mesh gridWithTags(const std::string& tags) {
  // 4x4 quads over a 5x5 vertex grid (vertex index = 5 y + x, 0-based in tags).
  std::string text;
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 5; ++x) {
      text += "v " + std::to_string(x) + " " + std::to_string(y) + " " +
              std::to_string((x * 7 + y * 3) % 5 * 0.1) + "\n";
    }
  }
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int a = 5 * y + x + 1;
      text += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 6) +
              " " + std::to_string(a + 5) + "\n";
    }
  }
  return mesh::loadObjText(text + tags, "grid.obj");
}

// Oracle: the rule list in cross_check_eligibility.h, one small mesh per rule.
TEST(EmbreeCrossCheck, IneligibilityNamesTheReason) {
  EXPECT_EQ(crossCheckIneligibility(gridWithTags(""), osd::Scheme::kCatmullClark), "");
  EXPECT_NE(crossCheckIneligibility(gridWithTags(""), osd::Scheme::kLoop).find("Loop"),
            std::string::npos);
  EXPECT_NE(crossCheckIneligibility(gridWithTags("t hole 1/0/0 5\n"), osd::Scheme::kCatmullClark)
                .find("hole"),
            std::string::npos);
  EXPECT_NE(crossCheckIneligibility(gridWithTags("t creasemethod 0/0/1 chaikin\n"),
                                    osd::Scheme::kCatmullClark)
                .find("Chaikin"),
            std::string::npos);
  EXPECT_NE(
      crossCheckIneligibility(gridWithTags("t crease 2/1/0 6 7 10\n"), osd::Scheme::kCatmullClark)
          .find("infinitely sharp"),
      std::string::npos);
  // Equal semi-sharp creases along a line agree; unequal ones meeting at vertex 12 do not.
  EXPECT_EQ(
      crossCheckIneligibility(gridWithTags("t crease 2/1/0 11 12 2\nt crease 2/1/0 12 13 2\n"),
                              osd::Scheme::kCatmullClark),
      "");
  EXPECT_NE(
      crossCheckIneligibility(gridWithTags("t crease 2/1/0 11 12 1\nt crease 2/1/0 12 13 2\n"),
                              osd::Scheme::kCatmullClark)
          .find("unequal"),
      std::string::npos);
  // A fractional crease ending on the boundary meets two (infinitely sharp) boundary edges.
  EXPECT_NE(
      crossCheckIneligibility(gridWithTags("t crease 2/1/0 2 7 2.5\n"), osd::Scheme::kCatmullClark)
          .find("three or more"),
      std::string::npos);
  EXPECT_EQ(
      crossCheckIneligibility(gridWithTags("t crease 2/1/0 2 7 2\n"), osd::Scheme::kCatmullClark),
      "");
  EXPECT_EQ(
      crossCheckIneligibility(loadShape("catmark_gregory_test8.obj"), osd::Scheme::kCatmullClark),
      "interior valence-2 vertex 1");
  const std::string non_manifold =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  EXPECT_NE(crossCheckIneligibility(mesh::loadObjText(non_manifold, "fin.obj"),
                                    osd::Scheme::kCatmullClark)
                .find("non-manifold"),
            std::string::npos);
}

}  // namespace
}  // namespace tb::ref
