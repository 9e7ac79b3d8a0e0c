// Small glTF 2.0 files written for tests (the loader's tests, the CLI's bad-input table): one
// mesh of one TRIANGLES primitive under one node, its buffer a base64 data URI, and an edit
// hook to break one rule at a time.
#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/mesh/gltf_loader.h"
#include "core/mesh/input_error.h"

namespace tb::testing {

inline std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(bytes[i]) << 16 |
                       (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                       (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0);
    text += kDigits[n >> 18 & 63];
    text += kDigits[n >> 12 & 63];
    text += i + 1 < bytes.size() ? kDigits[n >> 6 & 63] : '=';
    text += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
  }
  return text;
}

struct GltfSpec {
  std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};  // a unit square
  std::vector<float> normals;                                           // empty: no NORMAL
  std::vector<float> uvs;                                               // empty: no TEXCOORD_0
  std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};  // empty: no indices accessor
  int index_type = 5125;                               // 5121, 5123 or 5125
  // Edits the JSON before it is written (a node transform, a broken field).
  std::function<void(nlohmann::json&)> edit;
};

// The buffer's bytes: positions, normals, uvs, indices, each at a 4-byte boundary; `views`
// gets each part's (offset, length), in that order (absent parts get none).
inline std::vector<uint8_t> gltfBuffer(const GltfSpec& spec,
                                       std::vector<std::pair<size_t, size_t>>* views) {
  std::vector<uint8_t> bytes;
  auto append = [&](const void* data, size_t size) {
    while (bytes.size() % 4 != 0) bytes.push_back(0);
    views->push_back({bytes.size(), size});
    const auto* p = static_cast<const uint8_t*>(data);
    bytes.insert(bytes.end(), p, p + size);
  };
  for (const auto* part : {&spec.positions, &spec.normals, &spec.uvs}) {
    if (!part->empty()) append(part->data(), part->size() * sizeof(float));
  }
  if (!spec.indices.empty()) {
    const size_t width = spec.index_type == 5121 ? 1 : spec.index_type == 5123 ? 2 : 4;
    std::vector<uint8_t> packed(spec.indices.size() * width);
    for (size_t i = 0; i < spec.indices.size(); ++i) {
      std::memcpy(&packed[i * width], &spec.indices[i], width);  // little-endian
    }
    append(packed.data(), packed.size());
  }
  return bytes;
}

inline nlohmann::json gltfJson(const GltfSpec& spec) {
  std::vector<std::pair<size_t, size_t>> views;
  const std::vector<uint8_t> bytes = gltfBuffer(spec, &views);
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}}},
                         {"scene", 0},
                         {"scenes", {{{"nodes", {0}}}}},
                         {"nodes", {{{"mesh", 0}}}},
                         {"buffers",
                          {{{"byteLength", bytes.size()},
                            {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}}};
  nlohmann::json primitive = {{"mode", 4}, {"attributes", nlohmann::json::object()}};
  size_t view = 0;
  auto accessor = [&](const char* type, int component, size_t count) {
    gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", views[view].first}, {"byteLength", views[view].second}});
    gltf["accessors"].push_back(
        {{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}});
    ++view;
    return gltf["accessors"].size() - 1;
  };
  primitive["attributes"]["POSITION"] = accessor("VEC3", 5126, spec.positions.size() / 3);
  if (!spec.normals.empty()) {
    primitive["attributes"]["NORMAL"] = accessor("VEC3", 5126, spec.normals.size() / 3);
  }
  if (!spec.uvs.empty()) {
    primitive["attributes"]["TEXCOORD_0"] = accessor("VEC2", 5126, spec.uvs.size() / 2);
  }
  if (!spec.indices.empty()) {
    primitive["indices"] = accessor("SCALAR", spec.index_type, spec.indices.size());
  }
  gltf["meshes"] = {{{"name", "square"}, {"primitives", {primitive}}}};
  if (spec.edit) spec.edit(gltf);
  return gltf;
}

