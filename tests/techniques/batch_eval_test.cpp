// Batched evaluation (techniques/batch_eval.h) of every registered surface technique.
// Oracles: the technique's own per-point evaluate() (the batch must equal it to ~1e-12
// of the bounding-box diagonal, every variant, extraordinary vertices, boundaries and
// triangle patches included), the OpenSubdiv Bfr limit derivatives on faces Bfr itself
// represents by one B-spline patch (where acc and gregory_acc are exact), and central
// finite differences of the position where the technique's tangents are the geometry's
// derivatives (gregory_acc, acc without tangent patches).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/mesh/obj_loader.h"
#include "core/tess/tessellator.h"
#include "reference/limit_surface.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// All quads with extraordinary vertices; a smooth boundary; quads and triangles (gregory_acc
// triangle patches); N-gons (gregory_acc refines once); triangles only (pn, phong).
const std::vector<std::string> kAssets = {"opensubdiv/catmark_xord_interior.obj",
                                          "opensubdiv/catmark_edgecorner.obj",
                                          "opensubdiv/catmark_pyramid.obj",
                                          "opensubdiv/catmark_nonquads.obj",
                                          "opensubdiv/catmark_torus.obj",
                                          "opensubdiv/loop_icosahedron.obj",
                                          "tessbench/tri_torus.obj"};

constexpr double kPositionTolerance = 1e-12;  // of the bounding-box diagonal
constexpr double kNormalTolerance = 1e-11;    // unit normals, absolute

using testing::diagonalOf;
using testing::loadAsset;
using testing::surfaceTechniques;
using testing::technique;

techniques::VariantInfo variant(const techniques::Technique& t, const std::string& name) {
  for (const techniques::VariantInfo& v : t.variants()) {
    if (v.name == name) return v;
  }
  throw std::logic_error(t.info().id + " has no variant " + name);
}

// A lattice (exact corners and edges) and the tessellator's fractional-odd points.
std::vector<std::vector<techniques::DomainCoord>> patterns(techniques::PatchDomain domain) {
  tess::Levels levels;
  levels.outer = {5.3f, 5.3f, 5.3f, 5.3f};
  levels.inner = {5.3f, 5.3f};
  const tess::Tessellation t = tess::tessellate(
      domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle,
      tess::Spacing::kFractionalOdd, levels);
  std::vector<techniques::DomainCoord> tessellator;
  for (const tess::DomainPoint& d : t.points) tessellator.push_back({d[0], d[1], d[2]});
  return {techniques::latticeCoords(domain, 7), tessellator};
}

struct Coverage {
  size_t batched_patches = 0, triangle_patches = 0, default_patches = 0;
};

// Every point of every patch of `surface` through evaluateBatch against evaluate().
void expectBatchEqualsPerPoint(const techniques::SurfacePatches& surface, const std::string& what,
                               Coverage& coverage) {
  const double tolerance = kPositionTolerance * diagonalOf(surface.controlMesh());
  for (techniques::PatchDomain domain :
       {techniques::PatchDomain::kQuad, techniques::PatchDomain::kTriangle}) {
    for (const std::vector<techniques::DomainCoord>& coords : patterns(domain)) {
      const auto pattern =
          surface.makeBatchPattern(domain, coords, techniques::BatchOutput::kWithNormals);
      techniques::BatchPoints out;
      for (size_t p = 0; p < surface.patchCount(); ++p) {
        if (surface.patchDomain(p) != domain) continue;
        surface.evaluateBatch(p, *pattern, out);
        ASSERT_EQ(out.count, coords.size()) << what;
        ASSERT_TRUE(out.has_normals) << what;
        (out.has_derivatives ? coverage.batched_patches : coverage.default_patches)++;
        if (domain == techniques::PatchDomain::kTriangle && out.has_derivatives)
          ++coverage.triangle_patches;
        double worst_position = 0, worst_normal = 0, worst_cross = 0;
        for (size_t i = 0; i < coords.size(); ++i) {
          const techniques::SurfacePoint expected = surface.evaluate(p, coords[i]);
          worst_position =
              std::max(worst_position,
                       length(techniques::BatchPoints::at(out.position, i) - expected.position));
          worst_normal = std::max(
              worst_normal, length(techniques::BatchPoints::at(out.normal, i) - expected.normal));
          if (out.has_derivatives) {
            const mesh::Vec3d n = normalize(cross(techniques::BatchPoints::at(out.du, i),
                                                  techniques::BatchPoints::at(out.dv, i)));
            worst_cross = std::max(worst_cross, length(n - expected.normal));
          }
        }
        EXPECT_LE(worst_position, tolerance) << what << " patch " << p;
        EXPECT_LE(worst_normal, kNormalTolerance) << what << " patch " << p;
        EXPECT_LE(worst_cross, kNormalTolerance) << what << " patch " << p << ": du x dv";
      }
    }
  }
}

