// gregory_acc on the CPU. Oracles: the OpenSubdiv Bfr limit surface (regular faces are
// exactly the bicubic B-spline patch), the patch's own neighbour across each edge (C0),
// and the rules' one-line messages.
#include "techniques/gregory_acc/gregory_acc.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "core/tess/tessellator.h"
#include "harness/measures/error/error.h"
#include "reference/face_domain.h"
#include "reference/limit_surface.h"
#include "techniques/gregory_acc/gregory_stencils.h"
#include "techniques/registry.h"
#include "tests/techniques/gregory_acc_test_support.h"
#include "tests/test_support.h"

namespace tb::gregory_acc {
namespace {

// The bundled assets gregory_acc supports, pinned: all-quad, quad+triangle (triangle
// patches), with n-gons (refined once), with boundaries, with creases and corners
// (semi-sharp ones refined, tests/techniques/gregory_crease_test.cpp), and triangle meshes
// (Catmull-Clark of triangles).
const std::vector<std::string> kSupported = {"full_suite/pole64.obj",
                                             "opensubdiv/catmark_chaikin0.obj",
                                             "opensubdiv/catmark_cube.obj",
                                             "opensubdiv/catmark_cube_corner3.obj",
                                             "opensubdiv/catmark_cube_creases1.obj",
                                             "opensubdiv/catmark_edgecorner.obj",
                                             "opensubdiv/catmark_gregory_test2.obj",
                                             "opensubdiv/catmark_gregory_test5.obj",
                                             "opensubdiv/catmark_helmet.obj",
                                             "opensubdiv/catmark_nonquads.obj",
                                             "opensubdiv/catmark_pawn.obj",
                                             "opensubdiv/catmark_pyramid.obj",
                                             "opensubdiv/catmark_pyramid_creases1.obj",
                                             "opensubdiv/catmark_quadstrips.obj",
                                             "opensubdiv/catmark_single_crease.obj",
                                             "opensubdiv/catmark_tent_creases1.obj",
                                             "opensubdiv/catmark_toroidal_tet.obj",
                                             "opensubdiv/catmark_torus.obj",
                                             "opensubdiv/catmark_xord_interior.obj",
                                             "opensubdiv/loop_cube.obj",
                                             "opensubdiv/loop_cube_creases1.obj",
                                             "opensubdiv/loop_icos_semisharp.obj",
                                             "opensubdiv/loop_icosahedron.obj",
                                             "opensubdiv/loop_toroidal_tet.obj",
                                             "opensubdiv/loop_triangle_edgecorner.obj",
                                             "opensubdiv/loop_xord_interior.obj",
                                             "tessbench/cylinder_seam.obj",
                                             "tessbench/flat_cube.obj",
                                             "tessbench/tri_pawn.obj",
                                             "tessbench/tri_torus.obj"};

using tb::testing::diagonalOf;
using tb::testing::loadAsset;

techniques::BuiltSurface build(const mesh::Mesh& mesh, const std::string& variant = "") {
  GregoryAccTechnique technique;
  for (const techniques::VariantInfo& info : technique.variants()) {
    if (variant.empty() || info.name == variant)
      return techniques::buildSurface(technique, mesh, info);
  }
  return nullptr;
}

tess::Tessellation quadPoints(float level, tess::Spacing spacing = tess::Spacing::kInteger) {
  tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};
  return tess::tessellate(tess::Domain::kQuad, spacing, levels);
}

TEST(GregoryAcc, IsRegistered) {
  EXPECT_NE(techniques::TechniqueRegistry::instance().find("gregory_acc"), nullptr);
}

TEST(GregoryAcc, RegularFacesEqualTheBfrLimitSurface) {
  const tess::Tessellation domain = quadPoints(7.3f, tess::Spacing::kFractionalOdd);
  size_t regular_faces = 0;
  for (const std::string& name : kSupported) {
    const mesh::Mesh mesh = loadAsset(name);
    const auto patches = build(mesh);
    const mesh::Mesh& control = patches->controlMesh();
    // The refined mesh of a mixed input has the same limit; Bfr parameterises its faces.
    const ref::LimitSurface limit(control, osd::Scheme::kCatmullClark);
    const double diagonal = diagonalOf(mesh);
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      // Bfr says which faces are one regular B-spline patch (interior or boundary).
      if (!limit.hasLimitSurface(f) || !limit.isRegular(f)) continue;
      ++regular_faces;
      for (const tess::DomainPoint& d : domain.points) {
        const mesh::Vec3d expected = limit.evaluate(f, d[0], d[1]).position;
        const techniques::SurfacePoint got = patches->evaluate(f, {d[0], d[1], 0});
        ASSERT_LE(length(got.position - expected), 1e-12 * diagonal)
            << name << " face " << f << " at " << d[0] << "," << d[1];
        const techniques::SurfacePointF got_f = patches->evaluateFloat(f, d);
        ASSERT_LE(length(vecCast<double>(got_f.position) - expected), 1e-6 * diagonal)
            << name << " face " << f;
        EXPECT_LE(length(got.normal - limit.evaluate(f, d[0], d[1]).normal), 1e-9);
      }
    }
  }
  EXPECT_GE(regular_faces, 32u);  // every torus face is regular
}

