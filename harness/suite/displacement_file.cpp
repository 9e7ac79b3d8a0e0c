#include "harness/suite/displacement_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/displacement/exr_io.h"
#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "harness/bake/analytic_target.h"
#include "harness/bake/bake_sidecar.h"
#include "harness/measures/error/error.h"
#include "harness/suite/asset_catalog.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::suite {
namespace {

// Field `key` of the sidecar as T, or InputError naming the sidecar and the field.
template <class T>
T field(const nlohmann::json& json, const std::string& key, const std::string& file) {
  if (!json.contains(key)) throw mesh::InputError(file, key, "missing field");
  try {
    return json.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw mesh::InputError(file, key, "has the wrong type");
  }
}

void expectEqual(uint64_t sidecar, uint64_t exr, const std::string& what, const std::string& file) {
  if (sidecar != exr) {
    throw mesh::InputError(
        file, what,
        "the sidecar says " + std::to_string(sidecar) + " but the EXR has " + std::to_string(exr));
  }
}

}  // namespace

measures::DisplacedInput loadDisplacementFile(const std::string& path) {
  measures::DisplacedInput input;
  std::filesystem::path file(path);
  input.name = file.filename().string();
  input.path = path;
  const std::string json_path = bake::sidecarPath(path);
  if (!std::filesystem::exists(path)) throw mesh::InputError(path, "", "no such file");
  auto map =
      std::make_shared<displacement::DisplacementMap>(displacement::readDisplacementExr(path));
  input.file_bytes = std::filesystem::file_size(path);
  std::ifstream stream(json_path, std::ios::binary);
  if (!stream) {
    throw mesh::InputError(json_path, "",
                           "missing bake sidecar (tessbench bake writes FILE.exr.json)");
  }
  nlohmann::json sidecar;
  try {
    sidecar = nlohmann::json::parse(stream);
  } catch (const nlohmann::json::exception& error) {
    throw mesh::InputError(json_path, "", std::string("not JSON: ") + error.what());
  }
  if (!sidecar.is_object() || sidecar.value("format", "") != "tessbench-bake-1") {
    throw mesh::InputError(json_path, "format", "not a tessbench-bake-1 sidecar");
  }
  input.technique = field<std::string>(sidecar, "technique", json_path);
  input.variant = field<std::string>(sidecar, "variant", json_path);
  input.asset = field<std::string>(sidecar, "asset", json_path);
  input.target = field<std::string>(sidecar, "target", json_path);
  input.resolution = field<uint32_t>(sidecar, "resolution", json_path);
  if (field<std::string>(sidecar, "kind", json_path) != displacement::kindName(map->kind)) {
    throw mesh::InputError(json_path, "kind", "disagrees with the EXR's channels");
  }
  if (map->layout != displacement::DisplacementLayout::kTiles) {
    throw mesh::InputError(path, "",
                           "only per-patch tile maps can displace a technique (layout uv)");
  }
  expectEqual(field<uint64_t>(sidecar, "width", json_path), map->width, "width", json_path);
  expectEqual(field<uint64_t>(sidecar, "height", json_path), map->height, "height", json_path);
  expectEqual(input.resolution + 2ull * map->tiles.border, map->tiles.tile_size, "resolution",
              json_path);
  if (input.resolution < 2) throw mesh::InputError(json_path, "resolution", "must be at least 2");
  if (sidecar.contains("target_source")) {
    const nlohmann::json& source = sidecar["target_source"];
    const std::string kind = source.value("kind", "");
    if (kind == "analytic") {
      input.target_rate = field<int>(source, "rate", json_path);
      if (input.target_rate < 1 || input.target_rate > 1024) {
        throw mesh::InputError(json_path, "target_source.rate", "must be 1 to 1024");
      }
    } else if (kind == "mesh") {
      input.target_path = field<std::string>(source, "path", json_path);
    } else {
      throw mesh::InputError(json_path, "target_source.kind", "must be analytic or mesh");
    }
  }
  input.map = std::move(map);
  return input;
}

std::vector<measures::DisplacedInput> bundledDisplacements() {
  const std::filesystem::path folder = std::filesystem::path(assetsDirectory()) / "displacement";
  std::vector<std::string> paths;
  if (std::filesystem::is_directory(folder)) {
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      if (entry.path().extension() == ".exr") paths.push_back(entry.path().string());
    }
  }
  std::sort(paths.begin(), paths.end());
  std::vector<measures::DisplacedInput> inputs;
  for (const std::string& path : paths) {
    measures::DisplacedInput input = loadDisplacementFile(path);
    input.path = "assets/displacement/" + input.name;  // results do not depend on the checkout
    inputs.push_back(std::move(input));
  }
  return inputs;
}

std::shared_ptr<const measures::DisplacementTarget> rebuildTarget(
    const measures::DisplacedInput& input, const techniques::SurfacePatches& undisplaced) {
  auto target = std::make_shared<measures::DisplacementTarget>();
  if (input.target_rate > 0) {
    const mesh::Mesh& control = undisplaced.controlMesh();
    const ref::LimitTessellation mesh =
        bake::analyticTargetMesh(control, lod::referenceScheme(undisplaced.approximates()),
                                 input.target_rate, bake::analyticDisplacementFor(control));
    target->positions = mesh.positions;
    target->triangles = mesh.triangles;
  } else if (!input.target_path.empty()) {
    const mesh::Mesh mesh = mesh::loadObjFile(input.target_path);
    target->positions = mesh.positions;
    target->triangles = ref::fanTriangles(mesh);
  } else {
    throw mesh::InputError(input.path + ".json", "target_source",
                           "missing: the target cannot be rebuilt");
  }
  target->field = std::make_shared<ref::TriangleDistanceField>(target->positions, target->triangles,
                                                               input.name + " target");
  return target;
}

}  // namespace tb::suite
