// Oracle: the files' own numbers (written by tests/mesh/gltf_test_files.h or by
// scripts/make_gltf_asset.py, whose OBJ twin holds the same mesh in OBJ), the glTF 2.0
// specification's rules (node matrices, normalised integers, sparse accessors) and the
// one-line errors of docs/ARCHITECTURE.md §8.
#include "core/mesh/gltf_loader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "tests/mesh/gltf_test_files.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::GltfSpec;

mesh::Mesh loadGltfSpec(const GltfSpec& spec, const mesh::GltfLoadOptions& options = {}) {
  const std::string text = testing::gltfText(spec);
  return mesh::loadGltfBytes({reinterpret_cast<const uint8_t*>(text.data()), text.size()},
                             "test.gltf", options);
}

std::string gltfSpecError(const GltfSpec& spec) {
  return testing::gltfErrorOf(testing::gltfText(spec));
}

GltfSpec gltfWithEdit(std::function<void(nlohmann::json&)> edit) {
  GltfSpec spec;
  spec.edit = std::move(edit);
  return spec;
}

// The edges (welded position pairs) whose faces disagree on a corner's normal or uv value.
size_t attributeSeamEdges(const mesh::Mesh& m) {
  const mesh::Topology topology = mesh::buildTopology(m);
  size_t seams = 0;
  for (size_t e = 0; e < topology.edges.size(); ++e) {
    std::set<std::array<double, 5>> at_ends[2];
    for (uint32_t f : topology.facesOfEdge(e)) {
      for (uint32_t c = m.face_offsets[f]; c < m.face_offsets[f + 1]; ++c) {
        const mesh::Vec3d& n = m.normals[size_t(m.corner_normals[c])];
        const mesh::Vec2d& uv = m.uvs[size_t(m.corner_uvs[c])];
        for (int end = 0; end < 2; ++end) {
          const uint32_t v = end == 0 ? topology.edges[e].v0 : topology.edges[e].v1;
          if (m.corner_positions[c] == v) at_ends[end].insert({n.x, n.y, n.z, uv.x, uv.y});
        }
      }
    }
    seams += at_ends[0].size() > 1 || at_ends[1].size() > 1 ? 1 : 0;
  }
  return seams;
}

TEST(GltfLoader, BundledAssetEqualsItsObjTwinBitForBit) {
  const mesh::Mesh glb =
      mesh::loadGltfFile(testing::assetPath("full_suite/gltf/tri_torus_seams.glb"));
  const mesh::Mesh obj =
      mesh::loadObjFile(testing::assetPath("full_suite/gltf/tri_torus_seams_twin.obj"));
  EXPECT_EQ(glb.faceCount(), 64u);
  EXPECT_EQ(glb.positions.size(), 32u);  // the torus's 8 x 4 grid, welded
  // (8 + 1) x (4 + 1) = 45 split vertices, 5 of them in both primitives (each has its own).
  EXPECT_EQ(glb.normals.size(), 50u);
  EXPECT_EQ(glb.uvs.size(), 50u);
  EXPECT_FALSE(glb.normals_computed);
  ASSERT_EQ(glb.positions.size(), obj.positions.size());
  EXPECT_EQ(std::memcmp(glb.positions.data(), obj.positions.data(),
                        glb.positions.size() * sizeof(mesh::Vec3d)),
            0);
  ASSERT_EQ(glb.normals.size(), obj.normals.size());
  EXPECT_EQ(
      std::memcmp(glb.normals.data(), obj.normals.data(), glb.normals.size() * sizeof(mesh::Vec3d)),
      0);
  ASSERT_EQ(glb.uvs.size(), obj.uvs.size());
  EXPECT_EQ(std::memcmp(glb.uvs.data(), obj.uvs.data(), glb.uvs.size() * sizeof(mesh::Vec2d)), 0);
  EXPECT_EQ(glb.face_offsets, obj.face_offsets);
  EXPECT_EQ(glb.corner_positions, obj.corner_positions);
  EXPECT_EQ(glb.corner_normals, obj.corner_normals);
  EXPECT_EQ(glb.corner_uvs, obj.corner_uvs);
  // The ring seam crosses the tube's 4 edges, the tube seam the ring's 8.
  EXPECT_EQ(attributeSeamEdges(glb), 12u);
  EXPECT_EQ(attributeSeamEdges(obj), 12u);
}

