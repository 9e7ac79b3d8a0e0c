// The index of a run's pictures (pictures/pictures.json beside results.json): which
// pictures exist, for which technique, variant and asset, and the scale each is drawn on,
// so a report can embed and caption them without decoding a PNG.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tb::pictures {

// One technique × asset: its error and wireframe pictures.
struct PictureEntry {
  std::string technique;
  std::string variant;  // the technique's default variant (its first)
  std::string asset;    // as results.json names it
  int level = 0;        // uniform integer tessellation level of every patch
  // Paths relative to the run folder; empty when the picture failed (status, reason).
  std::string error_png;
  std::string wireframe_png;
  uint32_t width_px = 0;  // both pictures: the render plus the colour-bar strip below it
  uint32_t height_px = 0;
  double error_max = 0;  // largest vertex error, fraction of the bounding-box diagonal
  // What one triangle's colour shows: "max_of_3_vertices".
  std::string error_statistic;
  // The colour scale: scale_min maps to the ramp's first colour, scale_max (=
  // max(error_max, kMinimumScaleMax)) to its last, linearly, in rel_diag.
  double scale_min = 0;
  double scale_max = 0;
  std::string up_axis = "y";  // the axis drawn upwards (up_axis.h): "y", or "z" turned upright
  // Where the variant cracks (crack_picture.h): the path of the wireframe with the unequal
  // points of `crack_row` marked, empty when no cpu_float cracks row of the record has
  // points_not_equal > 0 (then the other crack_* fields are left out of the JSON).
  std::string crack_png;
  std::string crack_row;              // CrackRow::text()
  uint64_t crack_points = 0;          // unequal pairs marked (= the row's points_not_equal)
  uint64_t crack_points_visible = 0;  // of those, seen from the camera (discs; rings behind)
  double crack_max_gap_world = 0;     // the row's max_gap_world (circled), world units
  std::string status = "ok";          // "ok" or "failed"
  std::string reason;                 // why it failed; empty when ok
};

struct PicturesIndex {
  std::string status = "ok";           // "ok", or "skipped" when no Vulkan device is usable
  std::string reason;                  // why skipped; empty when ok
  std::string device;                  // the Vulkan device rendered on; empty when skipped
  std::vector<PictureEntry> pictures;  // in results.json record order
  // How long the pictures took and what they weigh; they vary run to run or machine to
  // machine, so they stay out of the JSON (printed by the CLI).
  double wall_s = 0;       // seconds, the device opened to the index written
  uint64_t png_bytes = 0;  // every PNG written, summed
};

// One line for the terminal: "12 pairs at level 8, 1.9 MB of PNG, 3.2 s" (plus "N failed"),
// or "skipped: <reason>".
std::string picturesSummary(const PicturesIndex& index);

// The folder of the pictures and the path of the index, inside the run folder.
inline constexpr const char* kPicturesFolder = "pictures";
inline constexpr const char* kPicturesIndexPath = "pictures/pictures.json";

// The index as JSON (nlohmann ordered_json, 1-space indent, newline at the end):
// {"schema_version": 1, "status", ["reason"], "device", "error_unit": "rel_diag",
//  "colour_ramp": [[r, g, b] low, ..., high], "pictures": [{technique, variant, asset,
//  level, error_png, wireframe_png, width_px, height_px, error_max, error_statistic,
//  scale_min, scale_max, up_axis, [crack_png, crack_row, crack_points, crack_points_visible,
//  crack_max_gap_world when the variant cracks], [status, reason when failed]}]}.
std::string picturesIndexJson(const PicturesIndex& index);

}  // namespace tb::pictures
