#include "harness/bake/bake_sidecar.h"

#include <filesystem>
#include <fstream>

#include "core/displacement/exr_io.h"
#include "core/mesh/input_error.h"

namespace tb::bake {

std::string sidecarPath(const std::string& exr_path) { return exr_path + ".json"; }

nlohmann::json bakeSidecar(const BakeProvenance& provenance, const BakeSettings& settings,
                           const BakeResult& result) {
  const displacement::DisplacementMap& map = result.map;
  const uint32_t channels = displacement::channelCount(map.kind);
  nlohmann::json min = nlohmann::json::array(), max = nlohmann::json::array();
  for (uint32_t c = 0; c < channels; ++c) {
    min.push_back(result.value_min[c]);
    max.push_back(result.value_max[c]);
  }
  return {
      {"format", "tessbench-bake-1"},
      {"technique", provenance.technique},
      {"variant", provenance.variant},
      {"asset", provenance.asset},
      {"target", provenance.target},
      {"target_source", provenance.target_rate > 0
                            ? nlohmann::json{{"kind", "analytic"}, {"rate", provenance.target_rate}}
                            : nlohmann::json{{"kind", "mesh"}, {"path", provenance.target_path}}},
      {"kind", std::string(displacement::kindName(map.kind))},
      {"pixel_type", std::string(displacement::pixelTypeName(map.pixel_type))},
      {"layout", std::string(displacement::layoutName(map.layout))},
      {"resolution", settings.resolution},
      {"width", map.width},
      {"height", map.height},
      {"tiles",
       {{"tile_size", map.tiles.tile_size},
        {"border", map.tiles.border},
        {"tiles_per_row", map.tiles.tiles_per_row},
        {"tile_count", map.tiles.tile_count}}},
      {"displacement", {{"min", min}, {"max", max}, {"length_max", result.length_max}}},
      {"texels_baked", result.texels_baked},
      {"rays_missed", result.rays_missed}};
}

void writeBake(const std::string& exr_path, const BakeResult& result,
               const nlohmann::json& sidecar) {
  const std::string json_path = sidecarPath(exr_path);
  for (const std::string& path : {exr_path, json_path}) {
    if (std::filesystem::exists(path)) {
      throw mesh::InputError(path, "", "the file exists already (never overwritten)");
    }
  }
  displacement::writeDisplacementExr(exr_path, result.map);
  std::error_code error;
  {
    std::ofstream file(json_path, std::ios::binary);
    file << sidecar.dump(2) << "\n";
    file.close();
    if (file) return;
  }
  std::filesystem::remove(json_path, error);
  std::filesystem::remove(exr_path, error);
  throw mesh::InputError(json_path, "", "cannot be written");
}

}  // namespace tb::bake
