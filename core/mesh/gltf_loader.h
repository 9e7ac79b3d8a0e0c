// glTF 2.0 loading with tinygltf (.gltf with external or data-URI buffers, and .glb): every
// TRIANGLES primitive of the default scene, node transforms applied, flattened into one Mesh
// the way the OBJ loader gives `f v/vt/vn` (docs/FORMATS.md, "glTF 2.0 assets").
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "core/mesh/mesh.h"

namespace tb::mesh {

struct GltfLoadOptions {
  // Meshes without normals get angle-weighted smooth normals, as OBJ's do (LoadOptions).
  bool compute_missing_normals = true;
  // The weld of the file's vertices into positions: 0 welds bitwise-equal transformed
  // positions only; > 0 (world units) also welds each vertex to the first earlier position
  // within this distance, for files whose seams do not match exactly.
  double weld_tolerance = 0;
};

// The mesh keeps the file's vertices as the engine draws them: glTF vertex i of the
// flattened scene is normal i and uv i (v flipped to OBJ's convention, 1 - v), its position
// the weld of its transformed POSITION, so a UV or normal seam is a corner attribute that
// differs across an edge, as in OBJ. Throws InputError naming the file, the mesh and the
// primitive and the rule (malformed JSON, a missing or short buffer, an accessor out of
// range, an index past the vertex count, a non-finite position, another mode, a missing
// POSITION, a required extension, a primitive whose triangles all have zero area).
Mesh loadGltfFile(const std::string& path, const GltfLoadOptions& options = {});

// Same, from the bytes of a .gltf or .glb (told apart by the "glTF" magic); `source_name`
// is used in errors. External buffers are refused: only data URIs and the GLB chunk.
Mesh loadGltfBytes(std::span<const uint8_t> bytes, const std::string& source_name,
                   const GltfLoadOptions& options = {});

// True for a path ending in .gltf or .glb (any case): the loader that reads it.
bool isGltfPath(const std::string& path);

}  // namespace tb::mesh
