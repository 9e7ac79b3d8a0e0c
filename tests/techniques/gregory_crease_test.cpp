// gregory_acc with creases, corners, holes and boundary interpolation edge-only / none
// (techniques/common/crease_refinement.h; Kovacs, Mitchell, Drone & Zorin, I3D 2009: a sharp
// edge is a boundary for patch construction). Oracles: the OpenSubdiv Bfr limit surface
// along the crease curves (a crease curve is the cubic B-spline of its crease vertices,
// which the sectors' P and E reproduce exactly), the patch on the other side of a sharp edge
// (bitwise in float, on the CPU and in lavapipe's capture), the same mesh without its hole
// tag, and the one-line messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/mesh/bounds.h"
#include "core/mesh/obj_loader.h"
#include "core/tess/tessellator.h"
#include "harness/measures/common/cracks/cracks.h"
#include "reference/limit_surface.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/gregory_acc/gregory_acc.h"
#include "techniques/gregory_acc/gregory_stencils.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/techniques/gregory_acc_test_support.h"
#include "tests/test_support.h"

namespace tb::gregory_acc {
namespace {

// Every bundled Catmull-Clark asset with crease or corner tags (pyramid_creases1 has
// triangles), and edgecorner (a boundary; its OBJ tag is edge-and-corner).
const std::vector<std::string> kCreasedAssets = {
    "opensubdiv/catmark_cube_creases1.obj", "opensubdiv/catmark_single_crease.obj",
    "opensubdiv/catmark_tent_creases1.obj", "opensubdiv/catmark_pawn.obj",
    "opensubdiv/catmark_helmet.obj",        "opensubdiv/catmark_chaikin0.obj",
    "opensubdiv/catmark_cube_corner3.obj",  "opensubdiv/catmark_pyramid_creases1.obj",
    "opensubdiv/catmark_edgecorner.obj"};

// The variants whose shared edges are evaluated symmetrically (bitwise watertight).
const char* const kSymmetricVariants[] = {"edge_symmetric", "exact_tangents", "quads_only"};

using tb::testing::diagonalOf;
using tb::testing::loadAsset;

techniques::VariantInfo variantNamed(const std::string& name) {
  for (const techniques::VariantInfo& info : GregoryAccTechnique().variants()) {
    if (info.name == name) return info;
  }
  throw std::runtime_error("no variant " + name);
}

techniques::BuiltSurface build(const mesh::Mesh& mesh,
                               const std::string& variant = "edge_symmetric") {
  return techniques::buildSurface(GregoryAccTechnique(), mesh, variantNamed(variant));
}

bool creaseOrCorner(techniques::SharpVertexKind kind) {
  return kind == techniques::SharpVertexKind::kCrease ||
         kind == techniques::SharpVertexKind::kCorner;
}

// An n x n grid of quads over a curved height field, with `tags` appended.
std::string grid(int n, const std::string& tags) {
  std::string obj;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double z = 0.15 * (i - 1.3) * (i - 1.3) - 0.1 * j * (i - j) + 0.05 * j * j;
      obj += "v " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(z) + "\n";
    }
  }
  auto at = [n](int i, int j) { return std::to_string(1 + j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      obj +=
          "f " + at(i, j) + " " + at(i + 1, j) + " " + at(i + 1, j + 1) + " " + at(i, j + 1) + "\n";
    }
  }
  return obj + tags;
}

const char kCube[] =
    "v -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\nv -1 1 -1\nv 1 1 -1\nv -1 -1 -1\nv 1 -1 -1\n"
    "f 1 2 4 3\nf 3 4 6 5\nf 5 6 8 7\nf 7 8 2 1\nf 2 8 6 4\nf 7 1 3 5\n";
// Infinitely sharp creases around the top face, and one down from vertex 0: vertices 1, 2,
// 3 are crease vertices (sectors of 1 and 2 faces), 0 a corner (three sharp edges), 6 a
// dart. Nothing semi-sharp: the limit is the input's own.
const char kCubeCreaseLoop[] =
    "t crease 2/1/0 0 1 10\nt crease 2/1/0 1 3 10\nt crease 2/1/0 3 2 10\n"
    "t crease 2/1/0 2 0 10\nt crease 2/1/0 0 6 10\n";

struct CurveFigures {
  size_t sides = 0;  // (patch, sharp edge) pairs checked
  double worst = 0;  // max |patch - limit| / bbox diagonal
};

