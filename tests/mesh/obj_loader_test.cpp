// Oracle: the OBJ files' own text (counts and tags read by eye from the bundled
// OpenSubdiv shapes) and the error rules of docs/ARCHITECTURE.md §8.
#include "core/mesh/obj_loader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/input_error.h"
#include "tests/test_support.h"

namespace tb {
namespace {

std::string errorOf(const std::string& text) {
  try {
    mesh::loadObjText(text, "test.obj");
  } catch (const mesh::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(ObjLoader, LoadsCubeCountsAndSplitNormals) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  EXPECT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.faceCount(), 6u);
  EXPECT_TRUE(mesh.allFacesOfSize(4));
  EXPECT_EQ(mesh.normals.size(), 24u);
  EXPECT_EQ(mesh.uvs.size(), 14u);
  EXPECT_FALSE(mesh.normals_computed);
  EXPECT_EQ(mesh.face_lines[0] > 0, true);
}

TEST(ObjLoader, ReadsCreaseTagsAndBoundaryMapping) {
  const mesh::Mesh mesh =
      mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube_creases1.obj"));
  ASSERT_EQ(mesh.tags.creases.size(), 12u);
  EXPECT_EQ(mesh.tags.creases[0].v0, 0u);
  EXPECT_EQ(mesh.tags.creases[0].v1, 1u);
  // tinyobjloader reads tag values as float.
  EXPECT_EQ(mesh.tags.creases[0].sharpness, 5.0);
  EXPECT_EQ(mesh.tags.creases[11].sharpness, double(0.1f));
  // OBJ value 2 is edge-only (the reverse of Sdc's enum order).
  EXPECT_EQ(mesh.tags.boundary, mesh::BoundaryInterpolation::kEdgeOnly);
  EXPECT_TRUE(mesh.tags.boundary_from_tag);
}

TEST(ObjLoader, BoundaryTagOneIsEdgeAndCorner) {
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt interpolateboundary 1/0/0 1\n", "tag.obj");
  EXPECT_EQ(mesh.tags.boundary, mesh::BoundaryInterpolation::kEdgeAndCorner);
}

TEST(ObjLoader, ReadsCornerTags) {
  const mesh::Mesh mesh =
      mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube_corner3.obj"));
  ASSERT_FALSE(mesh.tags.corners.empty());
  EXPECT_GT(mesh.tags.corners[0].sharpness, 0.0);
}

TEST(ObjLoader, ComputesNormalsWhenAbsent) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_cube.obj"));
  EXPECT_TRUE(mesh.normals_computed);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const mesh::Vec3d& n : mesh.normals) EXPECT_NEAR(length(n), 1.0, 1e-12);
}

TEST(ObjLoader, AngleWeightedNormalOfCubeCornerIsTheDiagonal) {
  // Three faces meet at (1,1,1) each with a 90-degree corner: equal weights.
  const std::string cube =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const mesh::Mesh mesh = mesh::loadObjText(cube, "cube.obj");
  const mesh::Vec3d n = mesh.normals[6];
  const double k = 1.0 / std::sqrt(3.0);
  EXPECT_NEAR(n.x, k, 1e-12);
  EXPECT_NEAR(n.y, k, 1e-12);
  EXPECT_NEAR(n.z, k, 1e-12);
}

TEST(ObjLoader, NegativeIndicesAreRelative) {
  const mesh::Mesh mesh = mesh::loadObjText("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n", "rel.obj");
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.facePositions(0)[0], 0u);
  EXPECT_EQ(mesh.facePositions(0)[2], 2u);
}

TEST(ObjLoader, MissingFileNamesTheFile) {
  try {
    mesh::loadObjFile("/nonexistent/dir/mesh.obj");
    FAIL() << "expected InputError";
  } catch (const mesh::InputError& error) {
    EXPECT_EQ(error.file(), "/nonexistent/dir/mesh.obj");
    EXPECT_NE(std::string(error.what()).find("cannot open"), std::string::npos);
  }
}

