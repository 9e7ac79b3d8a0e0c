// osd_adaptive (OpenSubdiv Far's feature-adaptive patch table; Nießner, Loop, Meyer & DeRose,
// ACM TOG 2012): regular patches against Bfr's exact limit, the error against the isolation
// level, creased input, refused input and determinism.
#include "techniques/osd_adaptive/osd_adaptive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "harness/measures/error/error.h"
#include "reference/limit_surface.h"
#include "reference/triangle_mesh_ref.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb::osd_adaptive {
namespace {

const techniques::Technique& technique() {
  const techniques::Technique* found =
      techniques::TechniqueRegistry::instance().find("osd_adaptive");
  if (found == nullptr) throw std::logic_error("osd_adaptive is not registered");
  return *found;
}

techniques::VariantInfo variant(int isolation, EndCap cap = EndCap::kGregoryBasis) {
  return {"test", "test", {{"isolation", double(isolation)}, {"endcap", double(int(cap))}}};
}

mesh::Mesh asset(const char* name) { return mesh::loadObjFile(testing::assetPath(name)); }

TEST(OsdAdaptive, IsRegisteredWithItsVariants) {
  const techniques::Technique& osd = technique();
  EXPECT_EQ(osd.info().family, techniques::TechniqueFamily::kSurface);
  const auto variants = osd.variants();
  ASSERT_FALSE(variants.empty());
  EXPECT_EQ(variants[0].name, "iso2_gregory");
  EXPECT_EQ(variantIsolation(variants[0]), 2);
  EXPECT_EQ(variantEndCap(variants[0]), EndCap::kGregoryBasis);
}

// Max |osd - Bfr| (world units) over a 9x9 lattice of every base face, at the samples whose
// Far patch is a regular B-spline patch (end caps left out). Best 0; the regular patches are
// the exact limit, so only rounding (~1e-15) remains. Counts the samples compared.
double maxRegularDifference(const techniques::SurfacePatches& patches,
                            const ref::LimitSurface& limit, size_t& compared) {
  double worst = 0;
  for (size_t f = 0; f < patches.patchCount(); ++f) {
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 8; ++j) {
        const double u = i / 8.0, v = j / 8.0;
        if (!isRegularAt(patches, f, u, v)) continue;
        const techniques::SurfacePoint osd = patches.evaluate(f, {u, v, 0});
        const ref::LimitPoint exact = limit.evaluate(f, u, v);
        worst = std::max(worst, length(osd.position - exact.position));
        ++compared;
      }
    }
  }
  return worst;
}

// Far truncates semi-sharp creases at the isolation level (a crease of sharpness s is exact
// only once the level reaches ceil(s)); the smallest level at which every crease and corner
// of `mesh` is exact, at least 2.
int exactCreaseLevel(const mesh::Mesh& mesh) {
  double sharpest = 0;
  for (const mesh::Crease& crease : mesh.tags.creases) {
    sharpest = std::max(sharpest, double(crease.sharpness));
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    sharpest = std::max(sharpest, double(corner.sharpness));
  }
  return std::clamp(int(std::ceil(sharpest)), 2, 10);
}

TEST(OsdAdaptive, RegularPatchesEqualBfrLimit) {
  for (const char* name : {"opensubdiv/catmark_torus.obj", "opensubdiv/catmark_cube.obj",
                           "opensubdiv/catmark_pawn.obj", "opensubdiv/catmark_cube_creases1.obj"}) {
    const mesh::Mesh mesh = asset(name);
    const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
    const int exact = exactCreaseLevel(mesh);
    for (int isolation : {exact, exact + 2}) {
      const techniques::BuiltSurface patches =
          techniques::buildSurface(technique(), mesh, variant(isolation));
      size_t compared = 0;
      const double worst = maxRegularDifference(*patches, limit, compared);
      std::printf("%s iso%d: max |osd - Bfr| on regular patches %.3g over %zu samples\n", name,
                  isolation, worst, compared);
      EXPECT_GT(compared, 0u) << name;
      EXPECT_LT(worst, 1e-12) << name << " isolation " << isolation;
    }
  }
}

// Below the crease's sharpness Far treats the rest of a semi-sharp crease as infinitely
// sharp, so the pawn's (sharpness 6) regular patches differ from Bfr there; the difference
// falls with the level.
TEST(OsdAdaptive, SemiSharpCreasesAreApproximatedBelowTheirSharpness) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_pawn.obj");
  const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
  double previous = INFINITY;
  for (int isolation : {2, 4}) {
    const techniques::BuiltSurface patches =
        techniques::buildSurface(technique(), mesh, variant(isolation));
    size_t compared = 0;
    const double worst = maxRegularDifference(*patches, limit, compared);
    std::printf("catmark_pawn iso%d: max |osd - Bfr| on regular patches %.3g\n", isolation, worst);
    EXPECT_GT(worst, 1e-9);
    EXPECT_LT(worst, previous);
    previous = worst;
  }
}

