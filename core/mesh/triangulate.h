#pragma once

#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::mesh {

struct Triangulation {
  Mesh mesh;                          // every face a triangle
  std::vector<uint32_t> source_face;  // per triangle: the face of the input it came from
  size_t polygons_split = 0;          // input faces with more than 3 corners
};

// Fan-triangulates every polygon from its first corner, keeping split normals and
// UVs per corner. Triangles pass through unchanged.
Triangulation fanTriangulate(const Mesh& mesh);

// The notes a triangle technique reports about its input: polygons split, normals computed.
std::vector<std::string> triangulationWarnings(const Triangulation& triangulation);

}  // namespace tb::mesh