using testing::cornerCount;
using testing::edgeCoord;

TEST(GregoryAcc, SharedEdgesAgreeFromBothSidesInDouble) {
  for (const std::string& name : kSupported) {
    const mesh::Mesh mesh = loadAsset(name);
    const auto patches = build(mesh, "asymmetric");
    const mesh::Mesh& control = patches->controlMesh();
    const double diagonal = diagonalOf(mesh);
    const std::vector<testing::EdgeTwin> twins = testing::edgeTwins(control);
    size_t edges = 0;
    size_t directed_edges = 0;
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      const techniques::PatchDomain domain = patches->patchDomain(f);
      directed_edges += size_t(cornerCount(domain));
      for (int c = 0; c < cornerCount(domain); ++c) {
        const testing::EdgeTwin twin = twins[f * 4 + c];
        if (twin.face < 0) continue;
        ++edges;
        const techniques::PatchDomain other = patches->patchDomain(size_t(twin.face));
        for (double t : {0.0, 0.125, 0.3, 0.5, 0.77, 1.0}) {
          const mesh::Vec3d p = patches->evaluate(f, edgeCoord(domain, c, t)).position;
          const mesh::Vec3d q =
              patches->evaluate(size_t(twin.face), edgeCoord(other, twin.corner, 1 - t)).position;
          ASSERT_LE(length(p - q), 1e-12 * diagonal) << name << " faces " << f << "," << twin.face;
        }
      }
    }
    // Every directed edge but the boundary ones has its twin (oracle: the topology).
    EXPECT_EQ(edges, directed_edges - mesh::buildTopology(control).boundaryEdgeCount()) << name;
  }
}

TEST(GregoryAcc, SymmetricVariantSharedEdgesAreBitwiseEqualInFloat) {
  const tess::Tessellation quads = quadPoints(7.3f, tess::Spacing::kFractionalOdd);
  std::vector<float> ts;
  for (const tess::DomainPoint& d : quads.points) {
    if (d[1] == 0.0f) ts.push_back(d[0]);
  }
  ASSERT_GT(ts.size(), 5u);
  for (const std::string& name : kSupported) {
    const mesh::Mesh mesh = loadAsset(name);
    const auto patches = build(mesh, "edge_symmetric");
    const std::vector<testing::EdgeTwin> twins = testing::edgeTwins(patches->controlMesh());
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      const techniques::PatchDomain domain = patches->patchDomain(f);
      for (int c = 0; c < cornerCount(domain); ++c) {
        const testing::EdgeTwin twin = twins[f * 4 + c];
        if (twin.face < 0) continue;
        const techniques::PatchDomain other = patches->patchDomain(size_t(twin.face));
        for (float t : ts) {
          const mesh::Vec3f p = patches->evaluateFloat(f, edgeCoord(domain, c, t)).position;
          const mesh::Vec3f q =
              patches->evaluateFloat(size_t(twin.face), edgeCoord(other, twin.corner, 1 - t))
                  .position;
          ASSERT_TRUE(p == q) << name << " faces " << f << "," << twin.face << " t " << t;
        }
      }
    }
  }
}