TEST(OsdAdaptive, TorusIsOneRegularPatchPerFace) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_torus.obj");
  const techniques::BuiltSurface patches = techniques::buildSurface(technique(), mesh, variant(4));
  const PatchTableCounts counts = patchTableCounts(*patches);
  EXPECT_EQ(counts.patches, mesh.faceCount());
  EXPECT_EQ(counts.regular_patches, mesh.faceCount());
  EXPECT_EQ(counts.end_caps, 0u);
}

// Parameters that land inside the end caps of every level up to 8: 0, 1 and m 2^-j, 1 - m 2^-j
// for m in {1, 1.5}, j = 1..8 (a lattice of step 1/8 only meets an end cap of level >= 3 at
// its corner, where it interpolates the limit).
std::vector<double> graded() {
  std::vector<double> values = {0, 1};
  for (int j = 1; j <= 8; ++j) {
    for (double m : {1.0, 1.5}) {
      const double x = m * std::ldexp(1.0, -j);
      if (x < 1) values.insert(values.end(), {x, 1 - x});
    }
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

// Max parametric error |osd(f, u, v) - Bfr(f, u, v)| over the graded lattice of every face,
// as a fraction of the bounding-box diagonal (best 0).
double maxParametricError(const techniques::SurfacePatches& patches,
                          const ref::LimitSurface& limit) {
  const std::vector<double> values = graded();
  const double diagonal = ref::boundingBoxDiagonal(patches.controlMesh().positions);
  double worst = 0;
  for (size_t f = 0; f < patches.patchCount(); ++f) {
    const ref::LimitFace face = limit.face(f);
    for (double u : values) {
      for (double v : values) {
        worst = std::max(worst, measures::parametricErrorAt(
                                    patches, face, osd::Scheme::kCatmullClark, f, {u, v, 0}) /
                                    diagonal);
      }
    }
  }
  return worst;
}

// Assets for the basis tests: extraordinary vertices (cube, pawn), boundaries and corners
// (edgecorner), creases (cube_creases1, single_crease).
const char* const kBasisAssets[] = {
    "opensubdiv/catmark_cube.obj", "opensubdiv/catmark_edgecorner.obj",
    "opensubdiv/catmark_cube_creases1.obj", "opensubdiv/catmark_single_crease.obj",
    "opensubdiv/catmark_pawn.obj"};

// Isolation levels 2 and 4 with Gregory basis end caps, level 2 with B-spline basis ones.
std::vector<techniques::VariantInfo> basisVariants() {
  return {variant(2), variant(4), variant(2, EndCap::kBSplineBasis)};
}

// The GPU's sub-patch search and basis (osd_basis.h) in double equal Far's PatchMap and
// EvaluateBasis<double> (the oracle, evaluate()) to rounding, regular patches with boundary
// masks and both end-cap kinds, on the graded lattice that lands inside the end caps.
// Normals too, but on Gregory basis end caps: there osd_basis.h differentiates the rational
// interior weights and Far does not (next test).
TEST(OsdAdaptive, OwnBasisEqualsFarsBasisInDouble) {
  const std::vector<double> values = graded();
  for (const char* name : kBasisAssets) {
    const mesh::Mesh mesh = asset(name);
    const double diagonal = ref::boundingBoxDiagonal(mesh.positions);
    for (const techniques::VariantInfo& info : basisVariants()) {
      const bool gregory = variantEndCap(info) == EndCap::kGregoryBasis;
      const techniques::BuiltSurface patches = techniques::buildSurface(technique(), mesh, info);
      double worst = 0, worst_normal = 0;
      size_t normals = 0;
      for (size_t f = 0; f < patches->patchCount(); ++f) {
        for (double u : values) {
          for (double v : values) {
            const techniques::SurfacePoint far = patches->evaluate(f, {u, v, 0});
            const std::optional<techniques::SurfacePoint> own = evaluateOwnBasis(*patches, f, u, v);
            ASSERT_TRUE(own.has_value());
            worst = std::max(worst, length(own->position - far.position) / diagonal);
            if (gregory && !isRegularAt(*patches, f, u, v)) continue;
            worst_normal = std::max(worst_normal, length(own->normal - far.normal));
            ++normals;
          }
        }
      }
      std::printf(
          "%s iso%d %s: own basis vs Far's, max %.3g of the diagonal; normals off "
          "Gregory end caps %.3g (%zu samples)\n",
          name, variantIsolation(info), gregory ? "gregory" : "bspline", worst, worst_normal,
          normals);
      EXPECT_LT(worst, 1e-13) << name;
      EXPECT_LT(worst_normal, 1e-9) << name;
      EXPECT_GT(normals, 0u) << name;
    }
  }
}

// On Gregory basis end caps the normal is the surface's: osd_basis.h's derivatives include
// those of the rational interior weights, so its normal equals the one from central
// differences of Far's positions (step 1e-6 of the base face: error ~1e-10). Far's
// EvaluateBasis leaves those terms out; its normals there are printed for comparison.
TEST(OsdAdaptive, GregoryEndCapNormalsAreTheSurfaceNormal) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_cube.obj");
  const techniques::BuiltSurface patches = techniques::buildSurface(technique(), mesh, variant(2));
  const double h = 1e-6;
  double worst_own = 0, worst_far = 0;
  size_t compared = 0;
  for (size_t f = 0; f < patches->patchCount(); ++f) {
    for (double u : {0.02, 0.07, 0.15, 0.85, 0.93, 0.98}) {
      for (double v : {0.03, 0.11, 0.2, 0.8, 0.89, 0.97}) {
        if (isRegularAt(*patches, f, u, v)) continue;
        const auto at = [&](double x, double y) {
          return patches->evaluate(f, {x, y, 0}).position;
        };
        const mesh::Vec3d n =
            normalize(cross(at(u + h, v) - at(u - h, v), at(u, v + h) - at(u, v - h)));
        worst_own = std::max(worst_own, length(evaluateOwnBasis(*patches, f, u, v)->normal - n));
        worst_far = std::max(worst_far, length(patches->evaluate(f, {u, v, 0}).normal - n));
        ++compared;
      }
    }
  }
  std::printf(
      "catmark_cube iso2 Gregory end caps, %zu samples: normal - central-difference "
      "normal, own basis %.3g, Far's EvaluateBasis %.3g\n",
      compared, worst_own, worst_far);
  EXPECT_GT(compared, 6u * 16);  // four corners of each face lie in end caps
  EXPECT_LT(worst_own, 1e-8);
}

// evaluateFloat (the shader's twin, float) against the double evaluations: positions
// against evaluate (Far), within 1e-5 of the bounding-box diagonal; normals against the
// same basis in double (evaluateOwnBasis; they differ from Far's on Gregory end caps).
TEST(OsdAdaptive, FloatTwinAgreesWithDoubleEvaluate) {
  const std::vector<double> values = graded();
  for (const char* name : kBasisAssets) {
    const mesh::Mesh mesh = asset(name);
    const double diagonal = ref::boundingBoxDiagonal(mesh.positions);
    for (const techniques::VariantInfo& info : basisVariants()) {
      const techniques::BuiltSurface patches = techniques::buildSurface(technique(), mesh, info);
      double worst = 0, worst_normal = 0;
      for (size_t f = 0; f < patches->patchCount(); ++f) {
        for (double u : values) {
          for (double v : values) {
            const tess::DomainPoint at{float(u), float(v), 0};
            const techniques::SurfacePointF single = patches->evaluateFloat(f, at);
            const techniques::SurfacePoint exact = patches->evaluate(f, {u, v, 0});
            worst = std::max(worst,
                             length(vecCast<double>(single.position) - exact.position) / diagonal);
            worst_normal =
                std::max(worst_normal, length(vecCast<double>(single.normal) -
                                              evaluateOwnBasis(*patches, f, u, v)->normal));
          }
        }
      }
      std::printf(
          "%s iso%d %s: evaluateFloat vs evaluate, max %.3g of the diagonal, normals "
          "%.3g\n",
          name, variantIsolation(info),
          variantEndCap(info) == EndCap::kGregoryBasis ? "gregory" : "bspline", worst,
          worst_normal);
      EXPECT_LT(worst, 1e-5) << name;
      // The pawn's small faces near its axis lose the tangents' low bits to cancellation in
      // float (1.3e-3 at isolation level 4); the other assets stay near 1e-5.
      const bool pawn = std::string(name).find("pawn") != std::string::npos;
      EXPECT_LT(worst_normal, pawn ? 5e-3 : 1e-4) << name;
    }
  }
}

// The parametric max error falls as the isolation level shrinks the end caps around the
// extraordinary vertices.
TEST(OsdAdaptive, ErrorFallsWithIsolationLevel) {
  for (const char* name : {"opensubdiv/catmark_cube.obj", "opensubdiv/catmark_toroidal_tet.obj"}) {
    const mesh::Mesh mesh = asset(name);
    const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
    for (EndCap cap : {EndCap::kGregoryBasis, EndCap::kBSplineBasis}) {
      double previous = INFINITY;
      for (int isolation : {1, 2, 3, 4, 5, 6}) {
        const techniques::BuiltSurface patches =
            techniques::buildSurface(technique(), mesh, variant(isolation, cap));
        const double error = maxParametricError(*patches, limit);
        const PatchTableCounts counts = patchTableCounts(*patches);
        std::printf("%s %s iso%d: parametric max %.3e of the diagonal; %.2f patches per face\n",
                    name, cap == EndCap::kGregoryBasis ? "gregory" : "bspline", isolation, error,
                    double(counts.patches) / double(counts.base_faces));
        EXPECT_LT(error, previous) << name << " isolation " << isolation;
        EXPECT_LT(error, 5e-2) << name;
        previous = error;
      }
    }
  }
}

// The error measure itself runs on osd_adaptive's patches (one per base face).
TEST(OsdAdaptive, ErrorMeasureRuns) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_cube.obj");
  const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
  const techniques::BuiltSurface patches = techniques::buildSurface(technique(), mesh, variant(2));
  const measures::SurfaceErrorFigures figures = measures::measureSurfaceError(*patches, limit);
  EXPECT_EQ(figures.samples, 6u * 81u);
  EXPECT_GT(figures.parametric_max, 1e-4);  // level-2 end caps: ~1.7e-3
  EXPECT_LT(figures.parametric_max, 1e-2);
}