TEST(BatchEval, EqualsPerPointEvaluateForEveryTechniqueAndVariant) {
  Coverage coverage;
  for (const techniques::Technique* t : surfaceTechniques()) {
    for (const std::string& name : kAssets) {
      const mesh::Mesh mesh = loadAsset(name);
      if (!t->checkSupport(mesh).empty()) continue;
      for (const techniques::VariantInfo& v : t->variants()) {
        expectBatchEqualsPerPoint(*techniques::buildSurface(*t, mesh, v),
                                  t->info().id + "/" + v.name + " on " + name, coverage);
      }
    }
  }
  std::printf("batched patches %zu (triangles %zu), point-by-point default %zu\n",
              coverage.batched_patches, coverage.triangle_patches, coverage.default_patches);
  EXPECT_GT(coverage.batched_patches, 1000u);
  EXPECT_GT(coverage.triangle_patches, 10u);
  EXPECT_GT(coverage.default_patches, 100u);  // pn_triangles and phong keep the default
}

// The position alone (BatchOutput::kPositions, the screen-space error's evaluation) is the
// full evaluation's position bit for bit: evaluatePosition against evaluate(), and the batch
// of positions against the batch with derivatives, so the adaptivity figures do not move.
// The control: coordinates 1e-9 off do move positions (the check sees a change).
TEST(BatchEval, PositionsAloneEqualTheFullEvaluationBitForBit) {
  size_t points = 0, moved_by_control = 0;
  for (const techniques::Technique* t : surfaceTechniques()) {
    for (const std::string& name : kAssets) {
      const mesh::Mesh mesh = loadAsset(name);
      if (!t->checkSupport(mesh).empty()) continue;
      for (const techniques::VariantInfo& v : t->variants()) {
        const auto surface = techniques::buildSurface(*t, mesh, v);
        const std::string what = t->info().id + "/" + v.name + " on " + name;
        for (techniques::PatchDomain domain :
             {techniques::PatchDomain::kQuad, techniques::PatchDomain::kTriangle}) {
          const std::vector<techniques::DomainCoord> coords = patterns(domain).back();
          std::vector<techniques::DomainCoord> nudged = coords;
          for (techniques::DomainCoord& c : nudged) c[0] += 1e-9;
          const auto positions =
              surface->makeBatchPattern(domain, coords, techniques::BatchOutput::kPositions);
          const auto full = surface->makeBatchPattern(
              domain, coords, techniques::BatchOutput::kPositionAndDerivatives);
          techniques::BatchPoints alone, with;
          for (size_t p = 0; p < surface->patchCount(); ++p) {
            if (surface->patchDomain(p) != domain) continue;
            surface->evaluateBatch(p, *positions, alone);
            surface->evaluateBatch(p, *full, with);
            for (size_t i = 0; i < coords.size(); ++i, ++points) {
              const mesh::Vec3d a = techniques::BatchPoints::at(alone.position, i);
              ASSERT_EQ(a, techniques::BatchPoints::at(with.position, i)) << what << " patch " << p;
              ASSERT_EQ(surface->evaluatePosition(p, coords[i]),
                        surface->evaluate(p, coords[i]).position)
                  << what << " patch " << p;
              if (surface->evaluatePosition(p, nudged[i]) != a) ++moved_by_control;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(points, 10000u);
  EXPECT_GT(moved_by_control, points / 4);  // the check can see a small change
}

TEST(BatchEval, ThePositionAndDerivativeOutputLeavesNormalsOut) {
  const mesh::Mesh mesh = loadAsset("opensubdiv/catmark_xord_interior.obj");
  for (const char* id : {"acc", "gregory_acc"}) {
    const techniques::BuiltSurface surface =
        techniques::buildSurface(technique(id), mesh, technique(id).variants()[0]);
    const auto pattern =
        surface->makeBatchPattern(techniques::PatchDomain::kQuad,
                                  techniques::latticeCoords(techniques::PatchDomain::kQuad, 4),
                                  techniques::BatchOutput::kPositionAndDerivatives);
    techniques::BatchPoints out;
    surface->evaluateBatch(0, *pattern, out);
    EXPECT_TRUE(out.has_derivatives) << id;
    EXPECT_FALSE(out.has_normals) << id;
    EXPECT_GT(pattern->multiplyAddsPerPoint(), 100.0) << id;
  }
}

// A pattern the technique did not make goes point by point; a pattern of the other domain
// is refused.
TEST(BatchEval, ForeignPatternsFallBackAndWrongDomainsThrow) {
  const mesh::Mesh mesh = loadAsset("opensubdiv/catmark_pyramid.obj");
  const techniques::BuiltSurface surface = techniques::buildSurface(
      technique("gregory_acc"), mesh, technique("gregory_acc").variants()[0]);
  const std::vector<techniques::DomainCoord> coords =
      techniques::latticeCoords(techniques::PatchDomain::kQuad, 3);
  const techniques::BatchPattern plain(techniques::PatchDomain::kQuad, coords,
                                       techniques::BatchOutput::kPositionAndDerivatives);
  size_t quad = 0, triangle = 0;
  while (surface->patchDomain(quad) != techniques::PatchDomain::kQuad) ++quad;
  while (surface->patchDomain(triangle) != techniques::PatchDomain::kTriangle) ++triangle;
  techniques::BatchPoints out;
  surface->evaluateBatch(quad, plain, out);
  EXPECT_FALSE(out.has_derivatives);
  for (size_t i = 0; i < coords.size(); ++i) {
    EXPECT_EQ(techniques::BatchPoints::at(out.position, i),
              surface->evaluate(quad, coords[i]).position);
  }
  EXPECT_THROW(surface->evaluateBatch(triangle, plain, out), std::invalid_argument);
  const auto own = surface->makeBatchPattern(techniques::PatchDomain::kQuad, coords,
                                             techniques::BatchOutput::kWithNormals);
  EXPECT_THROW(surface->evaluateBatch(triangle, *own, out), std::invalid_argument);
}

// Oracle: Bfr (ApproxLevel 10) derivatives on regular faces, where both techniques are the
// bicubic B-spline patch; 1e-12 of the diagonal per unit of u or v.
TEST(BatchEval, DerivativesEqualTheBfrLimitOnRegularFaces) {
  size_t faces = 0;
  for (const char* id : {"acc", "gregory_acc"}) {
    for (const char* name : {"opensubdiv/catmark_xord_interior.obj",
                             "opensubdiv/catmark_edgecorner.obj", "opensubdiv/catmark_torus.obj"}) {
      const mesh::Mesh mesh = loadAsset(name);
      if (!technique(id).checkSupport(mesh).empty()) continue;
      const techniques::BuiltSurface surface =
          techniques::buildSurface(technique(id), mesh, technique(id).variants()[0]);
      const ref::LimitSurface limit(surface->controlMesh(), osd::Scheme::kCatmullClark);
      const double tolerance = 1e-12 * diagonalOf(mesh);
      const std::vector<techniques::DomainCoord> coords =
          techniques::latticeCoords(techniques::PatchDomain::kQuad, 6);
      const auto pattern = surface->makeBatchPattern(
          techniques::PatchDomain::kQuad, coords, techniques::BatchOutput::kPositionAndDerivatives);
      techniques::BatchPoints out;
      for (size_t p = 0; p < surface->patchCount(); ++p) {
        if (!limit.isRegular(surface->sourceFace(p))) continue;
        ++faces;
        surface->evaluateBatch(p, *pattern, out);
        const ref::LimitFace face = limit.face(surface->sourceFace(p));
        for (size_t i = 0; i < coords.size(); ++i) {
          const ref::LimitPoint exact = face.evaluate(coords[i][0], coords[i][1]);
          EXPECT_LE(length(techniques::BatchPoints::at(out.position, i) - exact.position),
                    tolerance)
              << id << " " << name << " patch " << p;
          EXPECT_LE(length(techniques::BatchPoints::at(out.du, i) - exact.du), tolerance)
              << id << " " << name << " patch " << p;
          EXPECT_LE(length(techniques::BatchPoints::at(out.dv, i) - exact.dv), tolerance)
              << id << " " << name << " patch " << p;
        }
      }
    }
  }
  EXPECT_GT(faces, 50u);
}

// Oracle: central differences of evaluate()'s position (step 1e-5, error ~1e-10 of the
// patch size) at interior points, on every patch, where the technique's tangents are the
// derivatives of its position: gregory_acc (quads and triangles) and acc's no_tangent.
TEST(BatchEval, DerivativesAreFiniteDifferencesOfThePosition) {
  const double h = 1e-5;
  size_t triangles = 0;
  for (const auto& [id, variant_name] :
       std::vector<std::pair<std::string, std::string>>{{"gregory_acc", "asymmetric"},
                                                        {"gregory_acc", "edge_symmetric"},
                                                        {"acc", "no_tangent"}}) {
    for (const char* name :
         {"opensubdiv/catmark_xord_interior.obj", "opensubdiv/catmark_pyramid.obj",
          "opensubdiv/catmark_edgecorner.obj"}) {
      const mesh::Mesh mesh = loadAsset(name);
      const techniques::Technique& t = technique(id);
      if (!t.checkSupport(mesh).empty()) continue;
      const techniques::BuiltSurface surface =
          techniques::buildSurface(t, mesh, variant(t, variant_name));
      const double tolerance = 1e-7 * diagonalOf(mesh);
      for (techniques::PatchDomain domain :
           {techniques::PatchDomain::kQuad, techniques::PatchDomain::kTriangle}) {
        std::vector<techniques::DomainCoord>
            coords;  // the lattice's points off the domain boundary
        for (const techniques::DomainCoord& d : techniques::latticeCoords(domain, 6)) {
          const bool inside = domain == techniques::PatchDomain::kQuad
                                  ? d[0] > 0 && d[0] < 1 && d[1] > 0 && d[1] < 1
                                  : d[0] > 0 && d[1] > 0 && d[2] > 0;
          if (inside) coords.push_back(d);
        }
        const auto pattern = surface->makeBatchPattern(
            domain, coords, techniques::BatchOutput::kPositionAndDerivatives);
        techniques::BatchPoints out;
        for (size_t p = 0; p < surface->patchCount(); ++p) {
          if (surface->patchDomain(p) != domain) continue;
          surface->evaluateBatch(p, *pattern, out);
          ASSERT_TRUE(out.has_derivatives);
          if (domain == techniques::PatchDomain::kTriangle) ++triangles;
          for (size_t i = 0; i < coords.size(); ++i) {
            const techniques::DomainCoord& d = coords[i];
            // Quads move (u, v); triangles move weight from corner 0 to corner 1 or 2.
            const auto at = [&](double step_u, double step_v) {
              const techniques::DomainCoord moved =
                  domain == techniques::PatchDomain::kQuad
                      ? techniques::DomainCoord{d[0] + step_u, d[1] + step_v, 0}
                      : techniques::DomainCoord{d[0] - step_u - step_v, d[1] + step_u,
                                                d[2] + step_v};
              return surface->evaluate(p, moved).position;
            };
            const mesh::Vec3d du = (at(h, 0) - at(-h, 0)) * (0.5 / h);
            const mesh::Vec3d dv = (at(0, h) - at(0, -h)) * (0.5 / h);
            EXPECT_LE(length(techniques::BatchPoints::at(out.du, i) - du), tolerance)
                << id << "/" << variant_name << " " << name << " patch " << p;
            EXPECT_LE(length(techniques::BatchPoints::at(out.dv, i) - dv), tolerance)
                << id << "/" << variant_name << " " << name << " patch " << p;
          }
        }
      }
    }
  }
  EXPECT_GT(triangles, 0u);
}

}  // namespace
}  // namespace tb
