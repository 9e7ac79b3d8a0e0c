#include "harness/report/markdown.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "harness/report/markdown_sections.h"
#include "harness/report/summary.h"
#include "harness/results/device_identity.h"

namespace tb::report {

using namespace markdown_detail;

namespace {

void appendContext(const results::Results& results, std::string* out) {
  const results::RunContext& c = results.context;
  *out += "## Run context\n\n";
  appendHeader(out, {"field", "value"});
  appendRow(out, {"run id", c.run_id});
  appendRow(out, {"date (UTC)", c.date});
  appendRow(out, {"git sha", c.git_sha});
  appendRow(out, {"host", c.host});
  appendRow(out, {"CPU", c.cpu});
  appendRow(out, {"compiler", c.compiler + " (" + c.build_type + ")"});
  appendRow(out, {"Vulkan device", c.vulkan_device.empty() ? "none opened" : c.vulkan_device});
  if (const std::string caveat = results::deviceCaveat(c.vulkan_device); !caveat.empty()) {
    appendRow(out, {"device caveat", caveat});
  }
  for (const auto& [name, version] : c.libraries) appendRow(out, {name, version});
  appendRow(out, {"command", "`" + c.command_line + "`"});
  if (c.shard.count > 0) {
    appendRow(out, {"shard", std::to_string(c.shard.index) + " of " +
                                 std::to_string(c.shard.count) + " (numbered from 0)"});
  }
  for (const results::ShardSource& source : c.merged_from) {
    appendRow(out, {"merged from shard " + std::to_string(source.shard.index) + "/" +
                        std::to_string(source.shard.count),
                    source.folder + " (run " + source.run_id + ", " + source.date + ", " +
                        source.host + ")"});
  }
  *out += "\n";
}

void appendAssets(const results::Results& results, std::string* out) {
  *out += "## Assets\n\n";
  appendHeader(out, {"asset", "faces", "vertices", "faces are", "normals"});
  for (const results::AssetSummary& a : results.assets) {
    appendRow(out, {a.name, std::to_string(a.faces), std::to_string(a.vertices), a.face_kinds,
                    a.normals_computed ? "computed (angle-weighted)" : "from file"});
  }
  *out += "\n";
  for (const results::AssetSummary& a : results.assets) {
    for (const std::string& warning : a.warnings) *out += "- **" + a.name + "**: " + warning + "\n";
  }
  if (std::any_of(results.assets.begin(), results.assets.end(),
                  [](const results::AssetSummary& a) { return !a.warnings.empty(); })) {
    *out += "\n";
  }
}

std::string shortSha(const std::string& sha) { return sha.substr(0, 12); }

}  // namespace

std::string formatBytes(double bytes) {
  static const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int unit = 0;
  while (std::fabs(bytes) >= 1024 && unit < 4) {
    bytes /= 1024;
    ++unit;
  }
  return unit == 0 ? fmt::format("{:.0f} B", bytes) : fmt::format("{:.2f} {}", bytes, kUnits[unit]);
}

std::string formatMetricValue(const results::Metric& metric) {
  if (metric.unit == "bytes") return formatBytes(metric.value);
  if (std::isfinite(metric.value) && metric.value == std::floor(metric.value) &&
      std::fabs(metric.value) < 1e15) {
    return fmt::format("{:.0f}", metric.value);
  }
  return fmt::format("{:.4g}", metric.value);
}

namespace {

// The techniques × assets not measured, a line per technique (the assets by short name, the
// first reason); every refusal with its reason is in tables/skipped.csv.
void appendNotMeasured(const results::Results& results, std::string* out) {
  *out += "## Not measured\n\n";
  appendHeader(out, {"technique", "assets", "reason (the first; every one: `tables/skipped.csv`)"});
  std::vector<std::string> order;
  std::map<std::string, std::vector<const results::Skip*>> by_technique;
  for (const results::Skip& skip : results.skipped) {
    if (!by_technique.count(skip.technique)) order.push_back(skip.technique);
    by_technique[skip.technique].push_back(&skip);
  }
  for (const std::string& technique : order) {
    const std::vector<const results::Skip*>& skips = by_technique[technique];
    std::string assets = std::to_string(skips.size()) + ":";
    for (const results::Skip* skip : skips) {
      assets +=
          (assets.back() == ':' ? " " : ", ") + skip->asset.substr(skip->asset.rfind('/') + 1);
    }
    appendRow(out, {technique, assets, skips.front()->reason});
  }
  *out += "\n";
}

}  // namespace

std::string renderMarkdown(const results::Results& results) {
  const results::RunContext& c = results.context;
  const std::vector<std::string> measures = measureIds(results);
  size_t variants = 0;
  for (const auto& technique : techniquesOf(results)) variants += technique.variants.size();
  std::string out = "# tessbench report\n\n";
  out += fmt::format(
      "Run `{}` of {} · git {} · {} · suite {} · {} records ({} technique variants × {} "
      "assets), {} technique × asset pairs not measured. Every figure is measured by this run; "
      "every row is in `results.json` (schema {}) and `tables/<measure>.csv`, the charts and "
      "pictures in `report.html`.\n\n",
      c.run_id, c.date, shortSha(c.git_sha),
      c.vulkan_device.empty() ? "no Vulkan device" : c.vulkan_device,
      c.selection.suite.empty() ? "default" : c.selection.suite, results.records.size(), variants,
      results.assets.size(), results.skipped.size(), results.schema_version);
  if (const std::string caveat = results::deviceCaveat(c.vulkan_device); !caveat.empty()) {
    out += "The device is " + caveat + ".\n\n";
  }
  const std::vector<AssetDecision> decisions = decideAssets(results);
  appendAnswers(results, decisions, &out);
  appendDecisions(results, decisions, &out);
  appendCrackLocations(results, &out);
  appendSimulations(results, &out);
  appendRegressionScreen(results, measures, &out);
  appendChoiceScreen(results, measures, &out);
  appendPublishingScreen(results, measures, &out);
  out += "## Technique × asset matrices\n\n";
  out +=
      "Each technique's default variant (its first); the worst value over the rows of the "
      "measure's summary scope. n/a: the technique does not take the asset; —: not run.\n\n";
  for (const std::string& measure : measures) appendMatrix(results, measure, &out);
  out += "## Measures\n\n";
  for (const std::string& measure : measures) appendMeasureSection(results, measure, &out);
  appendContext(results, &out);
  appendAssets(results, &out);
  if (!results.skipped.empty()) appendNotMeasured(results, &out);
  size_t warnings = 0;
  size_t records_warned = 0;
  for (const results::Record& record : results.records) {
    warnings += record.warnings.size();
    records_warned += record.warnings.empty() ? 0 : 1;
  }
  if (warnings > 0) {
    out += "## Warnings\n\n";
    constexpr size_t kWarningsShown = 10;
    if (warnings <= kWarningsShown) {
      for (const results::Record& record : results.records) {
        for (const std::string& warning : record.warnings) {
          out += "- " + record.technique + "/" + record.variant + " on " + record.asset + ": " +
                 warning + "\n";
        }
      }
    } else {
      out += fmt::format(
          "{} warnings on {} records (patch statistics and notes of the input): "
          "`tables/warnings.csv`.\n",
          warnings, records_warned);
    }
  }
  return out;
}

}  // namespace tb::report
