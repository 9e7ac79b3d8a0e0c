// Oracle: the error measure's own sampling. limitParameterOf inverts the bilinear sub-face
// map measureSurfaceError samples Catmull-Clark triangles through (to 1e-12 in (s, t)), and
// parametricErrorAt taken over the measure's own lattice gives its parametric_max bit for bit
// on quad and Loop patches (the same evaluations in the same order), and to 1e-9 of it
// through sub-faces (where the parameter comes back through the inverse map).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>

#include "core/mesh/obj_loader.h"
#include "harness/measures/error/error.h"
#include "reference/limit_surface.h"
#include "reference/triangle_mesh_ref.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// Sub-face k's bilinear map, written out from error.cpp's description: corners corner k,
// the midpoint of edge k (towards corner k+1), the centroid, the midpoint of edge k-1.
techniques::DomainCoord subFacePoint(int k, double s, double t) {
  std::array<std::array<double, 3>, 4> quad{};
  quad[0][k] = 1;
  quad[1][k] = quad[1][(k + 1) % 3] = 0.5;
  quad[2] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  quad[3][k] = quad[3][(k + 2) % 3] = 0.5;
  const double w[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
  techniques::DomainCoord c{0, 0, 0};
  for (int q = 0; q < 4; ++q) {
    for (int i = 0; i < 3; ++i) c[i] += w[q] * quad[q][i];
  }
  return c;
}

TEST(LimitParameter, InvertsTheSubFaceMapOfACatmullClarkTriangle) {
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i <= 10; ++i) {
      for (int j = 0; j <= 10; ++j) {
        // Inside the sub-face: its edges s = 1 and t = 1 are shared with the neighbours.
        const double s = 0.005 + 0.099 * i, t = 0.005 + 0.099 * j;
        const measures::LimitParameter p =
            measures::limitParameterOf(techniques::PatchDomain::kTriangle,
                                       osd::Scheme::kCatmullClark, 0, 3, subFacePoint(k, s, t));
        ASSERT_EQ(p.sub_face, k) << s << " " << t;
        EXPECT_NEAR(p.u, s, 1e-12);
        EXPECT_NEAR(p.v, t, 1e-12);
      }
    }
  }
  // The corners of the sub-face.
  const measures::LimitParameter corner = measures::limitParameterOf(
      techniques::PatchDomain::kTriangle, osd::Scheme::kCatmullClark, 0, 3, {0, 1, 0});
  EXPECT_EQ(corner.sub_face, 1);
  EXPECT_EQ(corner.u, 0);
  EXPECT_EQ(corner.v, 0);
  const measures::LimitParameter centre =
      measures::limitParameterOf(techniques::PatchDomain::kTriangle, osd::Scheme::kCatmullClark, 0,
                                 3, {1.0 / 3, 1.0 / 3, 1.0 / 3});
  EXPECT_NEAR(centre.u, 1, 1e-15);
  EXPECT_NEAR(centre.v, 1, 1e-15);
}

TEST(LimitParameter, QuadsAndLoopTrianglesKeepTheirParameter) {
  const measures::LimitParameter quad = measures::limitParameterOf(
      techniques::PatchDomain::kQuad, osd::Scheme::kCatmullClark, 0, 4, {0.25, 0.75, 0});
  EXPECT_EQ(quad.sub_face, -1);
  EXPECT_EQ(quad.u, 0.25);
  EXPECT_EQ(quad.v, 0.75);
  const measures::LimitParameter loop = measures::limitParameterOf(
      techniques::PatchDomain::kTriangle, osd::Scheme::kLoop, 0, 3, {0.5, 0.125, 0.375});
  EXPECT_EQ(loop.sub_face, -1);
  EXPECT_EQ(loop.u, 0.125);
  EXPECT_EQ(loop.v, 0.375);
  EXPECT_THROW(measures::limitParameterOf(techniques::PatchDomain::kQuad, osd::Scheme::kLoop, 7, 4,
                                          {0.5, 0.5, 0}),
               std::logic_error);
  EXPECT_THROW(measures::limitParameterOf(techniques::PatchDomain::kTriangle,
                                          osd::Scheme::kCatmullClark, 7, 5, {1, 0, 0}),
               std::logic_error);
}

// Largest parametricErrorAt over the measure's lattices (error.cpp: kErrorSampleLevel on
// quads and Loop triangles; sub-face grids of kErrorSubFaceSampleLevel), over the diagonal.
double latticeErrorMax(const techniques::SurfacePatches& patches, const ref::LimitSurface& limit) {
  const osd::Scheme scheme = lod::referenceScheme(patches.approximates());
  double worst = 0;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    if (!limit.hasLimitSurface(p)) continue;
    const ref::LimitFace face = limit.face(p);
    std::vector<techniques::DomainCoord> coords;
    const bool sub_faces = patches.patchDomain(p) == techniques::PatchDomain::kTriangle &&
                           scheme == osd::Scheme::kCatmullClark;
    const int n = sub_faces ? measures::kErrorSubFaceSampleLevel : measures::kErrorSampleLevel;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const double a = double(i) / n, b = double(j) / n;
        if (sub_faces) {
          for (int k = 0; k < 3; ++k) coords.push_back(subFacePoint(k, a, b));
        } else if (patches.patchDomain(p) == techniques::PatchDomain::kQuad) {
          coords.push_back({a, b, 0});
        } else if (i + j <= n) {
          coords.push_back({1 - a - b, a, b});
        }
      }
    }
    for (const techniques::DomainCoord& c : coords) {
      worst = std::max(worst, measures::parametricErrorAt(patches, face, scheme, p, c));
    }
  }
  // Times the reciprocal, as measureSurfaceError scales its figures.
  return worst * (1 / ref::boundingBoxDiagonal(patches.controlMesh().positions));
}

measures::SurfaceErrorFigures figuresOf(const techniques::SurfacePatches& patches,
                                        const ref::LimitSurface& limit) {
  return measures::measureSurfaceError(patches, limit);
}

TEST(ParametricErrorAt, GivesTheMeasuresParametricMax) {
  struct LimitCase {
    const char* technique;
    const char* asset;
    double tolerance;  // relative to parametric_max
  };
  for (const LimitCase& c : {LimitCase{"acc", "opensubdiv/catmark_cube.obj", 0.0},
                             LimitCase{"pn_triangles", "opensubdiv/loop_cube.obj", 0.0},
                             LimitCase{"gregory_acc", "opensubdiv/catmark_pyramid.obj", 1e-9}}) {
    SCOPED_TRACE(c.technique);
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(c.technique);
    ASSERT_NE(technique, nullptr);
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(c.asset));
    const techniques::BuiltSurface patches =
        techniques::buildSurface(*technique, mesh, technique->variants().front());
    const ref::LimitSurface limit(patches->controlMesh(),
                                  lod::referenceScheme(patches->approximates()));
    const measures::SurfaceErrorFigures f = figuresOf(*patches, limit);
    ASSERT_GT(f.parametric_max, 1e-4);
    if (c.tolerance == 0) {
      EXPECT_EQ(latticeErrorMax(*patches, limit), f.parametric_max);
    } else {
      EXPECT_GT(f.patches_through_sub_faces, 0u);
      EXPECT_NEAR(latticeErrorMax(*patches, limit), f.parametric_max,
                  c.tolerance * f.parametric_max);
    }
  }
}

}  // namespace
}  // namespace tb
