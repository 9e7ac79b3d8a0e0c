// Oracle: topology counted by buildTopology on the original mesh, times the copies, and
// the copies' bounding boxes, which must not overlap.
#include "core/mesh/mesh_copies.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "tests/test_support.h"

namespace tb {
namespace {

TEST(MeshCopies, TopologyAndTagsRepeatOncePerCopy) {
  const mesh::Mesh mesh =
      mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_single_crease.obj"));
  ASSERT_FALSE(mesh.tags.creases.empty());
  const mesh::Topology one = mesh::buildTopology(mesh);
  for (int copies : {1, 4, 7}) {
    const mesh::Mesh many = mesh::translatedCopies(mesh, copies);
    const mesh::Topology topology = mesh::buildTopology(many);
    EXPECT_EQ(many.faceCount(), copies * mesh.faceCount());
    EXPECT_EQ(topology.edges.size(), copies * one.edges.size());
    EXPECT_EQ(topology.boundaryEdgeCount(), copies * one.boundaryEdgeCount());
    EXPECT_EQ(topology.component_count, copies * one.component_count);
    ASSERT_EQ(many.tags.creases.size(), copies * mesh.tags.creases.size());
    // The last copy's creases sit on its own edges, with the original sharpness.
    const mesh::Crease& last = many.tags.creases.back();
    EXPECT_GE(topology.findEdge(last.v0, last.v1), 0);
    EXPECT_EQ(last.sharpness, mesh.tags.creases.back().sharpness);
  }
}

// The default step (2 extents) and the scaling bench's tight one (1.125) keep every copy's
// bounding box apart; a step of one extent (copies touching) is refused.
class MeshCopiesStep : public ::testing::TestWithParam<double> {};

TEST_P(MeshCopiesStep, CopiesAreDisjointAndTheFirstKeepsItsPlace) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const int copies = 5;
  const mesh::Mesh many = mesh::translatedCopies(mesh, copies, GetParam());
  const size_t n = mesh.positions.size();
  for (size_t i = 0; i < n; ++i) EXPECT_EQ(many.positions[i].x, mesh.positions[i].x);
  std::vector<mesh::Vec3d> lo(copies, mesh::Vec3d{1e300, 1e300, 1e300}),
      hi(copies, mesh::Vec3d{-1e300, -1e300, -1e300});
  for (size_t i = 0; i < many.positions.size(); ++i) {
    const size_t c = i / n;
    for (int k = 0; k < 3; ++k) {
      lo[c][k] = std::min(lo[c][k], many.positions[i][k]);
      hi[c][k] = std::max(hi[c][k], many.positions[i][k]);
    }
  }
  for (int a = 0; a < copies; ++a) {
    for (int b = a + 1; b < copies; ++b) {
      bool separated = false;
      for (int k = 0; k < 3; ++k) separated |= hi[a][k] < lo[b][k] || hi[b][k] < lo[a][k];
      EXPECT_TRUE(separated) << "copies " << a << " and " << b << " overlap";
    }
  }
  EXPECT_THROW(mesh::translatedCopies(mesh, 0), std::invalid_argument);
  EXPECT_THROW(mesh::translatedCopies(mesh, 2, 1.0), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Steps, MeshCopiesStep, ::testing::Values(2.0, 1.125));

}  // namespace
}  // namespace tb