TEST(GltfLoader, SquareWithoutNormalsGetsComputedOnes) {
  const mesh::Mesh m = loadGltfSpec({});
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.faceCount(), 2u);
  EXPECT_TRUE(m.allFacesOfSize(3));
  EXPECT_TRUE(m.normals_computed);
  EXPECT_FALSE(m.hasUvs());
}

TEST(GltfLoader, EveryIndexComponentTypeGivesTheSameMesh) {
  const mesh::Mesh reference = loadGltfSpec({});
  for (int type : {5121, 5123, 5125}) {
    GltfSpec spec;
    spec.index_type = type;
    const mesh::Mesh m = loadGltfSpec(spec);
    EXPECT_EQ(m.corner_positions, reference.corner_positions) << type;
  }
  GltfSpec unindexed;
  unindexed.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  unindexed.indices.clear();
  const mesh::Mesh m = loadGltfSpec(unindexed);
  EXPECT_EQ(m.positions.size(), 4u) << "the repeated corners weld";
  EXPECT_EQ(m.corner_positions, reference.corner_positions);
}

TEST(GltfLoader, NodeTransformsApplyDownTheHierarchy) {
  GltfSpec spec = gltfWithEdit([](nlohmann::json& g) {
    g["scenes"][0]["nodes"] = {1};
    g["nodes"] = {{{"mesh", 0}, {"scale", {2, 2, 2}}},
                  {{"children", {0}}, {"translation", {10, 0, 0}}}};
  });
  spec.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const mesh::Mesh m = loadGltfSpec(spec);
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[2].x, 12.0);  // (1, 1, 0) scaled by 2, moved by 10
  EXPECT_EQ(m.positions[2].y, 2.0);
  // Normals go through the inverse transpose: 1/2 along z, unnormalised.
  EXPECT_EQ(m.normals[0].z, 0.5);
}

TEST(GltfLoader, RotationAndMirroringKeepFacesOutward) {
  // 90 degrees about x: the square in the xy plane, normal +z, turns to normal -y.
  const double s = std::sqrt(0.5);
  GltfSpec rotated = gltfWithEdit([s](nlohmann::json& g) {
    g["nodes"][0]["rotation"] = {s, 0, 0, s};
  });
  const mesh::Mesh m = loadGltfSpec(rotated);
  const auto f = m.facePositions(0);
  const mesh::Vec3d n =
      cross(m.positions[f[1]] - m.positions[f[0]], m.positions[f[2]] - m.positions[f[0]]);
  EXPECT_NEAR(n.y, -1.0, 1e-12);
  // A negative scale mirrors: the winding is reversed, so the face normal stays outward (+z
  // mirrored in x keeps +z).
  GltfSpec mirrored = gltfWithEdit([](nlohmann::json& g) { g["nodes"][0]["scale"] = {-1, 1, 1}; });
  const mesh::Mesh mm = loadGltfSpec(mirrored);
  const auto g = mm.facePositions(0);
  const mesh::Vec3d nm =
      cross(mm.positions[g[1]] - mm.positions[g[0]], mm.positions[g[2]] - mm.positions[g[0]]);
  EXPECT_GT(nm.z, 0.0);
}