TEST(OsdAdaptive, AcceptsCreasedAssets) {
  for (const char* name :
       {"opensubdiv/catmark_cube_creases1.obj", "opensubdiv/catmark_single_crease.obj",
        "opensubdiv/catmark_cube_corner3.obj", "opensubdiv/catmark_edgecorner.obj",
        "opensubdiv/catmark_tent_creases1.obj"}) {
    const mesh::Mesh mesh = asset(name);
    if (!technique().checkSupport(mesh).empty()) {
      ADD_FAILURE() << name << ": " << technique().checkSupport(mesh);
      continue;
    }
    const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
    const techniques::BuiltSurface patches =
        techniques::buildSurface(technique(), mesh, variant(4));
    const measures::SurfaceErrorFigures figures = measures::measureSurfaceError(*patches, limit);
    std::printf("%s iso4: parametric max %.3e\n", name, figures.parametric_max);
    EXPECT_LT(figures.parametric_max, 1e-2) << name;
    EXPECT_TRUE(std::isfinite(figures.hausdorff)) << name;
  }
}

TEST(OsdAdaptive, RefusesNonQuadMeshesWithAReason) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_nonquads.obj");
  const std::string reason = technique().checkSupport(mesh);
  EXPECT_NE(reason.find("osd_adaptive: face"), std::string::npos) << reason;
  EXPECT_THROW(techniques::buildSurface(technique(), mesh, variant(2)),
               techniques::UnsupportedInput);
}