TEST(GregoryAcc, CornersInterpolateTheLimitPositionAtExtraordinaryVertices) {
  double worst_dart = 0;  // |P - limit| / diagonal at dart vertices
  for (const std::string& name : kSupported) {
    const mesh::Mesh mesh = loadAsset(name);
    const auto patches = build(mesh, "exact_tangents");
    const mesh::Mesh& control = patches->controlMesh();
    // The limit the patches approximate: semi-sharp creases left after the face budget
    // are rounded (techniques/common/crease_refinement.h).
    const techniques::CreasePreparation creases = testing::defaultCreases(mesh);
    const ref::LimitSurface limit(testing::limitMeshOf(*patches, creases),
                                  osd::Scheme::kCatmullClark);
    const bool kinds_known = creases.control.positions.size() == control.positions.size();
    const std::vector<uint8_t> on_boundary = mesh::buildTopology(control).on_boundary;
    const double diagonal = diagonalOf(mesh);
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      const techniques::PatchDomain domain = patches->patchDomain(f);
      for (int c = 0; c < cornerCount(domain); ++c) {
        const techniques::DomainCoord d = edgeCoord(domain, c, 0.0);
        // Bfr: a Catmull-Clark triangle is 3 quad sub-faces, corner c at (0,0) of sub-face c.
        const mesh::Vec2d uv =
            domain == techniques::PatchDomain::kQuad
                ? mesh::Vec2d{d[0], d[1]}
                : ref::subFaceToFaceUv(osd::Scheme::kCatmullClark, 3, c, {0.0, 0.0});
        const ref::LimitPoint exact = limit.evaluate(f, uv.x, uv.y);
        const uint32_t v = control.facePositions(f)[c];
        const double error = length(patches->evaluate(f, d).position - exact.position);
        // A dart (one sharp edge) keeps the smooth rules (Kovacs et al. 2009), whose limit
        // mask is not the dart's: its corner is approximate (measured below).
        if (kinds_known && creases.vertex_kind[v] == techniques::SharpVertexKind::kDart) {
          worst_dart = std::max(worst_dart, error / diagonal);
          continue;
        }
        EXPECT_LE(error, 1e-12 * diagonal) << name << " face " << f << " vertex " << v;
        // Interior corners: the tangent plane is the limit's (exact tangent masks; the
        // boundary cross tangent is the paper's, not exact, so boundary corners are
        // not checked). 1e-5: Bfr
        // itself approximates irregular corners (Gregory patches after 10 levels), and the
        // Far-compatible mask is off by 1e-2 here, so the bound still separates the two.
        // Sharp vertices (crease, corner, dart) have no exact tangent mask either.
        if (on_boundary[v]) continue;
        if (kinds_known && creases.vertex_kind[v] != techniques::SharpVertexKind::kSmooth) continue;
        EXPECT_LE(length(patches->evaluate(f, d).normal - exact.normal), 1e-5)
            << name << " face " << f << " corner " << c << " vertex "
            << control.facePositions(f)[c];
      }
    }
  }
  // Measured: 4.6e-3 of the diagonal (catmark_chaikin0's four darts).
  std::printf("[gregory_acc corners] worst dart corner |P - limit| / diagonal %.2e\n", worst_dart);
  EXPECT_LT(worst_dart, 1e-2);
}

std::string rejection(const std::string& obj) {
  GregoryAccTechnique technique;
  const mesh::Mesh mesh = mesh::loadObjText(obj, "test.obj");
  const std::string reason = technique.checkSupport(mesh);
  try {
    techniques::buildSurface(technique, mesh, technique.variants().front());
    ADD_FAILURE() << "expected UnsupportedInput for " << reason;
  } catch (const techniques::UnsupportedInput& error) {
    EXPECT_EQ(reason, error.what());
  }
  return reason;
}

