#include "harness/report/markdown.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace tb {
namespace {

std::string escapeCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

void appendRow(std::string* out, const std::vector<std::string>& cells) {
  *out += "|";
  for (const auto& cell : cells) *out += " " + escapeCell(cell) + " |";
  *out += "\n";
}

void appendHeader(std::string* out, const std::vector<std::string>& cells) {
  appendRow(out, cells);
  *out += "|";
  for (size_t i = 0; i < cells.size(); ++i) *out += "---|";
  *out += "\n";
}

void appendContext(const Results& results, std::string* out) {
  const RunContext& c = results.context;
  *out += "## Run\n\n";
  appendHeader(out, {"field", "value"});
  appendRow(out, {"run id", c.run_id});
  appendRow(out, {"date (UTC)", c.date});
  appendRow(out, {"git sha", c.git_sha});
  appendRow(out, {"host", c.host});
  appendRow(out, {"CPU", c.cpu});
  appendRow(out, {"compiler", c.compiler + " (" + c.build_type + ")"});
  appendRow(out, {"Vulkan device", c.vulkan_device.empty() ? "none opened" : c.vulkan_device});
  for (const auto& [name, version] : c.libraries) appendRow(out, {name, version});
  appendRow(out, {"command", "`" + c.command_line + "`"});
  *out += "\n";
}

void appendAssets(const Results& results, std::string* out) {
  *out += "## Assets\n\n";
  appendHeader(out, {"asset", "faces", "vertices", "faces are", "normals"});
  for (const AssetSummary& a : results.assets) {
    appendRow(out, {a.name, std::to_string(a.faces), std::to_string(a.vertices), a.face_kinds,
                    a.normals_computed ? "computed (angle-weighted)" : "from file"});
  }
  *out += "\n";
}

// One table per measure: a line per record row, a column per metric.
void appendMeasure(const Results& results, const std::string& measure_id, std::string* out) {
  std::vector<std::string> key_names, metric_headers;
  std::vector<std::string> metric_names;
  std::set<std::string> seen_keys;
  std::vector<std::string> notes;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      if (notes.empty()) notes = m.notes;
      for (const MetricRow& row : m.rows) {
        for (const auto& [key, value] : row.keys) {
          if (seen_keys.insert(key).second) key_names.push_back(key);
        }
        if (metric_names.empty()) {
          for (const Metric& metric : row.metrics) {
            metric_names.push_back(metric.name);
            metric_headers.push_back(metric.name + " (" + metric.unit + ")");
          }
        }
      }
    }
  }
  *out += "## Measure: " + measure_id + "\n\n";
  for (const std::string& note : notes) *out += "- " + note + "\n";
  if (!notes.empty()) *out += "\n";
  std::vector<std::string> header{"technique", "variant", "asset"};
  header.insert(header.end(), key_names.begin(), key_names.end());
  header.push_back("status");
  header.insert(header.end(), metric_headers.begin(), metric_headers.end());
  appendHeader(out, header);
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      if (m.status != MeasureStatus::kOk) {
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        cells.resize(cells.size() + key_names.size());
        cells.push_back(std::string(toString(m.status)) + ": " + m.reason);
        cells.resize(header.size());
        appendRow(out, cells);
        continue;
      }
      for (const MetricRow& row : m.rows) {
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        for (const std::string& key : key_names) {
          auto it = row.keys.find(key);
          cells.push_back(it == row.keys.end() ? "" : it->second);
        }
        cells.push_back("ok");
        for (const std::string& name : metric_names) {
          std::string value;
          for (const Metric& metric : row.metrics) {
            if (metric.name == name) value = formatMetricValue(metric);
          }
          cells.push_back(value);
        }
        appendRow(out, cells);
      }
    }
  }
  *out += "\n";
}

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

std::string formatMetricValue(const Metric& metric) {
  if (metric.unit == "bytes") return formatBytes(metric.value);
  if (std::isfinite(metric.value) && metric.value == std::floor(metric.value) &&
      std::fabs(metric.value) < 1e15) {
    return fmt::format("{:.0f}", metric.value);
  }
  return fmt::format("{:.4g}", metric.value);
}

std::string renderMarkdown(const Results& results) {
  std::string out = "# tessbench report\n\n";
  out += "Rendered from results.json (schema " + std::to_string(results.schema_version) +
         "). Every figure below is measured by this run.\n\n";
  appendContext(results, &out);
  appendAssets(results, &out);
  std::vector<std::string> measure_ids;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (std::find(measure_ids.begin(), measure_ids.end(), m.measure) == measure_ids.end()) {
        measure_ids.push_back(m.measure);
      }
    }
  }
  std::sort(measure_ids.begin(), measure_ids.end());
  for (const std::string& id : measure_ids) appendMeasure(results, id, &out);
  if (!results.skipped.empty()) {
    out += "## Not measured\n\n";
    appendHeader(&out, {"technique", "asset", "reason"});
    for (const Skip& skip : results.skipped) appendRow(&out, {skip.technique, skip.asset, skip.reason});
    out += "\n";
  }
  bool any_warning = false;
  for (const Record& record : results.records) {
    for (const std::string& warning : record.warnings) {
      if (!any_warning) {
        out += "## Warnings\n\n";
        any_warning = true;
      }
      out += "- " + record.technique + "/" + record.variant + " on " + record.asset + ": " +
             warning + "\n";
    }
  }
  return out;
}

}  // namespace tb