TEST(OsdAdaptive, FloatEvaluationIsDeterministicAndCloseToDouble) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_pawn.obj");
  const techniques::BuiltSurface a = techniques::buildSurface(technique(), mesh, variant(2));
  const techniques::BuiltSurface b = techniques::buildSurface(technique(), mesh, variant(2));
  const double diagonal = ref::boundingBoxDiagonal(mesh.positions);
  double worst = 0;
  for (size_t f = 0; f < a->patchCount(); ++f) {
    for (int i = 0; i <= 4; ++i) {
      for (int j = 0; j <= 4; ++j) {
        const tess::DomainPoint at{float(i) / 4, float(j) / 4, 0};
        const techniques::SurfacePointF x = a->evaluateFloat(f, at), y = b->evaluateFloat(f, at);
        for (int k = 0; k < 3; ++k) {
          ASSERT_EQ(std::bit_cast<uint32_t>(x.position[k]), std::bit_cast<uint32_t>(y.position[k]));
        }
        const techniques::SurfacePoint d = a->evaluate(f, {double(at[0]), double(at[1]), 0});
        worst = std::max(worst, length(vecCast<double>(x.position) - d.position) / diagonal);
      }
    }
  }
  EXPECT_LT(worst, 1e-5);
  EXPECT_EQ(a->footprint(), b->footprint());
  EXPECT_GT(a->footprint().total(), 0u);
}

}  // namespace
}  // namespace tb::osd_adaptive
