// libFuzzer target: the OBJ loader (core/mesh/obj_loader.h) on arbitrary file contents,
// tags included, then what a run does with a loaded asset inside tb_mesh: topology,
// welding, bounds, fan triangulation, render vertices. InputError is the one expected
// exception; anything else, a sanitizer report or a broken Mesh property is a finding.
#include <cstdint>
#include <string>
#include <string_view>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "tests/fuzz/fuzz_mesh_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  tb::mesh::Mesh mesh;
  try {
    mesh = tb::mesh::loadObjText(text, "fuzz.obj");
  } catch (const tb::mesh::InputError& error) {
    const std::string_view message = error.what();
    tb::fuzz::require(message.find('\n') == std::string_view::npos,
                      "an InputError's message is one line");
    return 0;
  }
  tb::fuzz::checkLoadedMesh(mesh);
  tb::fuzz::useMesh(mesh);
  return 0;
}
