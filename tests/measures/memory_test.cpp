// Oracles: Euler's formula (a closed, seamless triangle mesh has V = F/2 + 2
// after any subdivision), hand counts for a single triangle, the closed-form counts
// against the mesh actually built, meshoptimizer's decoders for the compressed
// baseline, and a second run for determinism.
#include "harness/measures/memory/memory.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/mesh/mesh_copies.h"
#include "core/mesh/obj_loader.h"
#include "core/tess/tessellator.h"
#include "harness/results/results_json.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

techniques::BuiltSurface phongPatches(const mesh::Mesh& mesh) {
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  return techniques::buildSurface(*phong, mesh, phong->variants()[0]);
}

TEST(Memory, ClosedSeamlessMeshObeysEuler) {
  // loop_cube has no normals in the file (computed per position); dropping its
  // UVs removes the only seams.
  mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_cube.obj"));
  std::fill(mesh.corner_uvs.begin(), mesh.corner_uvs.end(), -1);
  const auto patches = phongPatches(mesh);
  for (uint32_t level : measures::kMemoryLevels) {
    const measures::MemoryFigures m = measures::measureMemory(*patches, level);
    EXPECT_EQ(m.plain_vertices, m.plain_triangles / 2 + 2) << "level " << level;
  }
}

TEST(Memory, SingleTriangleMatchesTheTessellatorCounts) {
  const mesh::Mesh mesh = mesh::loadObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri.obj");
  const auto patches = phongPatches(mesh);
  const measures::MemoryFigures m = measures::measureMemory(*patches, 8);
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
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  const auto patches = phongPatches(mesh);
  const uint32_t n = 16;
  const measures::MemoryFigures m = measures::measureMemory(*patches, n);
  const uint64_t interior = tess::trianglePointCount(n) - 3 * n;
  EXPECT_EQ(m.plain_vertices, 24 + (24 + 6) * (n - 1) + 12 * interior);
  // Plain bytes grow with the level; the technique's own data does not.
  EXPECT_GT(measures::measureMemory(*patches, 64).plain_bytes,
            15 * measures::measureMemory(*patches, 16).plain_bytes);
  EXPECT_EQ(measures::measureMemory(*patches, 64).technique.total(), m.technique.total());
}

TEST(Memory, BuiltMeshHasTheClosedFormCountsAndCompressesLosslessly) {
  // catmark_cube: split normals duplicate the cube edges; loop_cube: no seams once
  // its uvs are dropped; catmark_pyramid: a quad-and-triangle mesh, fan-triangulated.
  mesh::Mesh seamless = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_cube.obj"));
  std::fill(seamless.corner_uvs.begin(), seamless.corner_uvs.end(), -1);
  const std::vector<mesh::Mesh> meshes{
      mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj")), seamless,
      mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_pyramid.obj"))};
  for (const mesh::Mesh& mesh : meshes) {
    const auto patches = phongPatches(mesh);
    for (uint32_t level : {1u, 8u, 16u}) {
      SCOPED_TRACE(mesh.source + " level " + std::to_string(level));
      const measures::MemoryFigures m = measures::measureMemory(*patches, level);
      measures::TessellatedMesh built = measures::buildTessellatedMesh(*patches, level);
      EXPECT_EQ(built.vertexCount(), m.plain_vertices);
      EXPECT_EQ(built.indices.size(), 3 * m.plain_triangles);
      EXPECT_EQ(
          built.vertexCount() * mesh::kRenderVertexBytes + built.indices.size() * mesh::kIndexBytes,
          m.plain_bytes);
      EXPECT_LT(*std::max_element(built.indices.begin(), built.indices.end()), built.vertexCount());
      const measures::CompressedMesh compressed = measures::compressMesh(&built);
      // Every vertex is referenced, so fetch optimisation keeps them all.
      EXPECT_EQ(built.vertexCount(), m.plain_vertices);
      EXPECT_TRUE(measures::decodesTo(compressed, built));
      EXPECT_LT(compressed.bytes(), m.plain_bytes);
      EXPECT_GT(compressed.bytes(), 0u);
    }
  }
}

// Oracle: compressMesh on the whole mesh (one chunk), and on each chunk built by hand
// (several); the chunks' meshes together hold every triangle once.
TEST(Memory, CompressedSizeIsTheSumOverChunksOfPatches) {
  const mesh::Mesh one = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_xord_interior.obj"));
  const auto small = phongPatches(one);
  ASSERT_LE(small->patchCount(), measures::kCompressChunkPatches);
  measures::TessellatedMesh whole = measures::buildTessellatedMesh(*small, 8);
  const measures::CompressedMesh whole_compressed = measures::compressMesh(&whole);
  const measures::CompressedSize small_size = measures::compressedSize(*small, 8);
  EXPECT_EQ(small_size.chunks, 1u);
  EXPECT_EQ(small_size.vertex_bytes, whole_compressed.vertex_data.size());
  EXPECT_EQ(small_size.index_bytes, whole_compressed.index_data.size());

  const auto large = phongPatches(mesh::translatedCopies(one, 5));
  ASSERT_GT(large->patchCount(), measures::kCompressChunkPatches);
  const mesh::RenderVertices render = mesh::buildRenderVertices(large->controlMesh());
  measures::CompressedSize by_hand;
  uint64_t triangles = 0;
  for (size_t first = 0; first < large->patchCount(); first += measures::kCompressChunkPatches) {
    measures::TessellatedMesh chunk = measures::buildTessellatedMesh(
        *large, 8, render, first,
        std::min(large->patchCount(), first + measures::kCompressChunkPatches));
    triangles += chunk.indices.size() / 3;
    const measures::CompressedMesh compressed = measures::compressMesh(&chunk);
    EXPECT_TRUE(measures::decodesTo(compressed, chunk));
    by_hand.vertex_bytes += compressed.vertex_data.size();
    by_hand.index_bytes += compressed.index_data.size();
    ++by_hand.chunks;
  }
  EXPECT_EQ(triangles, measures::measureMemory(*large, 8).plain_triangles);
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    const measures::CompressedSize size = measures::compressedSize(*large, 8);
    EXPECT_EQ(size.chunks, by_hand.chunks);
    EXPECT_EQ(size.vertex_bytes, by_hand.vertex_bytes) << threads << " threads";
    EXPECT_EQ(size.index_bytes, by_hand.index_bytes) << threads << " threads";
  }
}