const char kCube[] =
    "v -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 -1\nv 1 -1 -1\n"
    "f 1 2 4 3\nf 3 4 6 5\nf 5 6 8 7\nf 7 8 2 1\nf 2 8 6 4\nf 7 1 3 5\n";

TEST(GregoryAccRejects, FacesAboveTheMaximumSize) {
  // A closed two-sided 33-gon.
  std::string obj, front = "f", back = "f";
  for (int i = 0; i < 33; ++i) {
    obj += "v " + std::to_string(std::cos(i * 0.19)) + " " + std::to_string(std::sin(i * 0.19)) +
           " 0\n";
    front.append(" ").append(std::to_string(i + 1));
    back.append(" ").append(std::to_string(33 - i));
  }
  EXPECT_EQ(rejection(obj + front + "\n" + back + "\n"),
            "gregory_acc: test.obj: face 0 (line 34) has 33 vertices; gregory_acc needs 3..32");
}

TEST(GregoryAccRejects, SmoothTriangles) {
  EXPECT_EQ(rejection(std::string(kCube) + "t smoothtriangles 0/0/1 catmark\n"),
            "gregory_acc: test.obj: `t smoothtriangles` is not supported (plain Catmull-Clark "
            "only)");
}

TEST(GregoryAccRejects, NonManifoldEdges) {
  // Three quads on edge (0, 1).
  EXPECT_EQ(rejection("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 1 -1 0\nv 0 -1 0\nv 0 0 1\nv 1 0 1\n"
                      "f 1 2 3 4\nf 2 1 6 5\nf 1 2 8 7\n"),
            "gregory_acc: test.obj: edge (0, 1) is non-manifold (3 faces)");
}

TEST(GregoryAccRejects, InconsistentOrientation) {
  std::string cube(kCube);
  cube.replace(cube.find("f 1 2 4 3"), 9, "f 3 4 2 1");
  EXPECT_EQ(rejection(cube),
            "gregory_acc: test.obj: edge (2, 3) is used twice in the same direction (face 1 "
            "(line 10)); faces must be consistently oriented");
}

