// acc against its oracles: the OpenSubdiv Bfr limit surface (regular faces are exact
// B-spline patches; tangent patches bring normals closer to the limit's), the other
// patch of every shared edge (C0 in double, bitwise in float for symmetric orders), a
// hand count of the Bézier evaluation, and the rejection rules.
#include "techniques/acc/acc.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>

#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "core/tess/tessellator.h"
#include "reference/limit_surface.h"
#include "techniques/common/bezier_eval.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/common/quad_ring.h"
#include "tests/techniques/acc_test_support.h"

namespace tb::acc {
namespace {

using testing::supportedAssets;
using testing::variantNamed;

using tb::testing::diagonalOf;

std::vector<tess::DomainPoint> domainPoints() {
  tess::Levels levels;
  levels.outer = {7.3f, 7.3f, 7.3f, 7.3f};
  levels.inner = {7.3f, 7.3f};
  return tess::tessellate(tess::Domain::kQuad, tess::Spacing::kFractionalOdd, levels).points;
}

TEST(Acc, SupportedAssetsAreListed) {
  std::vector<std::string> rejected;
  const auto assets = supportedAssets(&rejected);
  for (const auto& a : assets) std::printf("acc supports %s\n", a.name.c_str());
  for (const auto& r : rejected) std::printf("acc rejects %s\n", r.c_str());
  EXPECT_GE(assets.size(), 3u);
}

// Oracle: Bfr limit (ApproxLevel 10) on faces Bfr itself represents by one B-spline.
TEST(Acc, RegularFacesEqualTheBfrLimit) {
  const auto points = domainPoints();
  size_t checked_faces = 0;
  for (const auto& asset : supportedAssets()) {
    const auto patches =
        techniques::buildSurface(AccTechnique(), asset.mesh, variantNamed("default"));
    // Over the control mesh: a creased input is refined there (techniques/common/
    // crease_refinement.h), with the same limit surface.
    const ref::LimitSurface limit(patches->controlMesh(), osd::Scheme::kCatmullClark);
    const double diag = diagonalOf(asset.mesh);
    double worst_d = 0, worst_f = 0;
    size_t faces = 0;
    for (size_t f = 0; f < patches->patchCount(); ++f) {
      if (!limit.isRegular(f)) continue;
      ++faces;
      const ref::LimitFace face = limit.face(f);
      for (const tess::DomainPoint& d : points) {
        const ref::LimitPoint exact = face.evaluate(d[0], d[1]);
        const techniques::SurfacePoint p = patches->evaluate(f, {d[0], d[1], 0});
        const techniques::SurfacePointF q = patches->evaluateFloat(f, d);
        worst_d = std::max(worst_d, length(p.position - exact.position) / diag);
        worst_f = std::max(worst_f, length(vecCast<double>(q.position) - exact.position) / diag);
        EXPECT_LT(length(p.normal - exact.normal), 1e-9) << asset.name << " face " << f;
      }
    }
    std::printf("%-28s %4zu regular faces: max |acc - limit| / diagonal double %.2e float %.2e\n",
                asset.name.c_str(), faces, worst_d, worst_f);
    EXPECT_LT(worst_d, 1e-12) << asset.name;
    EXPECT_LT(worst_f, 1e-6) << asset.name;
    checked_faces += faces;
  }
  EXPECT_GT(checked_faces, 50u);
}

double meanNormalAngleDeg(const mesh::Mesh& mesh, const std::string& variant) {
  const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
  const auto patches = techniques::buildSurface(AccTechnique(), mesh, variantNamed(variant));
  const auto points = domainPoints();
  double sum = 0;
  size_t count = 0;
  for (size_t f = 0; f < patches->patchCount(); ++f) {
    const ref::LimitFace face = limit.face(f);
    for (const tess::DomainPoint& d : points) {
      const mesh::Vec3d n = patches->evaluate(f, {d[0], d[1], 0}).normal;
      const mesh::Vec3d m = face.evaluate(d[0], d[1]).normal;
      sum += std::acos(std::clamp(dot(n, m), -1.0, 1.0)) * 180 / std::numbers::pi;
      ++count;
    }
  }
  return sum / double(count);
}

// Oracle: Bfr limit normals; §3.2's tangent patches exist to make normals smooth.
TEST(Acc, TangentPatchesBringNormalsCloserToTheLimit) {
  for (const char* name : {"catmark_cube.obj", "catmark_toroidal_tet.obj"}) {
    const mesh::Mesh mesh =
        mesh::loadObjFile(tb::testing::assetPath(std::string("opensubdiv/") + name));
    const double with = meanNormalAngleDeg(mesh, "default");
    const double without = meanNormalAngleDeg(mesh, "no_tangent");
    std::printf("%s mean normal deviation: tangent patches %.4f deg, geometry %.4f deg\n", name,
                with, without);
    EXPECT_LT(with, without) << name;
  }
}

// Oracle: the neighbouring patch evaluated at the same edge point.
TEST(Acc, SharedEdgesAreC0InDouble) {
  for (const auto& asset : supportedAssets()) {
    const auto patches =
        techniques::buildSurface(AccTechnique(), asset.mesh, variantNamed("default"));
    const double diag = diagonalOf(asset.mesh);
    std::map<std::pair<uint32_t, uint32_t>, std::pair<size_t, int>> first_side;
    double worst = 0;
    size_t edges = 0;
    for (size_t p = 0; p < patches->patchCount(); ++p) {
      const auto c = patches->patchCorners(p);
      for (int k = 0; k < 4; ++k) {
        const auto key = std::make_pair(c[(k + 1) % 4], c[k]);  // the other side's direction
        const auto other = first_side.find(key);
        if (other == first_side.end()) {
          first_side[{c[k], c[(k + 1) % 4]}] = {p, k};
          continue;
        }
        ++edges;
        for (int i = 0; i <= 16; ++i) {
          const double s = i / 16.0;
          const auto a = testing::edgeUv(k, s);
          const auto b = testing::edgeUv(other->second.second, 1 - s);
          const mesh::Vec3d pa = patches->evaluate(p, {a[0], a[1], 0}).position;
          const mesh::Vec3d pb = patches->evaluate(other->second.first, {b[0], b[1], 0}).position;
          worst = std::max(worst, length(pa - pb) / diag);
        }
      }
    }
    EXPECT_LT(worst, 1e-12) << asset.name;
    EXPECT_GT(edges, 0u) << asset.name;
  }
}

// Oracle: bitwise equality of the float points two patches give on their shared edge
// (docs/ARCHITECTURE.md §5 rule 1 and 2); asymmetric is reported, not asserted.
TEST(Acc, SymmetricOrdersAreBitwiseWatertightInFloat) {
  const auto points = domainPoints();
  for (const char* variant : {"default", "symmetric_nofma", "symmetric_edges", "asymmetric"}) {
    size_t shared = 0, differing = 0;
    for (const auto& asset : supportedAssets()) {
      const auto patches =
          techniques::buildSurface(AccTechnique(), asset.mesh, variantNamed(variant));
      std::map<testing::EdgeKey, mesh::Vec3f> seen;
      for (size_t p = 0; p < patches->patchCount(); ++p) {
        for (const tess::DomainPoint& d : points) {
          const auto keys = testing::edgeKeys(patches->patchCorners(p), d[0], d[1]);
          if (keys.empty()) continue;
          const mesh::Vec3f q = patches->evaluateFloat(p, d).position;
          for (const auto& key : keys) {
            const auto [it, inserted] = seen.emplace(key, q);
            if (inserted) continue;
            ++shared;
            if (!(it->second == q)) ++differing;
          }
        }
      }
    }
    std::printf("%-16s CPU float: %zu of %zu shared edge points differ\n", variant, differing,
                shared);
    EXPECT_GT(shared, 1000u);
    if (std::string(variant) != "asymmetric") {
      EXPECT_EQ(differing, 0u) << variant;
    }
  }
}

// Oracle: a hand count. Basis: 1 sub + 10 mul per parameter. Each of the 5 four-term
// sums (4 rows, 1 column) is 4 mul + 3 add per component (fma = mul + add): 60 + 45.
TEST(Acc, BicubicEvaluationOperationCountsMatchAHandCount) {
  using C = techniques::CountingScalar<float>;
  std::array<mesh::Vec3T<C>, 16> b{};
  for (techniques::BezierOrder order :
       {techniques::BezierOrder::kAsymmetric, techniques::BezierOrder::kSymmetricNoFma,
        techniques::BezierOrder::kSymmetricFma, techniques::BezierOrder::kSymmetricEdges}) {
    techniques::resetOperationCounts();
    (void)techniques::evaluateBicubic(b, C(0.25f), C(0.5f), order);
    EXPECT_EQ(techniques::operationCounts().mul, 80u);
    EXPECT_EQ(techniques::operationCounts().add, 47u);
  }
  const mesh::Mesh cube = mesh::loadObjFile(tb::testing::assetPath("opensubdiv/catmark_cube.obj"));
  const auto patches = techniques::buildSurface(AccTechnique(), cube, variantNamed("default"));
  const auto profile = patches->operationProfile(0);
  ASSERT_TRUE(profile.has_value());
  EXPECT_GT(profile->per_patch_setup.total(), profile->per_vertex.total());
  EXPECT_EQ(profile->per_vertex.sqrt, 1u);
  const mesh::Mesh torus =
      mesh::loadObjFile(tb::testing::assetPath("opensubdiv/catmark_torus.obj"));
  const auto regular =
      techniques::buildSurface(AccTechnique(), torus, variantNamed("default"))->operationProfile(0);
  ASSERT_TRUE(regular.has_value());
  // Valence 3 rings are smaller than valence 4 ones: the cube's set-up is cheaper.
  EXPECT_LT(profile->per_patch_setup.total(), regular->per_patch_setup.total());
  EXPECT_EQ(profile->per_vertex.total(), regular->per_vertex.total());
  for (const auto* p : {&*profile, &*regular}) {
    std::printf(
        "set-up %llu ops (%llu mul, %llu add), per vertex %llu ops (%llu mul, %llu add, "
        "%llu div, %llu sqrt): %s\n",
        (unsigned long long)p->per_patch_setup.total(), (unsigned long long)p->per_patch_setup.mul,
        (unsigned long long)p->per_patch_setup.add, (unsigned long long)p->per_vertex.total(),
        (unsigned long long)p->per_vertex.mul, (unsigned long long)p->per_vertex.add,
        (unsigned long long)p->per_vertex.div, (unsigned long long)p->per_vertex.sqrt,
        p->note.c_str());
  }
}

// Oracle: hand count of corner (valence, boundary) tuples up to rotation.
TEST(Acc, TopologyCombinationsAreCountedUpToRotation) {
  const mesh::Mesh cube = mesh::loadObjFile(tb::testing::assetPath("opensubdiv/catmark_cube.obj"));
  EXPECT_EQ(topologyCombinationCount(*techniques::buildSurface(AccTechnique(), cube, {})), 1u);
  // A 2x1 strip: both quads have corners (2 boundary, 3 boundary, 3 boundary, 2 boundary)
  // in rotated order, so one combination.
  const mesh::Mesh strip = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n", "strip");
  const auto patches = techniques::buildSurface(AccTechnique(), strip, {});
  EXPECT_EQ(topologyCombinationCount(*patches), 1u);
  EXPECT_GT(patches->footprint().stencil_bytes, 0u);
  for (const auto& asset : supportedAssets()) {
    const auto p = techniques::buildSurface(AccTechnique(), asset.mesh, {});
    std::printf("%-28s %5zu patches, %3zu topology combinations, stencil %llu bytes\n",
                asset.name.c_str(), p->patchCount(), topologyCombinationCount(*p),
                (unsigned long long)p->footprint().stencil_bytes);
    EXPECT_LE(topologyCombinationCount(*p), p->patchCount());
    // The memory measure reads the count from the footprint (results.json).
    EXPECT_EQ(p->footprint().topology_combinations, topologyCombinationCount(*p));
  }
}

std::string rejection(const std::string& obj) {
  try {
    techniques::buildSurface(AccTechnique(), mesh::loadObjText(obj, "test.obj"), {});
  } catch (const techniques::UnsupportedInput& error) {
    EXPECT_EQ(std::string(error.what()),
              AccTechnique().checkSupport(mesh::loadObjText(obj, "test.obj")));
    return error.what();
  }
  return "accepted";
}

constexpr const char* kGrid =
    "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\n"
    "f 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n";

TEST(AccRejects, NonQuadFacesNamingTheFace) {
  const std::string why = rejection(std::string(kGrid) + "f 3 9 6\n");
  EXPECT_NE(why.find("acc: face 4 (line 14) has 3 vertices; ACC needs quads"), std::string::npos)
      << why;
}

TEST(AccRejects, NonManifoldEdgesNamingTheEdge) {
  const std::string why = rejection(
      std::string(kGrid) + "v 1 0 1\nv 2 0 1\nv 1 0 -1\nv 2 0 -1\nf 2 3 11 10\nf 3 2 12 13\n");
  EXPECT_NE(why.find("edge 1-2 is shared by 3 faces"), std::string::npos) << why;
}

TEST(AccRejects, ConePointsNamingTheVertex) {
  // An infinitely sharp vertex tag inside a smooth region: no crease to split the ring at.
  const std::string why = rejection(std::string(kGrid) + "t corner 1/1/0 4 10\n");
  EXPECT_NE(why.find("acc: vertex 4 (1, 1, 0) is an infinitely sharp corner with fewer than two "
                     "sharp edges (a cone point)"),
            std::string::npos)
      << why;
}

// What used to be refused: holes, creases, corner tags and edge-only boundaries.
TEST(AccTags, HolesCreasesCornersAndBoundaryRulesAreAccepted) {
  EXPECT_EQ(rejection(std::string(kGrid) + "t hole 1/0/0 2\n"), "accepted");
  EXPECT_EQ(rejection(std::string(kGrid) + "t crease 2/1/0 3 4 2.5\n"), "accepted");
  EXPECT_EQ(rejection(std::string(kGrid) + "t crease 2/1/0 3 4 10\n"), "accepted");
  EXPECT_EQ(rejection(std::string(kGrid) + "t corner 1/1/0 4 1.0\n"), "accepted");
  EXPECT_EQ(rejection(std::string(kGrid) + "t interpolateboundary 1/0/0 2\n"), "accepted");
  // Boundary interpolation "none": every face of the 2 x 2 grid touches the boundary, so
  // OpenSubdiv gives none of them a limit surface.
  EXPECT_EQ(rejection(std::string(kGrid) + "t interpolateboundary 1/0/0 0\n"),
            "acc: test.obj has no face with a limit surface");
}

// A hole has no patch; the other faces keep theirs, in input order, and still use the
// hole's vertices (its corner points are those of the full ring).
TEST(AccTags, HoleFacesGetNoPatch) {
  const mesh::Mesh mesh = mesh::loadObjText(std::string(kGrid) + "t hole 1/0/0 2\n", "hole.obj");
  const auto patches = techniques::buildSurface(AccTechnique(), mesh, {});
  ASSERT_EQ(patches->patchCount(), 3u);
  EXPECT_EQ(patches->controlMesh().faceCount(), 4u);
  EXPECT_EQ(patches->sourceFace(0), 0u);
  EXPECT_EQ(patches->sourceFace(1), 1u);
  EXPECT_EQ(patches->sourceFace(2), 3u);
  EXPECT_EQ(patches->controlMesh().tags.holes, std::vector<uint32_t>{3});
}

TEST(AccRejects, NonManifoldVerticesNamingTheVertex) {
  // Two quads touching at one vertex only (a bow tie).
  const std::string why = rejection(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 1 0\nv 2 2 0\nv 1 2 0\nf 1 2 3 4\nf 3 5 6 7\n");
  EXPECT_NE(why.find("vertex 2 (1, 1, 0) has faces in more than one fan"), std::string::npos)
      << why;
}

TEST(AccRejects, ValenceAboveTheMaximumNamingTheVertex) {
  // A fan of 257 quads around vertex 0 (closed disc): valence 257, one above kMaxValence.
  std::string obj = "v 0 0 0\n";
  const int n = 257;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n, b = 2 * std::numbers::pi * (i + 0.5) / n;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    obj +=
        "v " + std::to_string(1.5 * std::cos(b)) + " " + std::to_string(1.5 * std::sin(b)) + " 0\n";
  }
  for (int i = 0; i < n; ++i) {
    const int e0 = 2 + 2 * i, f0 = 3 + 2 * i, e1 = 2 + 2 * ((i + 1) % n);
    obj += "f 1 " + std::to_string(e0) + " " + std::to_string(f0) + " " + std::to_string(e1) + "\n";
  }
  const std::string why = rejection(obj);
  EXPECT_NE(why.find("vertex 0 (0, 0, 0) has valence 257 above the maximum 256"), std::string::npos)
      << why;
}

}  // namespace
}  // namespace tb::acc

