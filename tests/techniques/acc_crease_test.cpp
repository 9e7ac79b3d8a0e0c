// acc on creased meshes (techniques/common/crease_refinement.h) against the OpenSubdiv Bfr
// limit of its control mesh:
// - along an infinitely sharp edge between crease or corner vertices the patch edge is the
//   crease curve itself (the cubic B-spline of the crease vertices, corners interpolated),
//   to rounding: both sides build it from the crease vertices alone;
// - semi-sharp creases are refined away within a face budget; the error next to them falls
//   as the budget grows and the leftover sharpness that is rounded shrinks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "core/mesh/bounds.h"
#include "core/mesh/obj_loader.h"
#include "reference/limit_surface.h"
#include "techniques/acc/acc.h"
#include "techniques/common/crease_refinement.h"
#include "tests/techniques/acc_test_support.h"
#include "tests/test_support.h"

namespace tb::acc {
namespace {

using tb::testing::diagonalOf;

mesh::Mesh bundled(const std::string& name) {
  return mesh::loadObjFile(tb::testing::assetPath("opensubdiv") + "/" + name + ".obj");
}

// catmark_cube with every edge infinitely sharp: every vertex a corner of three creases.
mesh::Mesh sharpCube() {
  mesh::Mesh mesh = bundled("catmark_cube");
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto c = mesh.facePositions(f);
    for (int k = 0; k < 4; ++k) {
      if (c[k] < c[(k + 1) % 4]) mesh.tags.creases.push_back({c[k], c[(k + 1) % 4], 10.0});
    }
  }
  return mesh;
}

// A 6 x 6 grid of unit quads in z = 0 lifted by a bump, with an infinitely sharp crease
// along the row y = 3 from x = 1 to x = 5 (darts at both ends: the crease vertices in
// between are regular crease vertices).
mesh::Mesh creasedGrid() {
  std::string obj;
  for (int y = 0; y <= 6; ++y) {
    for (int x = 0; x <= 6; ++x) {
      const double z = 0.3 * std::sin(0.9 * x) * std::cos(0.7 * y) + (y == 3 ? 0.4 : 0.0);
      obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
  }
  const auto id = [](int x, int y) { return std::to_string(1 + x + 7 * y); };
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 6; ++x) {
      obj +=
          "f " + id(x, y) + " " + id(x + 1, y) + " " + id(x + 1, y + 1) + " " + id(x, y + 1) + "\n";
    }
  }
  for (int x = 1; x < 5; ++x) {
    // OBJ tag vertex indices are 0-based.
    obj += "t crease 2/1/0 " + std::to_string(x + 7 * 3) + " " + std::to_string(x + 1 + 7 * 3) +
           " 10\n";
  }
  return mesh::loadObjText(obj, "creased_grid.obj");
}

// An n x n grid of unit quads, bumped so no patch is planar, with a boundary rule.
mesh::Mesh bumpyGrid(int n, int boundary_tag) {
  std::string obj;
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) {
      const double z = 0.3 * std::sin(0.9 * x + 0.2) * std::cos(0.7 * y + 0.1);
      obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
  }
  const auto id = [n](int x, int y) { return std::to_string(1 + x + (n + 1) * y); };
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      obj +=
          "f " + id(x, y) + " " + id(x + 1, y) + " " + id(x + 1, y + 1) + " " + id(x, y + 1) + "\n";
    }
  }
  obj += "t interpolateboundary 1/0/0 " + std::to_string(boundary_tag) + "\n";
  return mesh::loadObjText(obj, "grid.obj");
}

struct CurveFigures {
  size_t edges = 0;
  double worst = 0;  // max |patch - limit| / diagonal along those edges
};