// Oracle: every chunk compressed (sample_chunks = all of them) against the measure's sample of
// kCompressSampleChunks evenly spaced chunks, on the production assets (bundled shapes
// refined by OpenSubdiv, 37-80 chunks) at level 8, where building every chunk is cheap.
// The bound the measure states: 0.3 % (measured: -0.02 % and +0.12 %). The broken control, a
// sample of the first chunk alone (the pawn's base), must miss it (+0.36 %, +0.72 %), or the
// test could not tell a sample that represents the asset from one that does not.
TEST(Memory, SampledCompressedBaselineIsWithinItsBoundOfEveryChunk) {
  for (const char* name : {"production/catmark_pawn_r2", "production/tri_pawn_r2"}) {
    const mesh::Mesh mesh = suite::loadAsset(suite::resolveAsset(name));
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(mesh.allFacesOfSize(3) ? "phong" : "acc");
    const auto patches = techniques::buildSurface(*technique, mesh, technique->variants()[0]);
    const measures::CompressedSize all = measures::compressedSize(*patches, 8, SIZE_MAX);
    const measures::CompressedSize sampled = measures::compressedSize(*patches, 8);
    ASSERT_EQ(all.sampled_chunks, all.chunks) << name;
    ASSERT_EQ(sampled.sampled_chunks, measures::kCompressSampleChunks) << name;
    ASSERT_GT(all.chunks, 4 * measures::kCompressSampleChunks) << name;
    const double error = std::abs(double(sampled.bytes()) / double(all.bytes()) - 1);
    EXPECT_LT(error, 0.003) << name << ": " << sampled.bytes() << " against " << all.bytes();
    const measures::CompressedSize first_only = measures::compressedSize(*patches, 8, 1);
    const double control = std::abs(double(first_only.bytes()) / double(all.bytes()) - 1);
    EXPECT_GT(control, 0.003) << name << ": the one-chunk control is within the bound";
  }
}

TEST(Memory, CorruptedCompressedDataDoesNotDecodeToTheMesh) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const auto patches = phongPatches(mesh);
  measures::TessellatedMesh built = measures::buildTessellatedMesh(*patches, 4);
  measures::CompressedMesh compressed = measures::compressMesh(&built);
  ASSERT_TRUE(measures::decodesTo(compressed, built));
  compressed.vertex_data[compressed.vertex_data.size() / 2] ^= 0x5a;
  EXPECT_FALSE(measures::decodesTo(compressed, built));
}

TEST(Memory, VectorDisplacementIsThreeScalarMaps) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const auto patches = phongPatches(mesh);
  for (uint32_t level : measures::kMemoryLevels) {
    const measures::MemoryFigures m = measures::measureMemory(*patches, level);
    EXPECT_EQ(m.vector_displacement_bytes, 3 * m.displacement_bytes);
    EXPECT_EQ(m.technique_with_vector_displacement_bytes,
              m.technique.total() + m.vector_displacement_bytes);
    EXPECT_LT(m.plain_over_technique_vector, m.plain_over_technique);
  }
}

// Oracle: the run itself, repeated. The crack, instruction and memory figures hold no
// timings, so two runs must serialise to the same bytes.
TEST(MeasuresDeterminism, TwoRunsGiveIdenticalJson) {
  suite::SuiteSelection selection;
  selection.techniques = {techniques::TechniqueRegistry::instance().find("phong")};
  for (const char* id : {"cracks", "instructions", "memory"}) {
    const measures::Measure* measure = measures::MeasureRegistry::instance().find(id);
    ASSERT_NE(measure, nullptr) << id;
    selection.measures.push_back(measure);
  }
  selection.assets = {suite::resolveAsset("catmark_cube"), suite::resolveAsset("tri_torus")};
  results::Results first, second;
  suite::runSuite(selection, nullptr, &first);
  suite::runSuite(selection, nullptr, &second);
  ASSERT_FALSE(first.records.empty());
  EXPECT_EQ(results::serializeResults(first), results::serializeResults(second));
}

}  // namespace
}  // namespace tb
