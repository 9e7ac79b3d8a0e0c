// Oracle: the OBJ files' own text (counts and tags read by eye from the bundled
// OpenSubdiv shapes) and the error rules of docs/ARCHITECTURE.md §8.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "tests/test_support.h"

namespace tb {
namespace {

std::string errorOf(const std::string& text) {
  try {
    loadObjText(text, "test.obj");
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ObjLoader, LoadsCubeCountsAndSplitNormals) {
  const Mesh mesh = loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  EXPECT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.faceCount(), 6u);
  EXPECT_TRUE(mesh.allFacesOfSize(4));
  EXPECT_EQ(mesh.normals.size(), 24u);
  EXPECT_EQ(mesh.uvs.size(), 14u);
  EXPECT_FALSE(mesh.normals_computed);
  EXPECT_EQ(mesh.face_lines[0] > 0, true);
}

TEST(ObjLoader, ReadsCreaseTagsAndBoundaryMapping) {
  const Mesh mesh = loadObjFile(testing::assetPath("opensubdiv/catmark_cube_creases1.obj"));
  ASSERT_EQ(mesh.tags.creases.size(), 12u);
  EXPECT_EQ(mesh.tags.creases[0].v0, 0u);
  EXPECT_EQ(mesh.tags.creases[0].v1, 1u);
  // tinyobjloader reads tag values as float.
  EXPECT_EQ(mesh.tags.creases[0].sharpness, 5.0);
  EXPECT_EQ(mesh.tags.creases[11].sharpness, double(0.1f));
  // OBJ value 2 is edge-only (the reverse of Sdc's enum order).
  EXPECT_EQ(mesh.tags.boundary, BoundaryInterpolation::kEdgeOnly);
  EXPECT_TRUE(mesh.tags.boundary_from_tag);
}

TEST(ObjLoader, BoundaryTagOneIsEdgeAndCorner) {
  const Mesh mesh = loadObjText(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt interpolateboundary 1/0/0 1\n", "tag.obj");
  EXPECT_EQ(mesh.tags.boundary, BoundaryInterpolation::kEdgeAndCorner);
}

TEST(ObjLoader, ReadsCornerTags) {
  const Mesh mesh = loadObjFile(testing::assetPath("opensubdiv/catmark_cube_corner3.obj"));
  ASSERT_FALSE(mesh.tags.corners.empty());
  EXPECT_GT(mesh.tags.corners[0].sharpness, 0.0);
}

TEST(ObjLoader, ComputesNormalsWhenAbsent) {
  const Mesh mesh = loadObjFile(testing::assetPath("opensubdiv/loop_cube.obj"));
  EXPECT_TRUE(mesh.normals_computed);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const Vec3d& n : mesh.normals) EXPECT_NEAR(length(n), 1.0, 1e-12);
}

TEST(ObjLoader, AngleWeightedNormalOfCubeCornerIsTheDiagonal) {
  // Three faces meet at (1,1,1) each with a 90-degree corner: equal weights.
  const std::string cube =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const Mesh mesh = loadObjText(cube, "cube.obj");
  const Vec3d n = mesh.normals[6];
  const double k = 1.0 / std::sqrt(3.0);
  EXPECT_NEAR(n.x, k, 1e-12);
  EXPECT_NEAR(n.y, k, 1e-12);
  EXPECT_NEAR(n.z, k, 1e-12);
}

TEST(ObjLoader, NegativeIndicesAreRelative) {
  const Mesh mesh = loadObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", "rel.obj");
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.facePositions(0)[0], 0u);
  EXPECT_EQ(mesh.facePositions(0)[2], 2u);
}

TEST(ObjLoader, MissingFileNamesTheFile) {
  try {
    loadObjFile("/nonexistent/dir/mesh.obj");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "/nonexistent/dir/mesh.obj");
    EXPECT_NE(std::string(error.what()).find("cannot open"), std::string::npos);
  }
}

TEST(ObjLoader, EmptyFileIsRejected) {
  const auto dir = testing::scratchDirectory("empty_obj");
  const std::string path = testing::writeTextFile(dir / "empty.obj", "\n\n");
  try {
    loadObjFile(path);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("empty"), std::string::npos);
  }
}

TEST(ObjLoader, FileWithoutFacesIsRejected) {
  EXPECT_NE(errorOf("v 0 0 0\nv 1 0 0\n").find("no faces"), std::string::npos);
}

TEST(ObjLoader, IndexOutOfRangeNamesTheLine) {
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\n# c\nf 1 2 4\n");
  EXPECT_NE(error.find("test.obj: line 5"), std::string::npos) << error;
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
}

TEST(ObjLoader, NormalIndexOutOfRangeIsRejected) {
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n");
  EXPECT_NE(error.find("line 5"), std::string::npos) << error;
  EXPECT_NE(error.find("normal index 2"), std::string::npos) << error;
}

TEST(ObjLoader, NanCoordinateIsRejected) {
  const std::string error = errorOf("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(error.find("line 2"), std::string::npos) << error;
  EXPECT_NE(error.find("not finite"), std::string::npos) << error;
}

TEST(ObjLoader, InfiniteCoordinateIsRejected) {
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
  EXPECT_NE(error.find("line 3"), std::string::npos) << error;
}

TEST(ObjLoader, NonNumberCoordinateIsRejected) {
  const std::string error = errorOf("v 0 0 zero\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(error.find("line 1"), std::string::npos) << error;
  EXPECT_NE(error.find("non-number"), std::string::npos) << error;
}

TEST(ObjLoader, DegenerateFaceIsRejected) {
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n");
  EXPECT_NE(error.find("line 5"), std::string::npos) << error;
  EXPECT_NE(error.find("at least 3"), std::string::npos) << error;
}

TEST(ObjLoader, FaceRepeatingAVertexIsRejected) {
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 -3 3\n");
  EXPECT_NE(error.find("line 6"), std::string::npos) << error;
  EXPECT_NE(error.find("uses vertex 2 twice (degenerate face)"), std::string::npos) << error;
}

TEST(ObjLoader, UnreadableTagIsRejected) {
  const std::string base = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_NE(errorOf(base + "t crease 2/x/0 0 1 2.0\n").find("line 5"), std::string::npos);
  EXPECT_NE(errorOf(base + "t crease 2/1/0 0 1\n").find("declares 3 values"), std::string::npos);
  EXPECT_NE(errorOf(base + "t crease 2/1/0 0 7 2.0\n").find("vertex 7 is out of range"),
            std::string::npos);
  EXPECT_NE(errorOf(base + "t interpolateboundary 1/0/0 5\n").find("not 0, 1 or 2"),
            std::string::npos);
}

}  // namespace
}  // namespace tb
