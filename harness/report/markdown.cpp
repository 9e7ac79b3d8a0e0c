#include "harness/report/markdown.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace tb {
namespace {

std::string escapeCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

void appendRow(std::string* out, const std::vector<std::string>& cells) {
  *out += "|";
  for (const auto& cell : cells) {
    // Appended piece by piece: `" " + escapeCell(cell) + " |"` trips GCC 12's -Wrestrict.
    *out += ' ';
    *out += escapeCell(cell);
    *out += " |";
  }
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
  if (c.shard.count > 0) {
    appendRow(out, {"shard", std::to_string(c.shard.index) + " of " +
                                 std::to_string(c.shard.count) + " (numbered from 0)"});
  }
  for (const ShardSource& source : c.merged_from) {
    appendRow(out, {"merged from shard " + std::to_string(source.shard.index) + "/" +
                        std::to_string(source.shard.count),
                    source.folder + " (run " + source.run_id + ", " + source.date + ", " +
                        source.host + ")"});
  }
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

// The measure's metric columns: the declared metrics some row emits, in declared order,
// then any undeclared one (results written without declarations) in order of appearance.
struct Column {
  std::string name;
  std::string header;  // "max_gap_world (world, lower better)"
};

std::string directionLabel(Direction direction) {
  switch (direction) {
    case Direction::kLowerIsBetter:
      return ", lower better";
    case Direction::kHigherIsBetter:
      return ", higher better";
    case Direction::kNone:
      return "";
  }
  return "";
}

// Rows that carry this key are a measure's summary (e.g. adaptivity's triangles at 1 px):
// rendered first, in their own table, before the declaration and the detail rows.
constexpr const char* kSummaryRowKey = "summary";

bool isSummaryRow(const MetricRow& row) { return row.keys.contains(kSummaryRowKey); }

using RowFilter = bool (*)(const MetricRow&);

// The metric columns of the measure's rows that pass `filter`: declared metrics in
// declaration order, then undeclared ones in order of appearance.
std::vector<Column> metricColumns(const Results& results, const std::string& measure_id,
                                  const MeasureDeclaration* declaration, RowFilter filter) {
  std::vector<std::string> seen;  // emitted names, in order of appearance
  std::map<std::string, std::string> row_unit;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        for (const Metric& metric : row.metrics) {
          if (row_unit.emplace(metric.name, metric.unit).second) seen.push_back(metric.name);
        }
      }
    }
  }
  std::vector<Column> columns;
  if (declaration != nullptr) {
    for (const MetricSpec& spec : declaration->metrics) {
      if (!row_unit.contains(spec.name)) continue;
      columns.push_back({spec.name, spec.name + " (" + std::string(toString(spec.unit)) +
                                        directionLabel(spec.direction) + ")"});
    }
  }
  for (const std::string& name : seen) {
    if (declaration != nullptr && declaration->find(name) != nullptr) continue;
    columns.push_back({name, name + " (" + row_unit[name] + ")"});
  }
  return columns;
}

// What the declaration says once for the whole measure: its title, fixed notes, headline
// metrics and the meaning of the units its columns use.
void appendDeclaration(const MeasureDeclaration& declaration, std::string* out) {
  if (!declaration.title.empty()) *out += "**" + declaration.title + "**";
  if (!declaration.description.empty()) *out += ": " + declaration.description;
  if (!declaration.title.empty() || !declaration.description.empty()) *out += "\n\n";
  for (const std::string& note : declaration.notes) *out += "- " + note + "\n";
  if (!declaration.headline.empty()) {
    *out += "- headline: ";
    for (size_t i = 0; i < declaration.headline.size(); ++i) {
      *out += (i > 0 ? ", " : "") + declaration.headline[i];
    }
    *out += "\n";
  }
  // Units whose spelling does not already say it all ("count", "bytes", "ratio" do).
  std::vector<Unit> units;
  for (const MetricSpec& spec : declaration.metrics) {
    if (toString(spec.unit) != describe(spec.unit) &&
        std::find(units.begin(), units.end(), spec.unit) == units.end()) {
      units.push_back(spec.unit);
    }
  }
  if (!units.empty()) {
    *out += "- units: ";
    for (size_t i = 0; i < units.size(); ++i) {
      *out += std::string(i > 0 ? "; " : "") + std::string(toString(units[i])) + " = " +
              std::string(describe(units[i]));
    }
    *out += "\n";
  }
  *out += "\n";
}

