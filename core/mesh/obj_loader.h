// OBJ loading with tinyobjloader, after a validating scan that reports the first
// broken rule with its line number (tinyobjloader itself only warns, and names
// the last line of the file).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::mesh {

struct LoadOptions {
  // Meshes without normals get angle-weighted smooth normals (docs/ARCHITECTURE.md); the
  // mesh then reports normals_computed.
  bool compute_missing_normals = true;
};

// Throws InputError naming the file, the line and the rule.
Mesh loadObjFile(const std::string& path, const LoadOptions& options = {});

// Same, from text already in memory; `source_name` is used in errors.
Mesh loadObjText(std::string_view text, const std::string& source_name,
                 const LoadOptions& options = {});

// Validates OBJ text line by line: vertex coordinates are finite numbers within float
// range, faces have >= 3 corners whose indices are in range, tags are well formed and
// refer to existing vertices and faces. Lines end at \n, \r\n or a lone \r, as
// tinyobjloader reads them. Throws InputError for the first violation.
// Returns the source line of every face, in file order.
std::vector<uint32_t> validateObjText(std::string_view text, const std::string& source_name);

}  // namespace tb::mesh