// Every patch edge on an infinitely sharp control edge (a crease tag >= 10, or a mesh
// boundary) whose two ends are crease or corner vertices untouched by a finite sharpness
// (where the budget rounded a leftover sharpness the limit is not the crease curve), sampled
// at 17 points.
CurveFigures creaseCurveError(const mesh::Mesh& mesh) {
  const auto patches = techniques::buildSurface(AccTechnique(), mesh, {});
  const mesh::Mesh& control = patches->controlMesh();
  const techniques::CreasePreparation creases =
      techniques::prepareCreases(mesh, "acc", techniques::kDefaultCreaseFaceBudget);
  const ref::LimitSurface limit(control, osd::Scheme::kCatmullClark);
  std::set<uint64_t> infinitely_sharp;
  for (const mesh::Crease& c : control.tags.creases) {
    if (c.sharpness >= 10)
      infinitely_sharp.insert(techniques::CreasePreparation::sharpEdgeKey(c.v0, c.v1));
  }
  std::set<uint32_t> finite_sharp;
  for (const mesh::Crease& c : control.tags.creases) {
    if (c.sharpness > 0 && c.sharpness < 10) finite_sharp.insert({c.v0, c.v1});
  }
  for (const mesh::Corner& c : control.tags.corners) {
    if (c.sharpness > 0 && c.sharpness < 10) finite_sharp.insert(c.vertex);
  }
  std::map<uint64_t, int> edge_faces;
  for (size_t f = 0; f < control.faceCount(); ++f) {
    const auto c = control.facePositions(f);
    for (size_t k = 0; k < c.size(); ++k)
      ++edge_faces[techniques::CreasePreparation::sharpEdgeKey(c[k], c[(k + 1) % c.size()])];
  }
  const auto crease_end = [&](uint32_t v) {
    return (creases.vertex_kind[v] == techniques::SharpVertexKind::kCrease ||
            creases.vertex_kind[v] == techniques::SharpVertexKind::kCorner) &&
           !finite_sharp.count(v);
  };
  const double diagonal = diagonalOf(control);
  CurveFigures figures;
  for (size_t p = 0; p < patches->patchCount(); ++p) {
    const auto c = patches->patchCorners(p);
    const ref::LimitFace face = limit.face(p);
    for (int k = 0; k < 4; ++k) {
      const uint32_t a = c[k], b = c[(k + 1) % 4];
      const uint64_t key = techniques::CreasePreparation::sharpEdgeKey(a, b);
      const bool boundary =
          edge_faces[key] == 1 && control.tags.boundary != mesh::BoundaryInterpolation::kNone;
      if (!(infinitely_sharp.count(key) || boundary) || !crease_end(a) || !crease_end(b)) continue;
      ++figures.edges;
      for (int i = 0; i <= 16; ++i) {
        const auto uv = testing::edgeUv(k, i / 16.0);
        const mesh::Vec3d ours = patches->evaluate(p, {uv[0], uv[1], 0}).position;
        const mesh::Vec3d exact = face.evaluate(uv[0], uv[1]).position;
        figures.worst = std::max(figures.worst, length(ours - exact) / diagonal);
      }
    }
  }
  return figures;
}

TEST(AccCreases, InfinitelySharpCreaseCurvesEqualTheLimit) {
  size_t edges = 0;
  for (const auto& [name, mesh] : {std::pair<std::string, mesh::Mesh>{"sharp cube", sharpCube()},
                                   {"creased grid", creasedGrid()},
                                   {"catmark_single_crease", bundled("catmark_single_crease")},
                                   {"catmark_edgecorner", bundled("catmark_edgecorner")},
                                   {"catmark_tent_creases1", bundled("catmark_tent_creases1")},
                                   {"grid, edge-only boundary", bumpyGrid(4, 2)}}) {
    const CurveFigures f = creaseCurveError(mesh);
    std::printf(
        "%-24s %4zu sharp patch edges between crease/corner vertices: max |acc - limit| "
        "/ diagonal %.2e\n",
        name.c_str(), f.edges, f.worst);
    EXPECT_LT(f.worst, 1e-12) << name;
    edges += f.edges;
  }
  EXPECT_GT(edges, 40u);
}

// Boundary interpolation "none": OpenSubdiv gives a limit surface only to the faces with no
// boundary vertex; acc patches exactly those (the inner 2 x 2 of a 4 x 4 grid, regular: exact
// B-spline patches over the rings that run through the boundary faces), in input order.
TEST(AccCreases, BoundaryInterpolationNonePatchesTheInnerFacesOnly) {
  const mesh::Mesh mesh = bumpyGrid(4, 0);
  const auto patches = techniques::buildSurface(AccTechnique(), mesh, {});
  ASSERT_EQ(patches->patchCount(), 4u);
  EXPECT_EQ(patches->controlMesh().faceCount(), 16u);
  const ref::LimitSurface limit(patches->controlMesh(), osd::Scheme::kCatmullClark);
  double worst = 0;
  for (size_t p = 0; p < patches->patchCount(); ++p) {
    ASSERT_TRUE(limit.hasLimitSurface(p)) << "patch " << p;
    const ref::LimitFace face = limit.face(p);
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 8; ++j) {
        const mesh::Vec3d ours = patches->evaluate(p, {i / 8.0, j / 8.0, 0}).position;
        worst = std::max(worst, length(ours - face.evaluate(i / 8.0, j / 8.0).position));
      }
    }
  }
  for (size_t f = patches->patchCount(); f < 16; ++f) EXPECT_FALSE(limit.hasLimitSurface(f));
  EXPECT_EQ(patches->sourceFace(0), 5u);  // the inner faces of the 4 x 4 grid: 5, 6, 9, 10
  EXPECT_EQ(patches->sourceFace(3), 10u);
  std::printf("grid, boundary none: %zu patches, max |acc - limit| %.2e\n", patches->patchCount(),
              worst);
  EXPECT_LT(worst, 1e-12);
}