// Along every sharp edge of the control mesh whose ends are crease or corner vertices,
// from each patch on it: the patch's boundary curve against Bfr over `limit_mesh`, whose
// faces are the control mesh's (quads: the same (u, v)).
CurveFigures creaseCurveError(const techniques::SurfacePatches& patches,
                              const techniques::CreasePreparation& creases,
                              const mesh::Mesh& limit_mesh, double diagonal) {
  const mesh::Mesh& control = patches.controlMesh();
  EXPECT_EQ(control.positions.size(), creases.control.positions.size());
  const ref::LimitSurface limit(limit_mesh, osd::Scheme::kCatmullClark);
  CurveFigures figures;
  for (size_t f = 0; f < patches.patchCount(); ++f) {
    EXPECT_EQ(patches.patchDomain(f), techniques::PatchDomain::kQuad);
    const auto fv = control.facePositions(f);
    for (int c = 0; c < 4; ++c) {
      const uint32_t a = fv[c], b = fv[(c + 1) % 4];
      if (!creases.isSharp(a, b) || !creaseOrCorner(creases.vertex_kind[a]) ||
          !creaseOrCorner(creases.vertex_kind[b])) {
        continue;
      }
      ++figures.sides;
      for (double t : {0.0, 0.1, 0.25, 0.4, 0.5, 0.66, 0.9, 1.0}) {
        const techniques::DomainCoord d = testing::edgeCoord(techniques::PatchDomain::kQuad, c, t);
        const mesh::Vec3d exact = limit.evaluate(f, d[0], d[1]).position;
        figures.worst =
            std::max(figures.worst, length(patches.evaluate(f, d).position - exact) / diagonal);
      }
    }
  }
  return figures;
}

TEST(GregoryCrease, EveryBundledCreasedCatmarkAssetIsAccepted) {
  GregoryAccTechnique technique;
  for (const std::string& name : kCreasedAssets) {
    const mesh::Mesh mesh = loadAsset(name);
    EXPECT_EQ(technique.checkSupport(mesh), "") << name;
    for (const techniques::VariantInfo& variant : technique.variants()) {
      const auto patches = techniques::buildSurface(technique, mesh, variant);
      EXPECT_GT(patches->patchCount(), 0u) << name << " " << variant.name;
    }
    const techniques::CreasePreparation creases = testing::defaultCreases(mesh);
    size_t kinds[5] = {};
    for (techniques::SharpVertexKind kind : creases.vertex_kind) ++kinds[int(kind)];
    std::printf(
        "[gregory creases] %-40s %4zu patches, %d of %d levels, %3zu sharp edges, "
        "rounded %.3g; vertices: %zu crease, %zu corner, %zu dart\n",
        name.c_str(), build(mesh)->patchCount(), creases.levels, creases.levels_needed,
        creases.sharp_edges.size(), creases.rounded_sharpness, kinds[2], kinds[3], kinds[1]);
  }
}

// The crease curve depends on the crease vertices only (P = the B-spline limit point,
// E = its Bézier points; a corner's E the end rule), so it is the limit's crease curve
// exactly, whatever the faces on either side.
TEST(GregoryCrease, CreaseCurvesEqualTheBfrLimit) {
  size_t checked = 0;
  const auto check = [&](const std::string& name, const mesh::Mesh& mesh) {
    const techniques::CreasePreparation creases = testing::defaultCreases(mesh);
    const double diagonal = diagonalOf(mesh);
    for (const char* variant : {"edge_symmetric", "asymmetric", "exact_tangents"}) {
      const auto patches = build(mesh, variant);
      // The limit the patches approximate: the control mesh itself, or with the leftover
      // semi-sharp creases rounded as the patches round them.
      const mesh::Mesh limit_mesh = testing::limitMeshOf(*patches, creases);
      const CurveFigures figures = creaseCurveError(*patches, creases, limit_mesh, diagonal);
      std::printf(
          "[gregory crease curves] %-40s %-14s %4zu edge sides: max |patch - limit| / "
          "diagonal %.2e (limit over the %s control mesh)\n",
          name.c_str(), variant, figures.sides, figures.worst,
          creases.rounded_sharpness == 0 ? "true" : "rounded");
      EXPECT_LE(figures.worst, 1e-12) << name << " " << variant;
      checked += figures.sides;
    }
  };
  for (const std::string& name : kCreasedAssets) check(name, loadAsset(name));
  check("cube with an infinitely sharp crease loop",
        mesh::loadObjText(std::string(kCube) + kCubeCreaseLoop, "crease_loop.obj"));
  check("grid, edge-only boundary",
        mesh::loadObjText(grid(3, "t interpolateboundary 1/0/0 2\n"), "edge_only.obj"));
  EXPECT_GT(checked, 500u);
}

