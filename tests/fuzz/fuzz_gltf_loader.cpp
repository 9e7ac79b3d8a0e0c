// libFuzzer target: the glTF reader (core/mesh/gltf_loader.h) on arbitrary bytes, .gltf JSON
// or .glb (told apart by the magic), then what a run does with a loaded asset inside tb_mesh
// (fuzz_mesh_checks.h). External files are refused in memory, so no input reads the disk.
// InputError is the one expected exception; anything else, a sanitizer report or a broken
// Mesh property (every face a triangle, indices in range, finite values) is a finding.
#include <cstdint>
#include <span>
#include <string_view>

#include "core/mesh/gltf_loader.h"
#include "core/mesh/input_error.h"
#include "tests/fuzz/fuzz_mesh_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tb::mesh::Mesh mesh;
  try {
    mesh = tb::mesh::loadGltfBytes(std::span<const uint8_t>(data, size), "fuzz.gltf");
  } catch (const tb::mesh::InputError& error) {
    const std::string_view message = error.what();
    tb::fuzz::require(message.find('\n') == std::string_view::npos,
                      "an InputError's message is one line");
    return 0;
  }
  tb::fuzz::require(mesh.allFacesOfSize(3), "a glTF mesh is triangles");
  tb::fuzz::checkLoadedMesh(mesh);
  tb::fuzz::useMesh(mesh);
  return 0;
}