// A closed quad "bipyramid": poles N (vertex 0) and S, equator E_i, and M_i between
// E_i and E_{i+1}; faces (N, E_i, M_i, E_{i+1}) and (S, E_{i+1}, M_i, E_i).
std::string bipyramid(int n) {
  std::string obj = "v 0 0 1\nv 0 0 -1\n";
  for (int i = 0; i < 2 * n; ++i) {
    const double a = M_PI * i / n;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  auto e = [n](int i) { return std::to_string(3 + 2 * (i % n)); };  // 1-based
  auto m = [n](int i) { return std::to_string(4 + 2 * (i % n)); };
  for (int i = 0; i < n; ++i) {
    obj += "f 1 " + e(i) + " " + m(i) + " " + e(i + 1) + "\n";
    obj += "f 2 " + e(i + 1) + " " + m(i) + " " + e(i) + "\n";
  }
  return obj;
}

TEST(GregoryAccRejects, ValenceAboveTheMaximum) {
  EXPECT_EQ(rejection(bipyramid(257)),
            "gregory_acc: test.obj: vertex 0 has valence 257; gregory_acc needs 3..256");
}

TEST(GregoryAccRejects, ValenceTwo) {
  // With 64 the poles pass; the first M vertex (index 3) has valence 2.
  EXPECT_EQ(rejection(bipyramid(64)),
            "gregory_acc: test.obj: vertex 3 has valence 2; gregory_acc needs 3..256");
}

TEST(GregoryAccRejects, BoundaryVertexWithTooManyFaces) {
  // An open fan of 257 quads (0, r_i, m_i, r_{i+1}) around vertex 0.
  std::string obj = "v 0 0 0\n";
  for (int i = 0; i <= 514; ++i) {
    const double a = 3.0 * i / 514, radius = i % 2 == 0 ? 1.0 : 1.5;
    obj += "v " + std::to_string(radius * std::cos(a)) + " " +
           std::to_string(radius * std::sin(a)) + " 0\n";
  }
  for (int i = 0; i < 257; ++i) {
    obj += "f 1 " + std::to_string(2 + 2 * i) + " " + std::to_string(3 + 2 * i) + " " +
           std::to_string(4 + 2 * i) + "\n";
  }
  EXPECT_EQ(rejection(obj),
            "gregory_acc: test.obj: boundary vertex 0 has 257 faces; gregory_acc needs 1..256");
}

TEST(GregoryAccRejects, NoFaces) {
  mesh::Mesh mesh;
  mesh.source = "empty.obj";
  mesh.positions.push_back({0, 0, 0});
  GregoryAccTechnique technique;
  EXPECT_EQ(technique.checkSupport(mesh), "gregory_acc: empty.obj: has no faces");
  EXPECT_THROW(techniques::buildSurface(technique, mesh, technique.variants().front()),
               techniques::UnsupportedInput);
}

TEST(GregoryAcc, SupportsExactlyTheManifoldAssetsWithoutSmoothTrianglesOrValenceTwo) {
  GregoryAccTechnique technique;
  EXPECT_EQ(testing::supportedBundledAssets(), kSupported);
  // The three bundled refusals, each with its rule.
  EXPECT_EQ(technique.checkSupport(loadAsset("opensubdiv/catmark_smoothtris0.obj")),
            "gregory_acc: " + tb::testing::assetPath("opensubdiv/catmark_smoothtris0.obj") +
                ": `t smoothtriangles` is not supported (plain Catmull-Clark only)");
  EXPECT_NE(technique.checkSupport(loadAsset("opensubdiv/catmark_gregory_test8.obj"))
                .find("has valence 2; gregory_acc needs 3..256"),
            std::string::npos);
  EXPECT_NE(technique.checkSupport(loadAsset("tessbench/tjunction.obj")).find("is non-manifold"),
            std::string::npos);
  for (const char* name : {"opensubdiv/catmark_smoothtris0.obj",
                           "opensubdiv/catmark_gregory_test8.obj", "tessbench/tjunction.obj"}) {
    std::printf("[gregory_acc refuses] %s\n", technique.checkSupport(loadAsset(name)).c_str());
  }
}

TEST(GregoryAcc, FootprintCountsStencilsAndPatchIds) {
  const mesh::Mesh mesh = loadAsset("opensubdiv/catmark_cube.obj");
  const auto patches = build(mesh);
  const techniques::DataFootprint footprint = patches->footprint();
  EXPECT_EQ(footprint.control_mesh_bytes, 8u * 16u);
  EXPECT_EQ(footprint.patch_data_bytes, 6u * 20u * 4u);
  // 8 vertex stencils + 24 directed-edge stencils + 6 * 8 face stencils.
  const GregoryStencils stencils = buildGregoryStencils(mesh);
  EXPECT_EQ(stencils.stencilCount(), 8u + 24u + 48u);
  EXPECT_EQ(stencils.sharedStencilCount, 32u);
  EXPECT_EQ(footprint.stencil_bytes,
            (stencils.stencilCount() + 1) * 4 + stencils.indices.size() * 8);
  // Every stencil is affine (weights sum to 1): the patches move with the mesh.
  for (size_t s = 0; s < stencils.stencilCount(); ++s) {
    double sum = 0;
    for (uint32_t k = stencils.offsets[s]; k < stencils.offsets[s + 1]; ++k) {
      sum += stencils.weights[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << "stencil " << s;
  }
}

}  // namespace
}  // namespace tb::gregory_acc

namespace tb::gregory_acc {
namespace {

// Oracle: central finite differences of the position (the normal includes the
// derivative of the rational face-point blend, which regular faces do not exercise).
TEST(GregoryAcc, NormalIsTheCrossProductOfFiniteDifferenceTangents) {
  for (const std::string& name : kSupported) {
    const mesh::Mesh mesh = loadAsset(name);
    const auto patches = build(mesh, "asymmetric");
    const double h = 1e-6;
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      if (patches->patchDomain(f) == techniques::PatchDomain::kTriangle) {
        // Barycentric: tangents toward corner 1 and corner 2, normal (S_1 - S_0) x (S_2 - S_0).
        for (const techniques::DomainCoord& b :
             {techniques::DomainCoord{0.2, 0.3, 0.5}, techniques::DomainCoord{0.7, 0.1, 0.2},
              techniques::DomainCoord{0.05, 0.9, 0.05}, techniques::DomainCoord{0.45, 0.1, 0.45}}) {
          auto p = [&](double db, double dc) {
            return patches->evaluate(f, {b[0] - db - dc, b[1] + db, b[2] + dc}).position;
          };
          const mesh::Vec3d da = (p(h, 0) - p(-h, 0)) * (0.5 / h);
          const mesh::Vec3d dc = (p(0, h) - p(0, -h)) * (0.5 / h);
          EXPECT_LE(length(patches->evaluate(f, b).normal - normalize(cross(da, dc))), 1e-6)
              << name << " triangle " << f << " at " << b[0] << "," << b[1] << "," << b[2];
        }
        continue;
      }
      for (double u : {0.1, 0.37, 0.5, 0.81}) {
        for (double v : {0.05, 0.44, 0.9}) {
          auto p = [&](double a, double b) { return patches->evaluate(f, {a, b, 0}).position; };
          const mesh::Vec3d du = (p(u + h, v) - p(u - h, v)) * (0.5 / h);
          const mesh::Vec3d dv = (p(u, v + h) - p(u, v - h)) * (0.5 / h);
          const mesh::Vec3d expected = normalize(cross(du, dv));
          EXPECT_LE(length(patches->evaluate(f, {u, v, 0}).normal - expected), 1e-6)
              << name << " face " << f << " at " << u << "," << v;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tb::gregory_acc

namespace tb::gregory_acc {
namespace {

// Oracle: a hand count of gregory_eval.h / gregory_acc.tese at an interior point.
//   1 - u, 1 - v                                   2 add
//   4 blends: a+b (1 add), a+b == 0 (1 cmp), 1/(a+b) (1 div),
//     (fp a + fm b) inv (9 mul, 3 add), (fp - fm)(inv inv) (4 mul, 3 add),
//     two derivatives (a_u b - b_u a) diff (5 mul, 1 add each)    x4: 36 add, 92 mul, 4 div, 4 cmp
//   2 Bernstein bases: s (1 add), b (10 mul), d (10 mul, 2 add)  x2: 6 add, 40 mul
//   4 rows x (4 x (row, row_u): 24 mul, 24 add; position, tangent_u, tangent_v: 9 mul, 9 add)
//                                                  132 add, 132 mul
//   4 interior derivative terms: w (1 mul), 2 x (3 mul, 3 add)      24 add, 28 mul
//   normal: cross (6 mul, 3 add), dot (3 mul, 2 add), sqrt, len > 0, 1/len, scale (3 mul)
//                                                  5 add, 12 mul, 1 sqrt, 1 cmp, 1 div
//   edge_symmetric: v == 0, u == 1, v == 1, u == 0   4 cmp
// Set-up: every stencil entry is one vec3 multiply-add: 3 mul + 3 add.
TEST(GregoryAcc, OperationCountsMatchAHandCount) {
  const mesh::Mesh mesh = loadAsset("opensubdiv/catmark_cube.obj");
  for (const char* variant : {"asymmetric", "edge_symmetric"}) {
    const auto patches = build(mesh, variant);
    const std::optional<techniques::OperationProfile> profile = patches->operationProfile(2);
    ASSERT_TRUE(profile.has_value());
    EXPECT_EQ(profile->per_vertex.add, 205u);
    EXPECT_EQ(profile->per_vertex.mul, 304u);
    EXPECT_EQ(profile->per_vertex.div, 5u);
    EXPECT_EQ(profile->per_vertex.sqrt, 1u);
    EXPECT_EQ(profile->per_vertex.compare, std::string(variant) == "asymmetric" ? 5u : 9u);
    const GregoryStencils stencils = buildGregoryStencils(mesh);
    uint64_t entries = 0;
    for (uint32_t s : stencils.patch_points[2])
      entries += stencils.offsets[s + 1] - stencils.offsets[s];
    EXPECT_EQ(profile->per_patch_setup.mul, 3 * entries);
    EXPECT_EQ(profile->per_patch_setup.add, 3 * entries);
    EXPECT_EQ(profile->per_patch_setup.div + profile->per_patch_setup.compare, 0u);
  }
}

}  // namespace
}  // namespace tb::gregory_acc

namespace tb::gregory_acc {
namespace {

// Oracle: the OBJ's own face sizes (catmark_pyramid: 1 quad, 4 triangles).
TEST(GregoryAcc, QuadsAndTrianglesGetOnePatchPerFaceAndOneProgramPerDomain) {
  const mesh::Mesh pyramid = loadAsset("opensubdiv/catmark_pyramid.obj");
  const auto patches = build(pyramid, "edge_symmetric");
  ASSERT_EQ(patches->patchCount(), pyramid.faceCount());
  size_t triangles = 0;
  for (size_t p = 0; p < patches->patchCount(); ++p) {
    EXPECT_EQ(patches->patchDomain(p), pyramid.faceSize(p) == 3 ? techniques::PatchDomain::kTriangle
                                                                : techniques::PatchDomain::kQuad);
    EXPECT_EQ(patches->sourceFace(p), p);
    triangles += patches->patchDomain(p) == techniques::PatchDomain::kTriangle;
  }
  EXPECT_EQ(triangles, 4u);
  EXPECT_EQ(patches->approximates(), techniques::LimitScheme::kCatmullClark);
  const std::vector<gpu::GpuPatchProgram> programs = patches->gpuPrograms();
  ASSERT_EQ(programs.size(), 2u);
  EXPECT_EQ(programs[0].domain, tess::Domain::kQuad);
  EXPECT_EQ(programs[0].patch_ids, std::vector<uint32_t>({4}));
  EXPECT_EQ(programs[1].domain, tess::Domain::kTriangle);
  EXPECT_EQ(programs[1].patch_ids, std::vector<uint32_t>({0, 1, 2, 3}));
  EXPECT_EQ(programs[1].storage_buffers.back().size(), 4u * kPointsPerTriangle);
  // 20 ids per quad, 15 per triangle.
  EXPECT_EQ(patches->footprint().patch_data_bytes, (20u + 4u * 15u) * 4u);
  // quads_only: refined once, 4 + 4 * 3 quads.
  const auto refined = build(pyramid, "quads_only");
  EXPECT_EQ(refined->patchCount(), 16u);
  EXPECT_EQ(refined->gpuPrograms().size(), 1u);
  // Faces of 5+ vertices: refined once in every variant (catmark_nonquads: 7 triangles,
  // 7 quads, 1 pentagon, 2 hexagons -> 21 + 28 + 5 + 12 quads).
  const auto nonquads = build(loadAsset("opensubdiv/catmark_nonquads.obj"), "edge_symmetric");
  EXPECT_EQ(nonquads->patchCount(), 66u);
  EXPECT_EQ(nonquads->patchDomain(0), techniques::PatchDomain::kQuad);
}

// Triangle patches on Catmull-Clark triangles, graded by the error measure against the
// Bfr limit through its quad sub-faces. Measured (fractions of the bbox diagonal):
// parametric max 1.53e-2 / 2.51e-2 / 1.29e-2 / 1.60e-2 and Hausdorff 1.30e-2 / 1.45e-2 /
// 1.10e-2 / 1.00e-2 on the four assets below. A regression bound with about 20% headroom:
// one cubic-boundary patch per triangle is not the limit (the lower bound). The G1 test
// below is the sharper check of the interior points.
TEST(GregoryAcc, TrianglePatchesStayCloseToTheCatmullClarkLimit) {
  for (const char* asset : {"opensubdiv/catmark_pyramid.obj", "opensubdiv/loop_cube.obj",
                            "opensubdiv/loop_icosahedron.obj", "tessbench/tri_torus.obj"}) {
    SCOPED_TRACE(asset);
    const mesh::Mesh mesh = loadAsset(asset);
    const auto patches = build(mesh, "edge_symmetric");
    const ref::LimitSurface limit(patches->controlMesh(), osd::Scheme::kCatmullClark);
    const measures::SurfaceErrorFigures f = measures::measureSurfaceError(*patches, limit);
    size_t triangles = 0;
    for (size_t p = 0; p < patches->patchCount(); ++p) {
      triangles += patches->patchDomain(p) == techniques::PatchDomain::kTriangle;
    }
    EXPECT_GT(triangles, 0u);
    EXPECT_EQ(f.patches_through_sub_faces, triangles);
    EXPECT_EQ(f.patches_without_limit, 0u);
    EXPECT_LT(f.parametric_max, 3e-2);
    EXPECT_LT(f.hausdorff, 1.8e-2);
    EXPECT_LT(f.normal_mean_deg, 6.0);
    EXPECT_GT(f.parametric_max, 1e-4);  // one cubic per triangle is not the limit
  }
}

// Gregory patches meet their neighbours with G1 continuity along every shared edge (the
// Chiyokura-Kimura condition the face points are built for), quad or triangle, so the
// analytic normals from both sides agree inside each edge. (The corners are left out: the
// rational blends are 0/0 there, and the corner normals are tested against Bfr above.)
TEST(GregoryAcc, NormalsAgreeAcrossSharedEdgesOfQuadsAndTriangles) {
  for (const char* asset :
       {"opensubdiv/catmark_pyramid.obj", "opensubdiv/catmark_cube.obj", "opensubdiv/loop_cube.obj",
        "tessbench/tri_torus.obj", "opensubdiv/catmark_xord_interior.obj"}) {
    const mesh::Mesh mesh = loadAsset(asset);
    const auto patches = build(mesh, "edge_symmetric");
    const mesh::Mesh& control = patches->controlMesh();
    const std::vector<testing::EdgeTwin> twins = testing::edgeTwins(control);
    double worst_deg = 0;
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      const techniques::PatchDomain domain = patches->patchDomain(f);
      for (int c = 0; c < cornerCount(domain); ++c) {
        const testing::EdgeTwin twin = twins[f * 4 + c];
        if (twin.face < 0) continue;
        const techniques::PatchDomain other = patches->patchDomain(size_t(twin.face));
        for (double t : {0.125, 0.3, 0.5, 0.77}) {
          const mesh::Vec3d n = patches->evaluate(f, edgeCoord(domain, c, t)).normal;
          const mesh::Vec3d m =
              patches->evaluate(size_t(twin.face), edgeCoord(other, twin.corner, 1 - t)).normal;
          const double cos_angle = std::clamp(dot(n, m) / (length(n) * length(m)), -1.0, 1.0);
          worst_deg = std::max(worst_deg, std::acos(cos_angle) * 180 / M_PI);
        }
      }
    }
    // Measured: 1.2e-6 degrees on every asset (acos resolves about 1.2e-6 near 1). With
    // the triangle's interior points set to the quad face points F instead of
    // (E + 3 F) / 4, the pyramid, loop_cube and tri_torus show kinks of 2.9, 4.5 and 6.0
    // degrees, so this fails.
    EXPECT_LT(worst_deg, 1e-4) << asset;
  }
}

}  // namespace
}  // namespace tb::gregory_acc