// The notes that belong to one record (e.g. how this asset's patches were sampled),
// each naming its record.
void appendRecordNotes(const Results& results, const std::string& measure_id, std::string* out) {
  bool any = false;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const std::string& note : m.notes) {
        if (!any) *out += "Notes per record:\n\n";
        any = true;
        *out += "- " + record.technique + "/" + record.variant + " on " + record.asset + ": " +
                note + "\n";
      }
    }
  }
  if (any) *out += "\n";
}

// One table of the measure's rows that pass `filter`: a line per row, a column per key and
// metric. Records whose measure did not run are listed when `with_status_rows`.
void appendTable(const Results& results, const std::string& measure_id,
                 const MeasureDeclaration* declaration, RowFilter filter, bool with_status_rows,
                 std::string* out) {
  std::vector<std::string> key_names;
  std::set<std::string> seen_keys;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        for (const auto& [key, value] : row.keys) {
          if (seen_keys.insert(key).second) key_names.push_back(key);
        }
      }
    }
  }
  const std::vector<Column> columns = metricColumns(results, measure_id, declaration, filter);
  std::vector<std::string> header{"technique", "variant", "asset"};
  header.insert(header.end(), key_names.begin(), key_names.end());
  header.push_back("status");
  for (const Column& column : columns) header.push_back(column.header);
  appendHeader(out, header);
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      if (m.status != MeasureStatus::kOk) {
        if (!with_status_rows) continue;
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        cells.resize(cells.size() + key_names.size());
        cells.push_back(std::string(toString(m.status)) + ": " + m.reason);
        cells.resize(header.size());
        appendRow(out, cells);
        continue;
      }
      for (const MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        for (const std::string& key : key_names) {
          auto it = row.keys.find(key);
          cells.push_back(it == row.keys.end() ? "" : it->second);
        }
        if (row.status != MeasureStatus::kOk) {
          cells.push_back(std::string(toString(row.status)) + ": " + row.reason);
          cells.resize(header.size());
          appendRow(out, cells);
          continue;
        }
        cells.push_back("ok");
        for (const Column& column : columns) {
          std::string value;
          for (const Metric& metric : row.metrics) {
            if (metric.name == column.name) value = formatMetricValue(metric);
          }
          cells.push_back(value);
        }
        appendRow(out, cells);
      }
    }
  }
  *out += "\n";
}

bool anyRow(const Results& results, const std::string& measure_id, RowFilter filter) {
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) {
        if (filter(row)) return true;
      }
    }
  }
  return false;
}

size_t countRows(const Results& results, const std::string& measure_id, RowFilter filter) {
  size_t count = 0;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) count += filter(row) ? 1 : 0;
    }
  }
  return count;
}

// Under a summary, more detail rows than this stay in results.json only.
constexpr size_t kDetailRowsShownUnderSummary = 400;

// One section per measure: its summary rows first (rows keyed `summary`), then the
// declaration, then a table of the other rows (left to results.json when a summary
// aggregates more than kDetailRowsShownUnderSummary of them).
void appendMeasure(const Results& results, const std::string& measure_id, std::string* out) {
  const MeasureDeclaration* declaration = results.findMeasure(measure_id);
  *out += "## Measure: " + measure_id + "\n\n";
  const RowFilter detail = [](const MetricRow& row) { return !isSummaryRow(row); };
  const bool summary = anyRow(results, measure_id, isSummaryRow);
  const size_t detail_rows = countRows(results, measure_id, detail);
  const bool detail_shown = !summary || detail_rows <= kDetailRowsShownUnderSummary;
  if (summary) appendTable(results, measure_id, declaration, isSummaryRow, !detail_shown, out);
  if (declaration != nullptr) appendDeclaration(*declaration, out);
  if (detail_shown) {
    appendTable(results, measure_id, declaration, detail, true, out);
  } else {
    *out += fmt::format(
        "The {} detail rows (per frame, policy and the other keys) are in results.json; the "
        "summary table above aggregates them.\n\n",
        detail_rows);
  }
  appendRecordNotes(results, measure_id, out);
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
    for (const Skip& skip : results.skipped)
      appendRow(&out, {skip.technique, skip.asset, skip.reason});
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