TEST(ObjLoader, EmptyFileIsRejected) {
  const auto dir = testing::scratchDirectory("empty_obj");
  const std::string path = testing::writeTextFile(dir / "empty.obj", "\n\n");
  try {
    mesh::loadObjFile(path);
    FAIL() << "expected InputError";
  } catch (const mesh::InputError& error) {
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

// Found by tests/fuzz (fuzz_obj_loader): a finite double beyond float range passed the
// scan and became an infinite position in tinyobjloader's floats.
TEST(ObjLoader, CoordinateBeyondFloatRangeIsRejected) {
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n");
  EXPECT_NE(error.find("line 3"), std::string::npos) << error;
  EXPECT_NE(error.find("beyond float range"), std::string::npos) << error;
  const std::string tag_error =
      errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1 1e39\n");
  EXPECT_NE(tag_error.find("line 5"), std::string::npos) << tag_error;
  EXPECT_NE(tag_error.find("beyond float range"), std::string::npos) << tag_error;
  // The largest float still loads.
  EXPECT_EQ(errorOf("v 0 0 0\nv 1 0 0\nv 0 3.4028234e38 0\nf 1 2 3\n"), "");
}

// A number the scan reads as 1e10 that tinyobjloader's own parser overflows (a 311-digit
// mantissa, then e-300) is refused after loading, naming the vertex.
TEST(ObjLoader, CoordinateTinyobjloaderReadsAsInfinityIsRejected) {
  const std::string error =
      errorOf("v 0 0 0\nv 1 0 0\nv 1" + std::string(310, '0') + "e-300 1 0\nf 1 2 3\n");
  EXPECT_NE(error.find("vertex position 3"), std::string::npos) << error;
  EXPECT_NE(error.find("not finite"), std::string::npos) << error;
}

// Found by tests/fuzz: a lone \r ends a line for tinyobjloader but was a space to the scan,
// so the scan saw one face "f 1 2 3" where tinyobjloader read "f 1 2 9" (9 > 3 positions),
// and computing normals read past the positions.
TEST(ObjLoader, LoneCarriageReturnEndsALineAsInTinyobjloader) {
  const mesh::Mesh mesh = mesh::loadObjText("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", "cr.obj");
  EXPECT_EQ(mesh.positions.size(), 3u);
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.face_lines[0], 4u);
  const std::string error = errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\rf 1 2 9\nf\r1 2 3\n");
  EXPECT_NE(error.find("line 4"), std::string::npos) << error;
  EXPECT_NE(error.find("vertex index 9 is out of range"), std::string::npos) << error;
  // \r\n is one line end, not two.
  EXPECT_EQ(
      mesh::loadObjText("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n", "crlf.obj").face_lines[0],
      4u);
}

// Found by tests/fuzz: for "2/" tinyobjloader reads the next corner's number as the
// texture coordinate index (atoi skips the space), past the file's texture coordinates.
TEST(ObjLoader, CornerEndingInSlashIsRejected) {
  const std::string base = "v 1 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n";
  for (const char* face : {"f 1 2/ 3\n", "f 1 2// 3\n", "f 1/1/ 2 3\n", "f 1 2 3/\n"}) {
    const std::string error = errorOf(base + face);
    EXPECT_NE(error.find("line 5"), std::string::npos) << face << " -> " << error;
    EXPECT_NE(error.find("ending in '/'"), std::string::npos) << face << " -> " << error;
  }
  EXPECT_EQ(errorOf(base + "f 1//1 2//1 3//1\n"), "");
}

// Found by tests/fuzz: tinyobjloader reads a skin weight's joint ("vw", its extension) as a
// float and converts it to int, undefined for 1e39 and for 2147483647, which rounds to 2^31
// as a float (UBSan in the fuzz build, which compiles tinyobjloader from its header).
TEST(ObjLoader, SkinWeightJointBeyondIntIsRejected) {
  const std::string base = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (const char* line : {"vw 1 1e39 0.5\n", "vw 1 2147483647 0.5\n", "vw 1 16777217 0.5\n",
                           "vw 1 -1 0.5\n", "vw 1 0 nan\n", "vw 1 0\n", "vw\n"}) {
    const std::string error = errorOf(base + line);
    EXPECT_NE(error.find("line 5: vertex weight"), std::string::npos) << line << " -> " << error;
  }
  EXPECT_EQ(errorOf(base + "vw 0 0 0.25 16777216 0.75\n"), "");
}

// Found by tests/fuzz: tinyobjloader's own number parser sums a decimal exponent in an int,
// which "0e02147483648" (0 to strtod) overflows (UBSan); so do a colour's numbers, which
// tinyobjloader reads after a position's three.
TEST(ObjLoader, ExponentOfMoreThanFourDigitsIsRejected) {
  const std::string tri = "v 0 0 0\nv 1 0 0\n";
  for (const std::string& text :
       {tri + "v 0 1 0e02147483648\nf 1 2 3\n", tri + "v 0 1 0 1 1 1e-99999\nf 1 2 3\n",
        tri + "vn 0 0 0e00012345\nv 0 1 0\nf 1 2 3\n"}) {
    const std::string error = errorOf(text);
    EXPECT_NE(error.find("line 3"), std::string::npos) << text << " -> " << error;
    EXPECT_NE(error.find("exponent of more than 4 digits"), std::string::npos) << error;
  }
  const std::string base = tri + "v 0 1 0\nf 1 2 3\n";
  EXPECT_NE(errorOf(base + "t crease 2/1/0 0 1 0e+123456\n").find("line 5: tag 'crease'"),
            std::string::npos);
  EXPECT_NE(errorOf(base + "vw 0 0 5e-000012345\n").find("line 5: vertex weight"),
            std::string::npos);
  // Leading zeros do not count: tinyobjloader's sum stays small.
  EXPECT_EQ(errorOf(tri + "v 0 1e-0000000000001 0 0.5 0.5 0.5\nf 1 2 3\n"), "");
}

// Found by tests/fuzz: the counts of a tag's triple were summed before being bounded, a
// signed overflow (UBSan) that could also make the sum match the values given.
TEST(ObjLoader, TagCountsThatOverflowAreRejected) {
  const std::string base = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string error =
      errorOf(base + "t crease 9223372036854775807/9223372036854775807/2 0 1 3\n");
  EXPECT_NE(error.find("line 5"), std::string::npos) << error;
  EXPECT_NE(error.find("declares 9223372036854775807 values but has 3"), std::string::npos)
      << error;
}

}  // namespace
}  // namespace tb
