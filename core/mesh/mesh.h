// The polygon mesh every technique starts from: positions, optional normals and
// UVs indexed per face corner (so they may be split), and OpenSubdiv's `t` tags.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/vec.h"

namespace tb::mesh {

// Sdc-style boundary interpolation. Note the OBJ tag value is NOT this enum:
// `t interpolateboundary` 1 means edge-and-corner and 2 means edge-only.
enum class BoundaryInterpolation { kNone, kEdgeOnly, kEdgeAndCorner };

struct Crease {
  uint32_t v0, v1;   // position indices, as written in the file
  double sharpness;  // 0 = smooth; >= 10 is treated as infinitely sharp by OpenSubdiv
};

struct Corner {
  uint32_t vertex;
  double sharpness;
};

// OpenSubdiv's OBJ tags, kept as data for the reference surfaces and ACC.
struct SubdivisionTags {
  std::vector<Crease> creases;
  std::vector<Corner> corners;
  std::vector<uint32_t> holes;  // face indices
  BoundaryInterpolation boundary = BoundaryInterpolation::kEdgeAndCorner;
  bool boundary_from_tag = false;
  int fvar_propagate_corners = 0;  // `t facevaryingpropagatecorners`, 0 when absent
  bool smooth_triangles = false;   // `t smoothtriangles` (Catmark weights on triangles)
  std::string crease_method;       // `t creasemethod` string ("normal", "chaikin"), "" when absent
};

struct Mesh {
  std::string source;  // file path or asset name, used in every error message

  std::vector<Vec3d> positions;
  std::vector<Vec3d> normals;  // empty when the file has none
  std::vector<Vec2d> uvs;      // empty when the file has none

  // Face f uses corners [face_offsets[f], face_offsets[f+1]).
  std::vector<uint32_t> face_offsets{0};
  std::vector<uint32_t> corner_positions;  // position index per corner
  std::vector<int32_t> corner_normals;     // normal index per corner, -1 when absent
  std::vector<int32_t> corner_uvs;         // uv index per corner, -1 when absent
  std::vector<uint32_t> face_lines;        // source line of each face, 0 when generated

  SubdivisionTags tags;
  bool normals_computed = false;  // true when normals were generated at load, not read

  size_t faceCount() const { return face_offsets.size() - 1; }
  uint32_t faceSize(size_t f) const { return face_offsets[f + 1] - face_offsets[f]; }
  std::span<const uint32_t> facePositions(size_t f) const {
    return {corner_positions.data() + face_offsets[f], faceSize(f)};
  }
  bool hasNormals() const { return !normals.empty(); }
  bool hasUvs() const { return !uvs.empty(); }
  bool allFacesOfSize(uint32_t n) const;
  uint32_t maxFaceSize() const;

  // Appends one face; normal/uv index spans are empty or the same length.
  void addFace(std::span<const uint32_t> positions_of_face, std::span<const int32_t> normal_ids,
               std::span<const int32_t> uv_ids, uint32_t line);
};

// A short human description of a face element for errors: "face 17 (line 42)".
std::string describeFace(const Mesh& mesh, size_t face);

}  // namespace tb::mesh