TEST(GltfLoader, NormalisedIntegerAttributesMapAsTheSpecificationSays) {
  GltfSpec spec;
  spec.uvs = {0, 0, 1, 0, 1, 1, 0, 1};
  spec.edit = [](nlohmann::json& g) {
    // The uv accessor (1) re-pointed at the index bytes read as normalised unsigned shorts.
    g["accessors"][1] = {{"bufferView", 2}, {"componentType", 5123}, {"normalized", true},
                         {"count", 4},      {"type", "VEC2"},        {"byteOffset", 0}};
  };
  const mesh::Mesh m = loadGltfSpec(spec);
  // The index bytes 0,1,2,0,2,3 as uint32: shorts 0,0, 1,0, 2,0, 0,0 -> u = c / 65535.
  ASSERT_EQ(m.uvs.size(), 4u);
  EXPECT_EQ(m.uvs[1].x, 1.0 / 65535.0);
  EXPECT_EQ(m.uvs[1].y, 1.0);  // v = 0 flipped to OBJ's 1 - v
}

TEST(GltfLoader, SparseAccessorOverridesTheNamedElements) {
  GltfSpec spec;
  spec.positions.insert(spec.positions.end(), {2, 2, 0});  // vertex 4, used by no triangle
  spec.edit = [](nlohmann::json& g) {
    // Element 2 of POSITION replaced by the bytes of vertex 4 (byte 48): the sparse index 2
    // is the uint32 at byte 8 of the index view (bytes 60.., after 5 positions).
    g["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 68}, {"byteLength", 4}});
    g["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 2}, {"componentType", 5125}}},
                                   {"values", {{"bufferView", 0}, {"byteOffset", 48}}}};
  };
  const mesh::Mesh m = loadGltfSpec(spec);
  EXPECT_EQ(m.positions[2].x, 2.0);
  EXPECT_EQ(m.positions[2].y, 2.0);
  // Control: the same file without the sparse part keeps (1, 1, 0).
  GltfSpec plain;
  plain.positions = spec.positions;
  EXPECT_EQ(loadGltfSpec(plain).positions[2].x, 1.0);
}

TEST(GltfLoader, ExactWeldAndToleranceOption) {
  GltfSpec spec;  // two triangles whose shared corners differ by 1e-7
  spec.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 1e-7f, 0, 0, 1, 1, 0, 0, 1, 0};
  spec.indices = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(loadGltfSpec(spec).positions.size(), 5u) << "exact: only bitwise-equal positions weld";
  mesh::GltfLoadOptions options;
  options.weld_tolerance = 1e-6;
  const mesh::Mesh welded = loadGltfSpec(spec, options);
  EXPECT_EQ(welded.positions.size(), 4u);
  EXPECT_EQ(welded.corner_positions[3], 0u);
  options.weld_tolerance = 1e-8;  // control: below the gap, nothing more welds
  EXPECT_EQ(loadGltfSpec(spec, options).positions.size(), 5u);
}

TEST(GltfLoader, ExternalBufferBesideTheFile) {
  const auto dir = testing::scratchDirectory("gltf_external");
  GltfSpec spec;
  std::vector<std::pair<size_t, size_t>> views;
  const std::vector<uint8_t> bytes = testing::gltfBuffer(spec, &views);
  testing::writeTextFile(dir / "square.bin", std::string(bytes.begin(), bytes.end()));
  spec.edit = [](nlohmann::json& g) { g["buffers"][0]["uri"] = "square.bin"; };
  testing::writeTextFile(dir / "square.gltf", testing::gltfText(spec));
  EXPECT_EQ(mesh::loadGltfFile((dir / "square.gltf").string()).faceCount(), 2u);
  // In memory there is no folder to read it from: refused, not read from the working folder.
  EXPECT_NE(gltfSpecError(spec).find("test.gltf"), std::string::npos);
}

TEST(GltfLoader, IsGltfPathByExtension) {
  EXPECT_TRUE(mesh::isGltfPath("a/b.glb"));
  EXPECT_TRUE(mesh::isGltfPath("B.GLTF"));
  EXPECT_FALSE(mesh::isGltfPath("b.obj"));
}

}  // namespace
}  // namespace tb
