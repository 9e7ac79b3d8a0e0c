// Oracle: the limit surface itself. Patches that return Bfr's limit have zero
// parametric error; the same patches moved by a known offset have exactly that
// error; and phong's figures on the Loop icosahedron are finite and non-zero.
#include "harness/measures/error/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

#include "core/mesh/obj_loader.h"
#include "harness/lod/reference_scheme.h"
#include "reference/limit_surface.h"
#include "techniques/registry.h"
#include "tests/measures/face_patches.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// Test double of a technique: the exact Loop limit, optionally offset.
class LimitPatches final : public testing::FacePatches {
 public:
  LimitPatches(const mesh::Mesh& mesh, mesh::Vec3d offset)
      : FacePatches(mesh), limit_(mesh, osd::Scheme::kLoop), offset_(offset) {}
  techniques::SurfacePoint evaluate(size_t p, const techniques::DomainCoord& c) const override {
    const ref::LimitPoint point = limit_.evaluate(p, c[1], c[2]);
    return {point.position + offset_, point.normal};
  }
  techniques::SurfacePointF evaluateFloat(size_t p, const tess::DomainPoint& c) const override {
    const techniques::SurfacePoint point = evaluate(p, {c[0], c[1], c[2]});
    return {vecCast<float>(point.position), vecCast<float>(point.normal)};
  }

 private:
  ref::LimitSurface limit_;
  mesh::Vec3d offset_;
};

TEST(SurfaceError, TheLimitItselfHasNoParametricError) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const LimitPatches patches(mesh, {0, 0, 0});
  const ref::LimitSurface limit(mesh, osd::Scheme::kLoop);
  const measures::SurfaceErrorFigures f = measures::measureSurfaceError(patches, limit);
  EXPECT_EQ(f.parametric_max, 0.0);
  EXPECT_LT(f.normal_max_deg, 1e-6);
  // Only the chords of the two tessellations separate them.
  EXPECT_LT(f.hausdorff, 2e-3);
  EXPECT_GT(f.samples, 0u);
  EXPECT_GT(f.samples_near_xord, 0u);  // the icosahedron's vertices have valence 5
}

TEST(SurfaceError, AKnownOffsetIsMeasuredExactly) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const ref::LimitSurface limit(mesh, osd::Scheme::kLoop);
  const double offset = 0.01;
  const LimitPatches patches(mesh, {offset, 0, 0});
  const measures::SurfaceErrorFigures f = measures::measureSurfaceError(patches, limit);
  EXPECT_NEAR(f.parametric_max * f.bbox_diagonal, offset, 1e-12);
  EXPECT_NEAR(f.parametric_rms * f.bbox_diagonal, offset, 1e-12);
  // A shifted closed surface is at most `offset` away, and somewhere a good part of it.
  EXPECT_LE(f.hausdorff * f.bbox_diagonal, offset + 2e-3 * f.bbox_diagonal);
  EXPECT_GT(f.hausdorff * f.bbox_diagonal, 0.5 * offset);
}

TEST(SurfaceError, PhongBulgesAwayFromTheShrunkenLoopLimitOfTheIcosahedron) {
  // The Loop limit of a convex control mesh lies inside its triangles, while Phong
  // tessellation bulges outwards by an amount growing with α: the distance to the
  // limit must therefore grow strictly with α (0 is the flat triangle).
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  std::map<double, double> rms_by_alpha;
  for (const techniques::VariantInfo& variant : phong->variants()) {
    if (variant.parameters.count("edge") != 0) continue;  // same α as alpha0.75
    const auto patches = techniques::buildSurface(*phong, mesh, variant);
    const ref::LimitSurface limit(patches->controlMesh(), osd::Scheme::kLoop);
    rms_by_alpha[variant.parameters.at("alpha")] =
        measures::measureSurfaceError(*patches, limit).rms_distance;
  }
  ASSERT_EQ(rms_by_alpha.size(), 4u);
  double previous = 0;
  for (const auto& [alpha, rms] : rms_by_alpha) {
    EXPECT_GT(rms, previous) << "alpha " << alpha;
    previous = rms;
  }
}

// Oracle: the full figure (every patch) against the sampled one, with the budget forced down to
// 16 patches (the feature patches and at most one run of others), on the bundled asset with
// the most regular patches (catmark_pawn: 588 quads, 1,176 triangles fan-triangulated), for a
// technique that errs at extraordinary vertices (acc) and one that errs everywhere
// (pn_triangles). The sample keeps every
// feature patch, so the sampled Hausdorff distance (the largest over the sample) equals the
// full one wherever the worst patch is a feature patch, and stays within the stated bound (at
// least 0.8 of it, never above it) elsewhere. The broken control, the same budget without the
// feature patches (runs only), must miss that bound, or the rule that keeps them would not be
// what the bound rests on.
TEST(SurfaceError, SampledHausdorffStaysWithinItsBoundOfTheFullFigure) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_pawn.obj"));
  bool control_missed = false;
  for (const char* id : {"acc", "pn_triangles"}) {
    const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
    const auto patches = techniques::buildSurface(*technique, mesh, technique->variants()[0]);
    const ref::LimitSurface limit(patches->controlMesh(),
                                  lod::referenceScheme(patches->approximates()));
    const size_t budget = 16;  // one run of regular patches at most
    const measures::SurfaceErrorFigures full =
        measures::measureSurfaceError(*patches, limit, &mesh, {SIZE_MAX, true});
    const measures::SurfaceErrorFigures sampled =
        measures::measureSurfaceError(*patches, limit, &mesh, {budget, true});
    const measures::SurfaceErrorFigures control =
        measures::measureSurfaceError(*patches, limit, &mesh, {budget, false});
    ASSERT_EQ(full.hausdorff_patches, patches->patchCount() - full.patches_without_limit);
    ASSERT_LT(sampled.hausdorff_patches, full.hausdorff_patches) << id;
    EXPECT_EQ(sampled.parametric_max, full.parametric_max) << id;
    EXPECT_LE(sampled.hausdorff, full.hausdorff * (1 + 1e-12)) << id;
    EXPECT_GE(sampled.hausdorff, 0.8 * full.hausdorff) << id;
    control_missed |= control.hausdorff < 0.8 * full.hausdorff;
    std::printf("%s: %zu of %zu patches; hausdorff full %.6g, sampled %.6g, control %.6g\n", id,
                sampled.hausdorff_patches, full.hausdorff_patches, full.hausdorff,
                sampled.hausdorff, control.hausdorff);
  }
  EXPECT_TRUE(control_missed) << "the sample without feature patches met the bound everywhere";
}

}  // namespace
}  // namespace tb
