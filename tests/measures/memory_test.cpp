// Oracles: Euler's formula (a closed, seamless triangle mesh has V = F/2 + 2
// after any subdivision) and hand counts for a single triangle.
#include <gtest/gtest.h>

#include <algorithm>

#include "harness/measures/memory.h"
#include "harness/mesh/obj_loader.h"
#include "harness/tess/tessellator.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

std::unique_ptr<SurfacePatches> phongPatches(const Mesh& mesh) {
  const Technique* phong = TechniqueRegistry::instance().find("phong");
  return phong->buildPatches(mesh, phong->variants()[0]);
}

TEST(Memory, ClosedSeamlessMeshObeysEuler) {
  // loop_cube has no normals in the file (computed per position); dropping its
  // UVs removes the only seams.
  Mesh mesh = loadObjFile(testing::assetPath("opensubdiv/loop_cube.obj"));
  std::fill(mesh.corner_uvs.begin(), mesh.corner_uvs.end(), -1);
  const auto patches = phongPatches(mesh);
  for (uint32_t level : kMemoryLevels) {
    const MemoryFigures m = measureMemory(*patches, level);
    EXPECT_EQ(m.plain_vertices, m.plain_triangles / 2 + 2) << "level " << level;
  }
}

TEST(Memory, SingleTriangleMatchesTheTessellatorCounts) {
  const Mesh mesh = loadObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri.obj");
  const auto patches = phongPatches(mesh);
  const MemoryFigures m = measureMemory(*patches, 8);
  EXPECT_EQ(m.plain_vertices, tess::trianglePointCount(8));
  EXPECT_EQ(m.plain_triangles, 96u);  // floor(3 * 64 / 2)
  EXPECT_EQ(m.plain_bytes, m.plain_vertices * 32 + 96u * 12);
  EXPECT_EQ(m.technique.control_mesh_bytes, 3u * 32 + 12);
  EXPECT_EQ(m.technique.patch_data_bytes, 0u);
  EXPECT_EQ(m.displacement_bytes, 9u * 10 / 2 * 2);
}

TEST(Memory, SplitNormalsDuplicateEdgePoints) {
  // catmark_cube, fan-triangulated, has a separate normal per face corner: every
  // cube edge is stored once per side, the 6 diagonals once.
  const Mesh mesh = loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const auto patches = phongPatches(mesh);
  const uint32_t n = 16;
  const MemoryFigures m = measureMemory(*patches, n);
  const uint64_t interior = tess::trianglePointCount(n) - 3 * n;
  EXPECT_EQ(m.plain_vertices, 24 + (24 + 6) * (n - 1) + 12 * interior);
  // Plain bytes grow with the level; the technique's own data does not.
  EXPECT_GT(measureMemory(*patches, 64).plain_bytes, 15 * measureMemory(*patches, 16).plain_bytes);
  EXPECT_EQ(measureMemory(*patches, 64).technique.total(), m.technique.total());
}

}  // namespace
}  // namespace tb