namespace tb {
namespace {

// Oracle: the faces' own corner order, which defines e_i, f_i and e_{i+1} of every slot.
TEST(QuadRings, EverySlotMatchesItsFacesCornerOrder) {
  for (const auto& asset : acc::testing::supportedAssets()) {
    const mesh::Mesh& mesh = asset.mesh;
    const techniques::QuadRings rings = techniques::buildQuadRings(mesh, "acc", acc::kMaxValence);
    const mesh::Topology topology = mesh::buildTopology(mesh);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      const auto c = mesh.facePositions(f);
      for (uint32_t k = 0; k < 4; ++k) {
        const uint32_t v = c[k], slot = rings.face_slots[f][k];
        EXPECT_EQ(rings.e(v, slot), c[(k + 1) % 4]) << asset.name << " face " << f;
        EXPECT_EQ(rings.f(v, slot), c[(k + 2) % 4]) << asset.name << " face " << f;
        EXPECT_EQ(rings.e(v, slot + 1), c[(k + 3) % 4]) << asset.name << " face " << f;
      }
    }
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
      EXPECT_EQ(rings.rings[v].valence, topology.valence[v]) << asset.name << " vertex " << v;
      EXPECT_EQ(rings.rings[v].boundary, topology.on_boundary[v] != 0) << asset.name;
    }
  }
}

}  // namespace
}  // namespace tb

