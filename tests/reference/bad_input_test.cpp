// Oracle: docs/ARCHITECTURE.md §8 — every rejection is an InputError naming the file,
// the element (option, face, vertex) and the rule.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "core/mesh/input_error.h"
#include "reference/embree_subdivision.h"
#include "reference/hausdorff.h"
#include "reference/limit_surface.h"
#include "reference/limit_tessellation.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

using testing::loadShape;

// Runs `action`, expects an InputError and returns it (an empty one when none came).
mesh::InputError expectInputError(const std::function<void()>& action) {
  try {
    action();
  } catch (const mesh::InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError thrown";
  return mesh::InputError("", "", "");
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(BadInput, ApproxLevelAboveTenIsRejected) {
  const mesh::Mesh mesh = loadShape("catmark_cube.obj");
  LimitOptions options;
  options.approx_level_smooth = 11;
  mesh::InputError error =
      expectInputError([&] { LimitSurface(mesh, osd::Scheme::kCatmullClark, options); });
  EXPECT_EQ(error.element(), "option 'approx_level_smooth'");
  EXPECT_TRUE(contains(error.file(), "catmark_cube.obj"));
  EXPECT_TRUE(contains(error.rule(), "11"));

  options = {};
  options.approx_level_sharp = 11;
  error = expectInputError([&] { LimitSurface(mesh, osd::Scheme::kCatmullClark, options); });
  EXPECT_EQ(error.element(), "option 'approx_level_sharp'");

  options = {};
  options.approx_level_smooth = 0;
  error = expectInputError([&] { LimitSurface(mesh, osd::Scheme::kCatmullClark, options); });
  EXPECT_EQ(error.element(), "option 'approx_level_smooth'");

  options.approx_level_smooth = kMaxApproxLevel;  // the largest accepted level
  EXPECT_NO_THROW(LimitSurface(mesh, osd::Scheme::kCatmullClark, options));
}

TEST(BadInput, FaceIndexOutOfRangeNamesTheFace) {
  const LimitSurface surface(loadShape("catmark_cube.obj"), osd::Scheme::kCatmullClark);
  for (const auto& call : std::vector<std::function<void()>>{
           [&] { surface.evaluate(6, 0.5, 0.5); }, [&] { surface.face(6); },
           [&] { surface.hasLimitSurface(6); }, [&] { surface.isRegular(6); }}) {
    const mesh::InputError error = expectInputError(call);
    EXPECT_EQ(error.element(), "face 6");
    EXPECT_TRUE(contains(error.rule(), "out of range"));
  }
  const EmbreeSubdivision embree(loadShape("catmark_cube.obj"));
  EXPECT_EQ(expectInputError([&] { embree.evaluate(17, 0, 0); }).element(), "face 17");
}

TEST(BadInput, LoopSurfaceFromQuadMeshIsRejected) {
  const mesh::InputError error =
      expectInputError([] { LimitSurface(loadShape("catmark_cube.obj"), osd::Scheme::kLoop); });
  EXPECT_TRUE(contains(error.element(), "face 0"));
  EXPECT_TRUE(contains(error.rule(), "Loop"));
  EXPECT_TRUE(contains(error.rule(), "4 corners"));
}

TEST(BadInput, HoleFaceHasNoLimitToEvaluate) {
  mesh::Mesh mesh = loadShape("catmark_torus.obj");
  mesh.tags.holes = {2};
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  const mesh::InputError error = expectInputError([&] { surface.evaluate(2, 0.5, 0.5); });
  EXPECT_TRUE(contains(error.element(), "face 2"));
  EXPECT_TRUE(contains(error.rule(), "hole"));
}

TEST(BadInput, BoundaryFaceWithoutInterpolationHasNoLimit) {
  mesh::Mesh mesh = loadShape("catmark_edgecorner.obj");
  mesh.tags.boundary = mesh::BoundaryInterpolation::kNone;
  const LimitSurface surface(mesh, osd::Scheme::kCatmullClark);
  size_t without = 0;
  for (size_t f = 0; f < surface.faceCount(); ++f) {
    if (surface.hasLimitSurface(f)) continue;
    ++without;
    EXPECT_TRUE(contains(expectInputError([&] { surface.face(f); }).rule(), "interpolateboundary"));
  }
  EXPECT_GT(without, 0u);
}

TEST(BadInput, ParameterOutsideTheFaceDomain) {
  const LimitSurface quads(loadShape("catmark_cube.obj"), osd::Scheme::kCatmullClark);
  EXPECT_TRUE(contains(expectInputError([&] { quads.evaluate(0, 1.5, 0.5); }).rule(), "outside"));
  const LimitSurface loop(loadShape("loop_icosahedron.obj"), osd::Scheme::kLoop);
  EXPECT_TRUE(contains(expectInputError([&] { loop.evaluate(0, 0.7, 0.7); }).rule(), "outside"));
  EXPECT_NO_THROW(loop.evaluate(0, 0.5, 0.5));
}

TEST(BadInput, NonFiniteCoordinateIsRejected) {
  mesh::Mesh mesh = loadShape("catmark_cube.obj");
  mesh.positions[3].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expectInputError([&] { LimitSurface(mesh, osd::Scheme::kCatmullClark); }).element(),
            "vertex 3");
  EXPECT_EQ(expectInputError([&] { EmbreeSubdivision{mesh}; }).element(), "vertex 3");
}

TEST(BadInput, MeshWithoutFacesIsRejected) {
  mesh::Mesh mesh;
  mesh.source = "empty.obj";
  mesh.positions = {{0, 0, 0}};
  const mesh::InputError error =
      expectInputError([&] { LimitSurface(mesh, osd::Scheme::kCatmullClark); });
  EXPECT_EQ(error.file(), "empty.obj");
  EXPECT_TRUE(contains(error.rule(), "no faces"));
}

// A fan of 65,536 triangles gives its centre a valence above Far's limit (65,535):
// the reason OpenSubdiv prints goes into the InputError.
TEST(BadInput, TopologyOpenSubdivRejectsCarriesItsReason) {
  constexpr uint32_t kFan = 65536;
  mesh::Mesh mesh;
  mesh.source = "fan.obj";
  mesh.positions.push_back({0, 0, 0});
  for (uint32_t i = 0; i < kFan; ++i) {
    mesh.positions.push_back({std::cos(i * 0.0001), std::sin(i * 0.0001), 0});
  }
  for (uint32_t i = 0; i < kFan; ++i) {
    const uint32_t corners[3] = {0, 1 + i, 1 + (i + 1) % kFan};
    mesh.addFace(corners, {}, {}, 0);
  }
  const mesh::InputError error = expectInputError([&] { LimitSurface(mesh, osd::Scheme::kLoop); });
  EXPECT_EQ(error.element(), "mesh topology");
  EXPECT_TRUE(contains(error.rule(), "valence 65536")) << error.rule();
}

TEST(BadInput, FaceTooLargeForEmbree) {
  std::string text;
  for (int i = 0; i < 16; ++i) {
    text += "v " + std::to_string(std::cos(i * 0.3927)) + " " +
            std::to_string(std::sin(i * 0.3927)) + " 0\n";
  }
  text += "f";
  for (int i = 1; i <= 16; ++i) text.append(" ").append(std::to_string(i));
  const mesh::Mesh mesh = mesh::loadObjText(text + "\n", "hexadecagon.obj");
  EXPECT_TRUE(contains(expectInputError([&] { EmbreeSubdivision{mesh}; }).rule(), "15"));
  EXPECT_TRUE(contains(crossCheckIneligibility(mesh, osd::Scheme::kCatmullClark), "15"));
  EXPECT_NO_THROW(LimitSurface(mesh, osd::Scheme::kCatmullClark));  // Bfr takes any N
}

TEST(BadInput, TessellationRateAndLatticeLevelOutOfRange) {
  const LimitSurface surface(loadShape("catmark_cube.obj"), osd::Scheme::kCatmullClark);
  EXPECT_EQ(expectInputError([&] { tessellateLimit(surface, 0); }).element(), "option 'rate'");
  EXPECT_EQ(expectInputError([&] { tessellateLimit(surface, kMaxTessellationRate + 1); }).element(),
            "option 'rate'");
  const LimitTessellation t = tessellateLimit(surface, 1);
  EXPECT_EQ(expectInputError([&] { hausdorff(t.view(), t.view(), 0); }).element(),
            "option 'lattice_level'");
}

}  // namespace
}  // namespace tb::ref