// The same limit with nothing rounded: the crease loop cube against Bfr over the control
// mesh as it is, and a corner patch (vertex 0, three sharp edges) interpolates its vertex.
TEST(GregoryCrease, InfinitelySharpCreasesNeedNoRounding) {
  const mesh::Mesh mesh =
      mesh::loadObjText(std::string(kCube) + kCubeCreaseLoop, "crease_loop.obj");
  const techniques::CreasePreparation creases = testing::defaultCreases(mesh);
  EXPECT_EQ(creases.levels, 0);
  EXPECT_EQ(creases.rounded_sharpness, 0.0);
  EXPECT_EQ(creases.vertex_kind[0], techniques::SharpVertexKind::kCorner);
  EXPECT_EQ(creases.vertex_kind[1], techniques::SharpVertexKind::kCrease);
  EXPECT_EQ(creases.vertex_kind[6], techniques::SharpVertexKind::kDart);
  const auto patches = build(mesh);
  const ref::LimitSurface limit(patches->controlMesh(), osd::Scheme::kCatmullClark);
  const CurveFigures figures = creaseCurveError(*patches, creases, patches->controlMesh(), 1.0);
  EXPECT_EQ(figures.sides, 8u);  // the top face's 4 edges, from both sides
  EXPECT_LE(figures.worst, 1e-12);
  // Face 0 = (0, 1, 3, 2): corner 0 is vertex 0, the corner.
  EXPECT_LE(length(patches->evaluate(0, {0, 0, 0}).position - mesh.positions[0]), 1e-15);
  EXPECT_LE(length(limit.evaluate(0, 0, 0).position - mesh.positions[0]), 1e-12);
}

// The P of a crease or corner vertex and E along a sharp edge are one stencil, which both
// sides read (the builder forms them from each sector and requires the same terms).
TEST(GregoryCrease, BothSidesOfASharpEdgeShareItsPointStencils) {
  size_t total = 0;
  for (const std::string& name : kCreasedAssets) {
    const mesh::Mesh mesh = loadAsset(name);
    const GregoryBuild built = buildGregory(mesh);
    const techniques::CreasePreparation& creases = built.creases;
    ASSERT_FALSE(built.refined) << name;
    const std::vector<testing::EdgeTwin> twins = testing::edgeTwins(built.control);
    size_t shared = 0;
    for (size_t f = 0; f < built.patch_count; ++f) {
      const auto fv = built.control.facePositions(f);
      if (fv.size() != 4) continue;
      for (int c = 0; c < 4; ++c) {
        const testing::EdgeTwin twin = twins[f * 4 + c];
        if (twin.face < 0 || !creases.isSharp(fv[c], fv[(c + 1) % 4])) continue;
        // Twin corner twin.corner is fv[c + 1]; the next one is fv[c], whose Em runs back.
        const auto& mine = built.stencils.patch_points[f];
        const auto& theirs = built.stencils.patch_points[size_t(twin.face)];
        const int other = (twin.corner + 1) % 4;
        EXPECT_EQ(mine[c * 5 + kP], theirs[other * 5 + kP]) << name;
        EXPECT_EQ(mine[c * 5 + kEp], theirs[other * 5 + kEm]) << name;
        ++shared;
      }
    }
    std::printf("[gregory crease sharing] %-40s %3zu sharp patch edges with a twin share P and E\n",
                name.c_str(), shared);
    total += shared;
  }
  EXPECT_GT(total, 300u);
}

