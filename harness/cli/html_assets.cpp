#include "harness/cli/html_assets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

namespace tb::cli {
namespace {

using Json = nlohmann::json;

// Pictures beyond this many PNG bytes in all are left out (with a note), so a huge run
// cannot make report.html too big for a browser to open (base64 adds a third).
constexpr size_t kMaxPictureBytes = size_t{48} << 20;

std::optional<std::string> readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return bytes.str();
}

std::string textOf(const Json& entry, const char* name) {
  const auto it = entry.find(name);
  return it != entry.end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::optional<double> numberOf(const Json& entry, const char* name) {
  const auto it = entry.find(name);
  return it != entry.end() && it->is_number() ? std::optional<double>(it->get<double>())
                                              : std::nullopt;
}

// A PNG of the run folder by its relative path; nullopt (and a note) when it is missing,
// not a PNG, or over the size budget.
std::optional<std::string> readPicture(const std::string& run_dir, const std::string& path,
                                       size_t* bytes_used, report::HtmlAssets* assets) {
  static constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";
  if (path.empty() || path.find("..") != std::string::npos || path.front() == '/') {
    assets->picture_notes.push_back("a picture path \"" + path +
                                    "\" left out (not a file of the run folder)");
    return std::nullopt;
  }
  std::optional<std::string> png = readWholeFile(run_dir + "/" + path);
  if (!png || png->compare(0, kPngSignature.size(), kPngSignature) != 0) {
    assets->picture_notes.push_back(path + " left out: " + (png ? "not a PNG" : "cannot be read"));
    return std::nullopt;
  }
  if (*bytes_used + png->size() > kMaxPictureBytes) {
    assets->picture_notes.push_back(path + " left out: the pictures passed " +
                                    std::to_string(kMaxPictureBytes >> 20) + " MiB");
    return std::nullopt;
  }
  *bytes_used += png->size();
  return png;
}

// What a picture shows, against the error table's hausdorff.
constexpr const char* kPictureMeaning =
    "Each picture: the parametric error |S(u,v) - limit(u,v)| at the vertices of a uniform "
    "tessellation, a triangle coloured by its largest vertex. It is not the error table's "
    "hausdorff: that is the two-sided distance between the whole tessellated surface and the "
    "limit surface (closest points), so a surface exact at its vertices (acc on an all-regular "
    "mesh, about 1e-16) can still have a hausdorff of 1e-3. The wireframes are in the run "
    "folder's pictures/ (left out here to keep the page small).";

// The ok entries of pictures.json ({technique, variant, asset, level, error_png, error_max,
// scale_min, scale_max, error_statistic, [status, reason]}) of one asset as one group: its
// error pictures side by side under the asset's colour scale, stated once.
void addAssetGroup(const std::string& run_dir, const std::string& asset,
                   const std::vector<const Json*>& entries, size_t* bytes_used,
                   report::HtmlAssets* assets) {
  report::HtmlPictureGroup group;
  group.title = asset;
  std::set<double> scales;
  std::optional<double> level;
  bool z_up = false;
  for (const Json* entry : entries) {
    const std::string name = textOf(*entry, "technique") + "/" + textOf(*entry, "variant");
    if (const std::string status = textOf(*entry, "status"); !status.empty() && status != "ok") {
      assets->picture_notes.push_back(name + " on " + asset + ": " + status + ": " +
                                      textOf(*entry, "reason"));
      continue;
    }
    if (const auto scale = numberOf(*entry, "scale_max")) scales.insert(*scale);
    if (!level) level = numberOf(*entry, "level");
    z_up = z_up || textOf(*entry, "up_axis") == "z";
    std::string caption = name;
    if (const auto error_max = numberOf(*entry, "error_max")) {
      caption += fmt::format(": largest vertex error {:.3g} rel_diag", *error_max);
    }
    if (auto png = readPicture(run_dir, textOf(*entry, "error_png"), bytes_used, assets)) {
      group.pictures.push_back({caption, std::move(*png)});
    }
  }
  if (group.pictures.empty()) return;
  if (level) group.note = fmt::format("uniform level {}; ", *level);
  if (z_up) group.note += "a z-up asset, seen with z upwards (the camera turned, not the data); ";
  group.shared_scale = scales.size() == 1;
  group.note += scales.size() == 1
                    ? fmt::format(
                          "one colour scale for every picture of the asset: 0 … {:.3g} "
                          "rel_diag (the largest vertex error among them).",
                          *scales.begin())
                    : std::string("each picture has its own colour scale (its colour bar).");
  assets->pictures.push_back(std::move(group));
}

// What a crack picture shows.
constexpr const char* kCrackPictureMeaning =
    "Each picture: the surface (uniform level 8) shaded grey, with every pair of shared points "
    "that differ in the cracks row named (the CPU float row with the largest gap; report.md's "
    "\"Where the default variants crack\") marked at its midpoint: a strong dot where the "
    "camera sees it, a pale one where it is behind the surface; the largest gap is circled. "
    "The gaps are float round-off (~1e-7 world units): the marks say where, not how wide.";

// The entries of pictures.json with a crack_png, in index order, as one group.
void addCrackGroup(const std::string& run_dir, const std::vector<const Json*>& entries,
                   size_t* bytes_used, report::HtmlAssets* assets) {
  report::HtmlPictureGroup group;
  group.title = "Where the default variants crack";
  group.note = kCrackPictureMeaning;
  for (const Json* entry : entries) {
    const std::string path = textOf(*entry, "crack_png");
    if (path.empty()) continue;
    const std::string caption = fmt::format(
        "{}/{} on {}: {} unequal points ({} seen), {}; largest gap {:.3g} world units",
        textOf(*entry, "technique"), textOf(*entry, "variant"), textOf(*entry, "asset"),
        numberOf(*entry, "crack_points").value_or(0),
        numberOf(*entry, "crack_points_visible").value_or(0), textOf(*entry, "crack_row"),
        numberOf(*entry, "crack_max_gap_world").value_or(0));
    if (auto png = readPicture(run_dir, path, bytes_used, assets)) {
      group.pictures.push_back({caption, std::move(*png)});
    }
  }
  if (!group.pictures.empty()) assets->crack_pictures.push_back(std::move(group));
}

void loadPictures(const std::string& run_dir, report::HtmlAssets* assets) {
  const std::string index_path = run_dir + "/pictures/pictures.json";
  const std::optional<std::string> text = readWholeFile(index_path);
  if (!text) {
    assets->picture_notes.push_back("No pictures: the run folder has no pictures/pictures.json.");
    return;
  }
  const Json index = Json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (!index.is_object() || !index.contains("pictures") || !index["pictures"].is_array()) {
    assets->picture_notes.push_back(
        "No pictures: pictures/pictures.json is not an object with a \"pictures\" list.");
    return;
  }
  if (const std::string status = textOf(index, "status"); !status.empty() && status != "ok") {
    assets->picture_notes.push_back("No pictures: " + status + ": " + textOf(index, "reason"));
  }
  if (const std::string device = textOf(index, "device"); !device.empty()) {
    assets->picture_notes.push_back("Rendered on " + device + ".");
  }
  size_t bytes_used = 0;
  size_t malformed = 0;
  std::vector<std::pair<std::string, std::vector<const Json*>>> by_asset;  // in index order
  std::vector<const Json*> ok_entries;                                     // in index order
  for (const Json& entry : index["pictures"]) {
    if (!entry.is_object() || textOf(entry, "technique").empty() ||
        textOf(entry, "asset").empty()) {
      ++malformed;
      continue;
    }
    const std::string asset = textOf(entry, "asset");
    ok_entries.push_back(&entry);
    auto it = std::find_if(by_asset.begin(), by_asset.end(),
                           [&](const auto& g) { return g.first == asset; });
    if (it == by_asset.end()) it = by_asset.insert(by_asset.end(), {asset, {}});
    it->second.push_back(&entry);
  }
  if (!by_asset.empty()) assets->picture_notes.push_back(kPictureMeaning);
  addCrackGroup(run_dir, ok_entries, &bytes_used, assets);
  for (const auto& [asset, entries] : by_asset)
    addAssetGroup(run_dir, asset, entries, &bytes_used, assets);
  if (malformed > 0) {
    assets->picture_notes.push_back(fmt::format(
        "{} entries of pictures/pictures.json without a technique and asset left out.", malformed));
  }
}

}  // namespace

std::string chartJsPath() {
  const char* path = std::getenv("TESSBENCH_CHARTJS");
  return path != nullptr && *path != '\0' ? std::string(path) : std::string(TB_CHARTJS_PATH);
}

report::HtmlAssets loadHtmlAssets(const std::string& run_dir) {
  report::HtmlAssets assets;
  const std::string path = chartJsPath();
  std::optional<std::string> source = readWholeFile(path);
  if (source && !source->empty()) {
    assets.chartjs_source = std::move(*source);
  } else {
    assets.chartjs_missing_reason =
        path +
        ": cannot read Chart.js (Debian package libjs-chart.js; TESSBENCH_CHARTJS=PATH "
        "names another file)";
  }
  loadPictures(run_dir, &assets);
  return assets;
}

std::string renderRunHtml(const results::Results& results, const std::string& run_dir) {
  const report::HtmlAssets assets = loadHtmlAssets(run_dir);
  if (assets.chartjs_source.empty()) {
    fmt::print(stderr, "tessbench: warning: {}; report.html has no charts\n",
               assets.chartjs_missing_reason);
  }
  return report::renderHtml(results, assets);
}

}  // namespace tb::cli