// Both sides of a creased edge are C0 in double (bitwise in float: the symmetric-variant
// crack tests in tests/measures/watertight_variants_test.cpp cover the creased assets), and
// the crease keeps its normal jump: the two sides' normals differ along a sharp edge between
// two crease vertices (towards a dart, where the crease fades, they meet).
TEST(AccCreases, SharpEdgesKeepTheirNormalJump) {
  const mesh::Mesh mesh = creasedGrid();
  const auto patches = techniques::buildSurface(AccTechnique(), mesh, {});
  std::map<std::pair<uint32_t, uint32_t>, std::pair<size_t, int>> first_side;
  double worst_gap = 0, smallest_jump = 1e9;
  size_t sharp_edges = 0;
  for (size_t p = 0; p < patches->patchCount(); ++p) {
    const auto c = patches->patchCorners(p);
    for (int k = 0; k < 4; ++k) {
      const auto other = first_side.find({c[(k + 1) % 4], c[k]});
      if (other == first_side.end()) {
        first_side[{c[k], c[(k + 1) % 4]}] = {p, k};
        continue;
      }
      const uint32_t lo = std::min(c[k], c[(k + 1) % 4]), hi = std::max(c[k], c[(k + 1) % 4]);
      const bool sharp = lo >= 22 && hi <= 26 && hi == lo + 1;  // vertices 22..26: y = 3, x = 1..5
      // The two edges between crease vertices (23-24, 24-25); 22 and 26 are darts.
      const bool between_creases = sharp && lo >= 23 && hi <= 25;
      sharp_edges += sharp;
      for (int i = 1; i < 16; ++i) {
        const auto ua = testing::edgeUv(k, i / 16.0);
        const auto ub = testing::edgeUv(other->second.second, 1 - i / 16.0);
        const techniques::SurfacePoint a = patches->evaluate(p, {ua[0], ua[1], 0});
        const techniques::SurfacePoint b =
            patches->evaluate(other->second.first, {ub[0], ub[1], 0});
        worst_gap = std::max(worst_gap, length(a.position - b.position));
        if (between_creases) smallest_jump = std::min(smallest_jump, length(a.normal - b.normal));
      }
    }
  }
  std::printf(
      "creased grid: max gap %.2e over every shared edge; smallest normal jump between "
      "crease vertices (%zu sharp edges) %.3f\n",
      worst_gap, sharp_edges, smallest_jump);
  EXPECT_EQ(sharp_edges, 4u);
  EXPECT_LT(worst_gap, 1e-14);
  EXPECT_GT(smallest_jump, 0.05);
}

// catmark_cube_creases1 (eleven edges of sharpness 5, one of 0.1) at growing face budgets.
// Below 6 x 4^5 faces the leftover sharpness (>= 1) is rounded to infinitely sharp: the true
// crease decays at level 5 whatever the budget, so the rounding error does not shrink with
// the budget; the ACC error at the cube's valence-3 corners shrinks with the patch size.
// With every level nothing is rounded, the patches are small, and the error falls by an
// order of magnitude. The crease faces are graded against the limit over the control mesh,
// which keeps the true leftover sharpness.
TEST(AccCreases, RefiningEveryLevelOfASemiSharpCreaseRemovesTheRoundingError) {
  const mesh::Mesh mesh = bundled("catmark_cube_creases1");
  std::vector<double> errors;
  for (double budget : {6.0, 24.0, 96.0, 384.0, 1536.0, 6144.0}) {
    techniques::VariantInfo variant{"budget", "", {{"crease_face_budget", budget}}};
    const auto patches = techniques::buildSurface(AccTechnique(), mesh, variant);
    const mesh::Mesh& control = patches->controlMesh();
    const ref::LimitSurface limit(control, osd::Scheme::kCatmullClark);
    const double diagonal = diagonalOf(control);
    double worst = 0;
    for (size_t p = 0; p < patches->patchCount(); ++p) {
      const ref::LimitFace face = limit.face(p);
      for (int i = 0; i <= 8; ++i) {
        for (int j = 0; j <= 8; ++j) {
          const double u = i / 8.0, v = j / 8.0;
          const mesh::Vec3d ours = patches->evaluate(p, {u, v, 0}).position;
          worst = std::max(worst, length(ours - face.evaluate(u, v).position) / diagonal);
        }
      }
    }
    std::printf(
        "catmark_cube_creases1 budget %5.0f faces: %4zu patches, max |acc - limit| / "
        "diagonal %.3e\n",
        budget, patches->patchCount(), worst);
    errors.push_back(worst);
  }
  // Rounded: within 5 % of the unrefined figure at every budget short of all levels.
  for (size_t i = 1; i + 1 < errors.size(); ++i) {
    EXPECT_NEAR(errors[i], errors[0], 0.05 * errors[0]) << "budget step " << i;
  }
  EXPECT_LT(errors.back(), errors.front() / 10);
}

}  // namespace
}  // namespace tb::acc
