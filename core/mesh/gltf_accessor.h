// Reading glTF accessors out of a model tinygltf parsed: every bound checked against the
// buffer view and the buffer, byte strides, sparse accessors and normalised integers (the
// glTF 2.0 specification, §3.6 and §3.11). Used by gltf_loader.cpp only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace tb::mesh {

// Where an accessor is read, for errors: the file and the element ("mesh 0 primitive 1").
struct GltfPlace {
  const std::string& file;
  const std::string& element;
};

// Accessor `index` as doubles, `width` components an element (1 SCALAR, 2 VEC2, 3 VEC3),
// element after element. Integer components convert to their value, or with `normalized` to
// [0, 1] (unsigned) or [-1, 1] (signed) as the specification maps them. `what` names the
// attribute ("POSITION"). Throws InputError at `place` for a missing accessor, another type,
// or any read past a buffer view or buffer.
std::vector<double> readGltfAccessor(const tinygltf::Model& model, int index, int width,
                                     const char* what, const GltfPlace& place);

// An index accessor (SCALAR of unsigned byte, short or int, not normalised).
std::vector<uint32_t> readGltfIndices(const tinygltf::Model& model, int index,
                                      const GltfPlace& place);

}  // namespace tb::mesh
