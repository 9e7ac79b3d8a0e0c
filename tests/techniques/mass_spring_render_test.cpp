// The render-vertex update through tetrahedral barycentric coordinates (seed 003): the
// rendered mesh (the simulated quads' tessellation) follows the simulated mesh.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/obj_loader.h"
#include "techniques/mass_spring/tet_binding.h"
#include "tests/techniques/mass_spring_test_support.h"

namespace tb::mass_spring {
namespace {

// Oracle: by hand. Triangle (0,0,0), (1,0,0), (0,1,0), area 1/2, apex height 3 over the
// centroid (1/3, 1/3, 0): p3 = (1/3, 1/3, 3). A corner has weight 1 there; the apex has all
// three weights 0; the centroid has w = 1/3 each and 0 for the apex.
TEST(MassSpringRender, BarycentricWeightsMatchHandComputation) {
  const std::vector<mesh::Vec3d> rest{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const mesh::Vec3d apex = virtualApex(rest[0], rest[1], rest[2], 0.5 * 3 / 3);
  EXPECT_NEAR(apex.x, 1.0 / 3, 1e-15);
  EXPECT_NEAR(apex.y, 1.0 / 3, 1e-15);
  EXPECT_NEAR(apex.z, 3.0, 1e-15);
  const TetBinding corner = bindToTriangle(rest, 0, 1, 2, rest[1], 3);
  EXPECT_NEAR(corner.w0, 0, 1e-15);
  EXPECT_NEAR(corner.w1, 1, 1e-15);
  EXPECT_NEAR(corner.w2, 0, 1e-15);
  const TetBinding top = bindToTriangle(rest, 0, 1, 2, apex, 3);
  EXPECT_NEAR(top.w0 + top.w1 + top.w2, 0, 1e-15);
  const TetBinding centre = bindToTriangle(rest, 0, 1, 2, {1.0 / 3, 1.0 / 3, 0}, 3);
  EXPECT_NEAR(centre.w0, 1.0 / 3, 1e-15);
  EXPECT_NEAR(centre.w2, 1.0 / 3, 1e-15);
  // Off the surface: (0.2, 0.2, 1) is 1/3 of the way to the apex from (0.2 - ..): check by
  // reconstruction.
  const mesh::Vec3d q{0.2, 0.3, 1.0};
  const TetBinding off = bindToTriangle(rest, 0, 1, 2, q, 3);
  const mesh::Vec3d back = drawVertex(off, rest);
  EXPECT_NEAR(length(back - q), 0, 1e-14);
}

mesh::Vec3d rigid(const mesh::Vec3d& p) {
  // A rotation of 0.7 rad about (1, 2, 2) / 3 and a translation.
  const mesh::Vec3d axis{1.0 / 3, 2.0 / 3, 2.0 / 3};
  const double c = std::cos(0.7), s = std::sin(0.7);
  return c * p + s * cross(axis, p) + (1 - c) * dot(axis, p) * axis + mesh::Vec3d{0.5, -2, 1};
}

// Oracle: the render vertices at rest (exact reproduction) and under a rigid motion of the
// simulated mesh (they move rigidly with it: the constant-volume apex keeps its height).
TEST(MassSpringRender, RenderMeshFollowsTheSimulatedMesh) {
  auto instance = tb::testing::buildMassSpring(tb::testing::massSpringScenario(), "jacobi");
  const MassSpringSimulation& simulation = tb::testing::massSpringOf(*instance);
  const RenderMesh& render = simulation.renderMesh();
  ASSERT_GT(render.bindings.size(), 588u * 9);  // level 3: 16 points per quad
  const mesh::Mesh skin = mesh::loadObjFile(tb::testing::assetPath("opensubdiv/catmark_pawn.obj"));
  // At rest (the simulation's start) every render vertex is where it was tessellated.
  const std::vector<mesh::Vec3d> at_rest = simulation.renderPositions();
  double worst = 0;
  for (size_t i = 0; i < at_rest.size(); ++i) {
    worst = std::max(worst, length(at_rest[i] - render.rest_positions[i]));
  }
  EXPECT_LT(worst, 1e-6);  // the simulated positions are float; the pawn spans ~0.5 m
  // The float twin of the GPU's render pass agrees with the double DrawVertex.
  const std::vector<mesh::Vec3f> at_rest_float = simulation.renderPositionsFloat();
  double worst_float = 0;
  for (size_t i = 0; i < at_rest.size(); ++i) {
    worst_float = std::max(
        worst_float, length(vecCast<double>(at_rest_float[i]) + simulation.origin() - at_rest[i]));
  }
  EXPECT_LT(worst_float, 1e-6);
  std::vector<mesh::Vec3d> moved = skin.positions;
  for (mesh::Vec3d& p : moved) p = rigid(p);
  worst = 0;
  double worst_fixed_apex = 0;
  for (size_t i = 0; i < render.bindings.size(); ++i) {
    const TetBinding& b = render.bindings[i];
    // The rendered mesh itself, and the same points lifted off the simulated surface by
    // 0.3 mean spring lengths (a rendered mesh that differs from the simulated one).
    const mesh::Vec3d normal = normalize(cross(skin.positions[b.v1] - skin.positions[b.v0],
                                               skin.positions[b.v2] - skin.positions[b.v0]));
    const mesh::Vec3d lifted = render.rest_positions[i] + 0.3 * simulation.lengthScale() * normal;
    const TetBinding lifted_binding =
        bindToTriangle(skin.positions, b.v0, b.v1, b.v2, lifted, simulation.lengthScale());
    worst = std::max(worst, length(drawVertex(b, moved) - rigid(render.rest_positions[i])));
    worst = std::max(worst, length(drawVertex(lifted_binding, moved) - rigid(lifted)));
    // Broken variant: an apex left where it was at rest does not follow the motion.
    const TetBinding& l = lifted_binding;
    const mesh::Vec3d apex =
        virtualApex(skin.positions[l.v0], skin.positions[l.v1], skin.positions[l.v2], l.volume);
    const mesh::Vec3d fixed_apex = l.w0 * moved[l.v0] + l.w1 * moved[l.v1] + l.w2 * moved[l.v2] +
                                   (1 - l.w0 - l.w1 - l.w2) * apex;
    worst_fixed_apex = std::max(worst_fixed_apex, length(fixed_apex - rigid(lifted)));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(worst_fixed_apex, 1e-3);
}

}  // namespace
}  // namespace tb::mass_spring
