#include "harness/pictures/pictures_index.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "harness/pictures/heat_map.h"

namespace tb::pictures {

std::string picturesSummary(const PicturesIndex& index) {
  if (index.status != "ok") return index.status + ": " + index.reason;
  size_t failed = 0;
  for (const PictureEntry& p : index.pictures) failed += p.status != "ok";
  char text[160];
  std::snprintf(text, sizeof(text), "%zu pairs at level %d, %.1f MB of PNG, %.1f s",
                index.pictures.size() - failed,
                index.pictures.empty() ? 0 : index.pictures.front().level,
                double(index.png_bytes) / 1e6, index.wall_s);
  std::string line = text;
  if (failed > 0) line += ", " + std::to_string(failed) + " failed";
  return line;
}

std::string picturesIndexJson(const PicturesIndex& index) {
  using Json = nlohmann::ordered_json;
  Json json{{"schema_version", 1}, {"status", index.status}};
  if (!index.reason.empty()) json["reason"] = index.reason;
  json["device"] = index.device;
  json["error_unit"] = "rel_diag";
  Json ramp = Json::array();
  for (int i = 0; i <= 4; ++i) {
    const Rgb c = heatColour(i / 4.0);
    ramp.push_back({c.r, c.g, c.b});
  }
  json["colour_ramp"] = ramp;
  Json pictures = Json::array();
  for (const PictureEntry& p : index.pictures) {
    Json entry{{"technique", p.technique}, {"variant", p.variant},
               {"asset", p.asset},         {"level", p.level},
               {"error_png", p.error_png}, {"wireframe_png", p.wireframe_png},
               {"width_px", p.width_px},   {"height_px", p.height_px},
               {"error_max", p.error_max}, {"error_statistic", p.error_statistic},
               {"scale_min", p.scale_min}, {"scale_max", p.scale_max},
               {"up_axis", p.up_axis}};
    if (!p.crack_png.empty()) {
      entry["crack_png"] = p.crack_png;
      entry["crack_row"] = p.crack_row;
      entry["crack_points"] = p.crack_points;
      entry["crack_points_visible"] = p.crack_points_visible;
      entry["crack_max_gap_world"] = p.crack_max_gap_world;
    }
    if (p.status != "ok") {
      entry["status"] = p.status;
      entry["reason"] = p.reason;
    }
    pictures.push_back(std::move(entry));
  }
  json["pictures"] = std::move(pictures);
  return json.dump(1) + "\n";
}

}  // namespace tb::pictures