// CPU float, symmetric variants: across every sharp edge the two patches give the same
// bits at mirrored edge coordinates (integer 16 and fractional-odd 7.3 points).
TEST(GregoryCrease, SymmetricVariantsAreBitwiseWatertightAcrossCreasesInFloat) {
  std::vector<float> ts;
  for (const auto& [level, spacing] : {std::pair{7.3f, tess::Spacing::kFractionalOdd},
                                       std::pair{16.0f, tess::Spacing::kInteger}}) {
    tess::Levels levels;
    levels.outer = {level, level, level, level};
    levels.inner = {level, level};
    for (const tess::DomainPoint& d :
         tess::tessellate(tess::Domain::kQuad, spacing, levels).points) {
      if (d[1] == 0.0f) ts.push_back(d[0]);
    }
  }
  for (const char* variant : kSymmetricVariants) {
    size_t pairs = 0, unequal = 0;
    for (const std::string& name : kCreasedAssets) {
      const mesh::Mesh mesh = loadAsset(name);
      const auto patches = build(mesh, variant);
      const techniques::CreasePreparation creases = testing::defaultCreases(mesh);
      const mesh::Mesh& control = patches->controlMesh();
      const std::vector<testing::EdgeTwin> twins = testing::edgeTwins(control);
      for (size_t f = 0; f < patches->patchCount(); ++f) {
        const auto fv = control.facePositions(f);
        const techniques::PatchDomain domain = patches->patchDomain(f);
        for (int c = 0; c < testing::cornerCount(domain); ++c) {
          const testing::EdgeTwin twin = twins[f * 4 + c];
          if (twin.face < 0 || !creases.isSharp(fv[c], fv[(c + 1) % fv.size()])) continue;
          const techniques::PatchDomain other = patches->patchDomain(size_t(twin.face));
          for (float t : ts) {
            const mesh::Vec3f p =
                patches->evaluateFloat(f, testing::edgeCoord(domain, c, t)).position;
            const mesh::Vec3f q = patches
                                      ->evaluateFloat(size_t(twin.face),
                                                      testing::edgeCoord(other, twin.corner, 1 - t))
                                      .position;
            ++pairs;
            unequal += !(p == q);
          }
        }
      }
    }
    std::printf(
        "[gregory crease watertight cpu] %-14s %zu point pairs across sharp edges, %zu "
        "not bitwise equal\n",
        variant, pairs, unequal);
    EXPECT_GT(pairs, 1000u) << variant;
    EXPECT_EQ(unequal, 0u) << variant;
  }
}

// lavapipe: the crack measure over every shared edge (crease edges included) of the
// creased assets, a holed cube and grids with edge-only / none boundaries (the TCS reads
// the stencils from buffers: no shader knows about creases or holes), capture against
// capture, and the capture against evaluateFloat.
TEST(GregoryCrease, SymmetricVariantsAreBitwiseWatertightInTheLavapipeCapture) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  std::vector<std::pair<std::string, mesh::Mesh>> meshes;
  for (const std::string& name : kCreasedAssets) meshes.emplace_back(name, loadAsset(name));
  meshes.emplace_back("holed cube",
                      mesh::loadObjText(std::string(kCube) + "t hole 1/0/0 2\n", "holed.obj"));
  meshes.emplace_back("crease loop cube",
                      mesh::loadObjText(std::string(kCube) + kCubeCreaseLoop, "loop.obj"));
  meshes.emplace_back("edge-only grid",
                      mesh::loadObjText(grid(3, "t interpolateboundary 1/0/0 2\n"), "eo.obj"));
  meshes.emplace_back("none grid",
                      mesh::loadObjText(grid(4, "t interpolateboundary 1/0/0 0\n"), "none.obj"));
  for (const char* variant : kSymmetricVariants) {
    uint64_t pairs = 0, unequal = 0, device_ulp = 0;
    for (const auto& [name, mesh] : meshes) {
      const auto patches = build(mesh, variant);
      for (const auto& [level, spacing] : {std::pair{7.3f, tess::Spacing::kFractionalOdd},
                                           std::pair{16.0f, tess::Spacing::kInteger}}) {
        const measures::CrackFigures f = measures::measureCracks(
            *patches, spacing, level, measures::CrackBackend::kGpu, &context);
        ASSERT_TRUE(f.measured) << f.skipped_reason;
        EXPECT_EQ(f.points_not_equal, 0u) << name << " " << variant << " level " << level;
        EXPECT_EQ(f.unpaired_points, 0u) << name;
        pairs += f.points_compared;
        unequal += f.points_not_equal;
        device_ulp = std::max(device_ulp, f.device_max_ulp);
      }
    }
    std::printf(
        "[gregory crease watertight lavapipe] %-14s %llu point pairs, %llu not bitwise "
        "equal; capture up to %llu ulp from evaluateFloat\n",
        variant, (unsigned long long)pairs, (unsigned long long)unequal,
        (unsigned long long)device_ulp);
    EXPECT_EQ(device_ulp, 0u) << variant;
  }
}