inline std::string gltfText(const GltfSpec& spec) { return gltfJson(spec).dump(); }

// The InputError message of loading these bytes as "test.gltf"; "" when they load.
inline std::string gltfErrorOf(const std::string& bytes) {
  try {
    mesh::loadGltfBytes({reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()},
                        "test.gltf");
  } catch (const mesh::InputError& error) {
    return error.what();
  }
  return "";
}

struct GltfCase {
  const char* name;
  std::string file;                // a file name for it ("cut.gltf")
  std::string text;                // the file's bytes
  std::vector<std::string> names;  // what the one line must contain besides the file
};

inline std::string gltfTextWith(std::function<void(nlohmann::json&)> edit) {
  GltfSpec spec;
  spec.edit = std::move(edit);
  return gltfText(spec);
}

inline constexpr const char* kGltfPrimitive = "mesh 0 (square) primitive 0";

// Malformed files, one broken rule each, as bytes (no external file): the loader's test
// (tests/mesh/gltf_errors_test.cpp) and the CLI's bad-input table read them; `names` are
// what the one line must contain besides the file.
inline std::vector<GltfCase> badGltfFiles() {
  const std::string square = gltfText({});
  GltfSpec nan;
  nan.positions[4] = std::numeric_limits<float>::quiet_NaN();
  GltfSpec past;
  past.indices = {0, 1, 9, 0, 2, 3};
  GltfSpec line;
  line.positions = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
  return {
      {"malformed JSON", "cut.gltf", square.substr(0, square.size() / 2), {"tinygltf"}},
      {"empty", "empty.gltf", "", {"empty"}},
      {"binary garbage", "garbage.glb", std::string("glTF\x02\0\0\0\xff\xff\xff\x7f", 12), {}},
      {"short buffer",
       "short.gltf",
       gltfTextWith([](nlohmann::json& g) { g["bufferViews"][0]["byteLength"] = 4096; }),
       {kGltfPrimitive, "runs past buffer 0", "missing or short buffer"}},
      {"accessor out of range",
       "range.gltf",
       gltfTextWith([](nlohmann::json& g) { g["accessors"][0]["count"] = 100; }),
       {kGltfPrimitive, "POSITION accessor 0", "run past its buffer view"}},
      {"accessor that does not exist",
       "accessor.gltf",
       gltfTextWith([](nlohmann::json& g) {
         g["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9;
       }),
       {kGltfPrimitive, "accessor 9 does not exist"}},
      {"index past the vertex count",
       "index.gltf",
       gltfText(past),
       {kGltfPrimitive, "index 9 is past the 4 vertices"}},
      {"non-finite position",
       "nan.gltf",
       gltfText(nan),
       {kGltfPrimitive, "vertex 1", "not finite"}},
      {"zero-area primitive", "flat.gltf", gltfText(line), {kGltfPrimitive, "zero area"}},
      {"another mode",
       "lines.gltf",
       gltfTextWith([](nlohmann::json& g) { g["meshes"][0]["primitives"][0]["mode"] = 1; }),
       {kGltfPrimitive, "mode 1 is not TRIANGLES"}},
      {"missing POSITION",
       "position.gltf",
       gltfTextWith([](nlohmann::json& g) {
         g["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
       }),
       {kGltfPrimitive, "no POSITION"}},
      {"required extension",
       "draco.gltf",
       gltfTextWith([](nlohmann::json& g) {
         g["extensionsUsed"] = {"KHR_draco_mesh_compression"};
         g["extensionsRequired"] = {"KHR_draco_mesh_compression"};
         g["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
             {"bufferView", 0}, {"attributes", {{"POSITION", 0}}}};
       }),
       {kGltfPrimitive, "KHR_draco_mesh_compression"}},
      {"node cycle",
       "cycle.gltf",
       gltfTextWith([](nlohmann::json& g) { g["nodes"][0]["children"] = {0}; }),
       {"node 0", "cycle"}},
  };
}

}  // namespace tb::testing
