// The JSON sidecar written beside a baked map (docs/FORMATS.md, "The baker's sidecar"): FILE.exr
// gets FILE.exr.json, which says what was baked from what.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "harness/bake/baker.h"

namespace tb::bake {

struct BakeProvenance {
  std::string technique, variant, asset;  // asset as shown (bundled name or path)
  // "analytic: <formula with its numbers>, rate N" or the target OBJ's path.
  std::string target;
  // How to rebuild the target (`run --displacement` grades the displaced surface against it):
  // the analytic target's tessellation rate, or 0 with target_path the OBJ.
  int target_rate = 0;
  std::string target_path = {};
};

// The sidecar's path for a map written to `exr_path`: exr_path + ".json".
std::string sidecarPath(const std::string& exr_path);

// {"format": "tessbench-bake-1", technique, variant, asset, target, target_source {"kind":
//  "analytic", "rate"} or {"kind": "mesh", "path"}, kind, pixel_type, layout,
//  resolution, width, height, tiles{tile_size, border, tiles_per_row, tile_count},
//  displacement{min[], max[], length_max} (world units, per channel), texels_baked,
//  rays_missed}.
nlohmann::json bakeSidecar(const BakeProvenance& provenance, const BakeSettings& settings,
                           const BakeResult& result);

// Writes the map to exr_path and the sidecar beside it. Refuses (InputError, nothing
// written) when either file exists already; a failed sidecar removes the map again.
void writeBake(const std::string& exr_path, const BakeResult& result,
               const nlohmann::json& sidecar);

}  // namespace tb::bake