// A hole gets no patch; the other faces' patches are those of the mesh without the tag
// (the rings still include the hole's face).
TEST(GregoryCrease, HoleFacesGetNoPatchButShapeTheirNeighbours) {
  const mesh::Mesh whole = mesh::loadObjText(kCube, "cube.obj");
  const mesh::Mesh holed = mesh::loadObjText(std::string(kCube) + "t hole 1/0/0 2\n", "holed.obj");
  EXPECT_EQ(GregoryAccTechnique().checkSupport(holed), "");
  const auto with_hole = build(holed);
  const auto without = build(whole);
  ASSERT_EQ(with_hole->patchCount(), 5u);
  EXPECT_EQ(with_hole->controlMesh().faceCount(), 6u);
  const std::vector<uint32_t> sources = {0, 1, 3, 4, 5};
  for (size_t p = 0; p < 5; ++p) {
    EXPECT_EQ(with_hole->sourceFace(p), sources[p]);
    for (const techniques::DomainCoord& d :
         {techniques::DomainCoord{0, 0, 0}, techniques::DomainCoord{0.3, 0.8, 0},
          techniques::DomainCoord{1, 0.45, 0}, techniques::DomainCoord{0.5, 0.5, 0}}) {
      // The rings start at other faces (the hole moved last): rounding differs, 1 ulp.
      EXPECT_LE(
          length(with_hole->evaluate(p, d).position - without->evaluate(sources[p], d).position),
          1e-15);
    }
  }
  const std::vector<gpu::GpuPatchProgram> programs = with_hole->gpuPrograms();
  ASSERT_EQ(programs.size(), 1u);
  EXPECT_EQ(programs[0].patch_count, 5u);
  EXPECT_EQ(programs[0].storage_buffers.back().size(), 5u * kPointsPerPatch);
}

// Boundary interpolation none: the faces at the boundary have no limit surface (holes);
// the middle face of a 3 x 3 grid is a regular B-spline patch, which gregory_acc is.
TEST(GregoryCrease, BoundaryInterpolationNoneKeepsOnlyTheInteriorFace) {
  const mesh::Mesh mesh = mesh::loadObjText(grid(3, "t interpolateboundary 1/0/0 0\n"), "none.obj");
  const auto patches = build(mesh);
  ASSERT_EQ(patches->patchCount(), 1u);
  EXPECT_EQ(patches->sourceFace(0), 4u);
  const ref::LimitSurface limit(patches->controlMesh(), osd::Scheme::kCatmullClark);
  ASSERT_TRUE(limit.isRegular(0));
  for (double u : {0.0, 0.3, 0.75, 1.0}) {
    for (double v : {0.0, 0.5, 0.9}) {
      EXPECT_LE(length(patches->evaluate(0, {u, v, 0}).position - limit.evaluate(0, u, v).position),
                1e-12 * diagonalOf(mesh));
    }
  }
}

// Edge-only: a one-face boundary vertex is a crease vertex, not a corner: the boundary
// curve does not pass through the grid's corner vertex (edge-and-corner's does).
TEST(GregoryCrease, EdgeOnlyBoundaryCornersAreCreaseVertices) {
  const mesh::Mesh edge_only =
      mesh::loadObjText(grid(3, "t interpolateboundary 1/0/0 2\n"), "edge_only.obj");
  const mesh::Mesh edge_and_corner =
      mesh::loadObjText(grid(3, "t interpolateboundary 1/0/0 1\n"), "eac.obj");
  EXPECT_EQ(testing::defaultCreases(edge_only).vertex_kind[0],
            techniques::SharpVertexKind::kCrease);
  EXPECT_EQ(testing::defaultCreases(edge_and_corner).vertex_kind[0],
            techniques::SharpVertexKind::kCorner);
  const auto a = build(edge_only), b = build(edge_and_corner);
  ASSERT_EQ(a->patchCount(), 9u);
  EXPECT_EQ(b->evaluate(0, {0, 0, 0}).position, edge_and_corner.positions[0]);
  EXPECT_GT(length(a->evaluate(0, {0, 0, 0}).position - edge_only.positions[0]), 0.1);
  const ref::LimitSurface limit(a->controlMesh(), osd::Scheme::kCatmullClark);
  EXPECT_LE(length(a->evaluate(0, {0, 0, 0}).position - limit.evaluate(0, 0, 0).position), 1e-12);
}