namespace tb::acc {
namespace {

// Oracle: the neighbouring patch's normal at the same edge point. Tangent patches
// (§3.2) make the cross tangents of both sides sum to a multiple of the shared edge
// tangent, so the normals agree along every edge not touching an extraordinary
// boundary vertex (where acc keeps the geometry tangents); the geometry's own
// derivatives do not.
TEST(Acc, TangentPatchesMakeNormalsContinuousAcrossEdges) {
  for (const char* variant : {"default", "no_tangent"}) {
    double worst = 0;
    size_t edges = 0;
    for (const auto& asset : testing::supportedAssets()) {
      const techniques::CreasePreparation creases =
          techniques::prepareCreases(asset.mesh, "acc", techniques::kDefaultCreaseFaceBudget);
      const techniques::QuadRings rings =
          techniques::buildQuadRings(creases.control, "acc", kMaxValence, &creases);
      // Boundary, crease and corner vertices keep the geometry tangents (a regular boundary
      // or crease sector, valence 3, still matches its neighbour), and a sharp edge is meant
      // to break the normal.
      const auto keeps_geometry = [&](uint32_t v) {
        const techniques::SharpVertexKind kind = creases.vertex_kind[v];
        return (rings.rings[v].boundary && rings.rings[v].valence != 3) ||
               kind == techniques::SharpVertexKind::kCrease ||
               kind == techniques::SharpVertexKind::kCorner;
      };
      const auto patches =
          techniques::buildSurface(AccTechnique(), asset.mesh, variantNamed(variant));
      std::map<std::pair<uint32_t, uint32_t>, std::pair<size_t, int>> first_side;
      for (size_t p = 0; p < patches->patchCount(); ++p) {
        const auto c = patches->patchCorners(p);
        for (int k = 0; k < 4; ++k) {
          const uint32_t a = c[k], b = c[(k + 1) % 4];
          const auto other = first_side.find({b, a});
          if (other == first_side.end()) {
            first_side[{a, b}] = {p, k};
            continue;
          }
          if (keeps_geometry(a) || keeps_geometry(b) || creases.isSharp(a, b)) continue;
          ++edges;
          for (int i = 1; i < 16; ++i) {
            const auto ua = testing::edgeUv(k, i / 16.0);
            const auto ub = testing::edgeUv(other->second.second, 1 - i / 16.0);
            const mesh::Vec3d na = patches->evaluate(p, {ua[0], ua[1], 0}).normal;
            const mesh::Vec3d nb = patches->evaluate(other->second.first, {ub[0], ub[1], 0}).normal;
            worst = std::max(worst, length(na - nb));
          }
        }
      }
    }
    std::printf("%-10s max normal jump across %zu edges: %.3e (|n_a - n_b|)\n", variant, edges,
                worst);
    if (std::string(variant) == "default") {
      EXPECT_LT(worst, 1e-9);
    } else {
      EXPECT_GT(worst, 1e-3);
    }
  }
}

}  // namespace
}  // namespace tb::acc