TEST(GregoryCrease, ConePointsAreRefusedWithTheirVertex) {
  const mesh::Mesh mesh =
      mesh::loadObjText(std::string(kCube) + "t corner 1/1/0 3 10\n", "cone.obj");
  const std::string expected =
      "gregory_acc: cone.obj: vertex 3 (1, 1, 1) is an infinitely sharp corner with fewer than "
      "two sharp edges (a cone point); Gregory patches cannot represent it";
  EXPECT_EQ(GregoryAccTechnique().checkSupport(mesh), expected);
  try {
    build(mesh);
    ADD_FAILURE() << "expected UnsupportedInput";
  } catch (const techniques::UnsupportedInput& error) {
    EXPECT_EQ(std::string(error.what()), expected);
  }
}

// A pentagon next to a crease: refineOnce knows no creases, so the mesh is refined once by
// OpenSubdiv instead, and the crease curve is still the limit's.
TEST(GregoryCrease, NGonsNextToCreasesAreRefinedByOpenSubdiv) {
  // A closed pentagonal prism: two pentagons and five quads; an infinitely sharp crease
  // around the top pentagon.
  std::string obj;
  for (int z : {0, 1}) {
    for (int i = 0; i < 5; ++i) {
      const double a = 2 * M_PI * i / 5;
      obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " " +
             std::to_string(z) + "\n";
    }
  }
  obj += "f 5 4 3 2 1\nf 6 7 8 9 10\n";
  for (int i = 0; i < 5; ++i) {
    const int j = (i + 1) % 5;
    obj += "f " + std::to_string(1 + i) + " " + std::to_string(1 + j) + " " +
           std::to_string(6 + j) + " " + std::to_string(6 + i) + "\n";
  }
  for (int i = 0; i < 5; ++i) {
    obj +=
        "t crease 2/1/0 " + std::to_string(5 + i) + " " + std::to_string(5 + (i + 1) % 5) + " 10\n";
  }
  const mesh::Mesh mesh = mesh::loadObjText(obj, "prism.obj");
  for (const char* variant : {"edge_symmetric", "quads_only"}) {
    const auto patches = build(mesh, variant);
    EXPECT_EQ(patches->patchCount(), 30u);  // 2 x 5 + 5 x 4 quads
    const techniques::CreasePreparation creases =
        techniques::prepareCreases(mesh, "gregory_acc", techniques::kDefaultCreaseFaceBudget, 1);
    const CurveFigures figures =
        creaseCurveError(*patches, creases, patches->controlMesh(), diagonalOf(mesh));
    EXPECT_EQ(figures.sides, 20u);  // 5 crease edges, 2 halves each, 2 sides
    EXPECT_LE(figures.worst, 1e-12) << variant;
  }
}

TEST(GregoryCrease, TheCreaseFaceBudgetIsAVariantParameter) {
  const mesh::Mesh mesh =
      loadAsset("opensubdiv/catmark_cube_creases1.obj");  // sharpness 5: 5 levels
  EXPECT_EQ(build(mesh)->patchCount(), 96u);              // 256 faces: 2 levels
  techniques::VariantInfo variant = variantNamed("edge_symmetric");
  variant.parameters["crease_face_budget"] = 1536.0;
  EXPECT_EQ(variantCreaseFaceBudget(variant), 1536u);
  EXPECT_EQ(techniques::buildSurface(GregoryAccTechnique(), mesh, variant)->patchCount(), 1536u);
}

}  // namespace
}  // namespace tb::gregory_acc

namespace tb::gregory_acc {
namespace {

// loop_icosahedron is closed but tagged edge-only: nothing sharp, so quads_only keeps the
// stencils over its own 12 vertices (refineOnce), as before creases were supported.
TEST(GregoryCrease, AClosedMeshsBoundaryTagForcesNoOpenSubdivRefinement) {
  const mesh::Mesh mesh = loadAsset("opensubdiv/loop_icosahedron.obj");
  ASSERT_EQ(mesh.tags.boundary, mesh::BoundaryInterpolation::kEdgeOnly);
  const auto patches = build(mesh, "quads_only");
  EXPECT_EQ(patches->footprint().control_mesh_bytes, 12u * 16u);  // vec4 per input vertex
  EXPECT_EQ(patches->patchCount(), 60u);                          // 20 triangles x 3 quads
}

}  // namespace
}  // namespace tb::gregory_acc
