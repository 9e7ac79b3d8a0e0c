// The measures' sections of report.md: declaration, summary, rows (markdown_sections.h).
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "harness/report/answers.h"
#include "harness/report/comparison.h"
#include "harness/report/markdown.h"
#include "harness/report/markdown_sections.h"
#include "harness/report/summary.h"

namespace tb::report::markdown_detail {
namespace {

// The measure's metric columns: the declared metrics some row emits, in declared order,
// then any undeclared one (results written without declarations) in order of appearance.
struct Column {
  std::string name;
  std::string header;  // "max_gap_world (world, lower better)"
};

std::string directionLabel(results::Direction direction) {
  switch (direction) {
    case results::Direction::kLowerIsBetter:
      return ", lower better";
    case results::Direction::kHigherIsBetter:
      return ", higher better";
    case results::Direction::kNone:
      return "";
  }
  return "";
}

using RowFilter = bool (*)(const results::MetricRow&);

// The metric columns of the measure's rows that pass `filter`: declared metrics in
// declaration order, then undeclared ones in order of appearance.
std::vector<Column> metricColumns(const results::Results& results, const std::string& measure_id,
                                  const results::MeasureDeclaration* declaration,
                                  RowFilter filter) {
  std::vector<std::string> seen;  // emitted names, in order of appearance
  std::map<std::string, std::string> row_unit;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const results::MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        for (const results::Metric& metric : row.metrics) {
          if (row_unit.emplace(metric.name, metric.unit).second) seen.push_back(metric.name);
        }
      }
    }
  }
  std::vector<Column> columns;
  if (declaration != nullptr) {
    for (const results::MetricSpec& spec : declaration->metrics) {
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

// A RowScope as "policy = *_order_dependent, spacing = integer".
std::string scopeText(const results::RowScope& scope) {
  std::string text;
  for (const auto& [key, value] : scope) text += (text.empty() ? "" : ", ") + key + " = " + value;
  return text;
}

// What the declaration says once for the whole measure: its title, fixed notes, headline
// metrics and the meaning of the units its columns use.
void appendDeclaration(const results::MeasureDeclaration& declaration, std::string* out) {
  if (!declaration.title.empty()) *out += "**" + declaration.title + "**";
  if (!declaration.description.empty()) *out += ": " + declaration.description;
  if (!declaration.title.empty() || !declaration.description.empty()) *out += "\n\n";
  for (const std::string& note : declaration.notes) *out += "- " + note + "\n";
  if (!declaration.control_rows.empty()) {
    *out += "- controls (rows made to show a failure: never recommended, left out of summaries): ";
    for (size_t i = 0; i < declaration.control_rows.size(); ++i) {
      *out += (i > 0 ? "; " : "") + scopeText(declaration.control_rows[i]);
    }
    *out += "\n";
  }
  if (!declaration.headline.empty()) {
    *out += "- headline: ";
    for (size_t i = 0; i < declaration.headline.size(); ++i) {
      *out += (i > 0 ? ", " : "") + declaration.headline[i];
    }
    *out += "\n";
  }
  // Units whose spelling does not already say it all ("count", "bytes", "ratio" do).
  std::vector<results::Unit> units;
  for (const results::MetricSpec& spec : declaration.metrics) {
    if (toString(spec.unit) != results::describe(spec.unit) &&
        std::find(units.begin(), units.end(), spec.unit) == units.end()) {
      units.push_back(spec.unit);
    }
  }
  if (!units.empty()) {
    *out += "- units: ";
    for (size_t i = 0; i < units.size(); ++i) {
      *out += std::string(i > 0 ? "; " : "") + std::string(toString(units[i])) + " = " +
              std::string(results::describe(units[i]));
    }
    *out += "\n";
  }
  *out += "\n";
}

// The notes that belong to one record (e.g. how this asset's patches were sampled),
// each naming its record.
void appendRecordNotes(const results::Results& results, const std::string& measure_id,
                       std::string* out) {
  bool any = false;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
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
void appendTable(const results::Results& results, const std::string& measure_id,
                 const results::MeasureDeclaration* declaration, RowFilter filter,
                 bool with_status_rows, std::string* out) {
  std::vector<std::string> key_names;
  std::set<std::string> seen_keys;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const results::MetricRow& row : m.rows) {
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
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      if (m.status != results::MeasureStatus::kOk) {
        if (!with_status_rows) continue;
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        cells.resize(cells.size() + key_names.size());
        cells.push_back(std::string(toString(m.status)) + ": " + m.reason);
        cells.resize(header.size());
        appendRow(out, cells);
        continue;
      }
      for (const results::MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        for (const std::string& key : key_names) {
          auto it = row.keys.find(key);
          cells.push_back(it == row.keys.end() ? "" : it->second);
        }
        if (row.status != results::MeasureStatus::kOk) {
          cells.push_back(std::string(toString(row.status)) + ": " + row.reason);
          cells.resize(header.size());
          appendRow(out, cells);
          continue;
        }
        const bool control =
            declaration != nullptr && results::isControlRow(*declaration, row.keys);
        cells.push_back(control ? "ok (control)" : "ok");
        for (const Column& column : columns) {
          std::string value;
          for (const results::Metric& metric : row.metrics) {
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

// A comparison's cell: counts (triangles per frame, a mean) as whole numbers (123457, not
// 1.235e+05), the best in bold, "—" for no figure.
std::string comparisonCell(const ComparisonCell& cell, const std::string& unit) {
  if (!cell.value) return "—";
  const std::string figure =
      unit == "count" ? fmt::format("{:.0f}", *cell.value) : formatFigure(*cell.value, unit);
  std::string text = cell.best ? "**" + figure + "**" : figure;
  for (const std::optional<double>& more : cell.more) {
    text += " / " + (more ? fmt::format("{:.6g}", *more) : std::string("—"));
  }
  return text;
}

// The facets' values after the first ("camera_path orbit"): one table each.
std::string tableName(const ComparisonGroup& group) {
  std::string text;
  for (size_t i = 1; i < group.facets.size(); ++i) {
    text += (text.empty() ? "" : ", ") + group.facets[i].first + " " + group.facets[i].second;
  }
  return text;
}

// A table per value of the facets after the first (camera path, spacing): the first facet (the
// asset) its first column, named on its first line; a line per technique; a column one group
// lacks is "—" there. A heading and a header per table, not per asset: report.md stays short.
void appendComparisonTables(const ComparisonTable& table, std::string* out) {
  const bool lead_column = !table.groups.front().facets.empty();
  std::vector<std::string> names;
  for (const ComparisonGroup& g : table.groups) {
    if (std::find(names.begin(), names.end(), tableName(g)) == names.end())
      names.push_back(tableName(g));
  }
  for (const std::string& name : names) {
    std::vector<const ComparisonGroup*> groups;
    std::vector<std::string> keys, extras;  // the columns, in the groups' order
    for (const ComparisonGroup& g : table.groups) {
      if (tableName(g) != name) continue;
      groups.push_back(&g);
      for (size_t i = 0; i < g.columns.size(); ++i) {
        std::vector<std::string>& into = i < g.key_columns ? keys : extras;
        if (std::find(into.begin(), into.end(), g.columns[i]) == into.end())
          into.push_back(g.columns[i]);
      }
    }
    keys.insert(keys.end(), extras.begin(), extras.end());
    if (!name.empty()) *out += "**" + name + "**\n\n";
    std::vector<std::string> header;
    if (lead_column) header.push_back(table.groups.front().facets.front().first);
    header.push_back("technique");
    header.insert(header.end(), keys.begin(), keys.end());
    appendHeader(out, header);
    for (const ComparisonGroup* g : groups) {
      for (size_t l = 0; l < g->lines.size(); ++l) {
        std::vector<std::string> cells;
        if (lead_column) cells.push_back(l == 0 ? g->facets.front().second : "");
        cells.push_back(g->lines[l].technique);
        for (const std::string& column : keys) {
          const auto at = std::find(g->columns.begin(), g->columns.end(), column);
          cells.push_back(
              at == g->columns.end()
                  ? "—"
                  : comparisonCell(g->lines[l].cells[size_t(at - g->columns.begin())], table.unit));
        }
        appendRow(out, cells);
      }
    }
    *out += "\n";
  }
}

// The declared comparisons (comparison.h): the lead line, what the rows are, the tables.
void appendComparisons(const results::Results& results,
                       const results::MeasureDeclaration& declaration, std::string* out) {
  for (const results::ComparisonSpec& spec : declaration.comparisons) {
    const ComparisonTable table = comparisonTable(results, declaration, spec);
    if (table.groups.empty()) continue;
    *out += spec.title + "\n\n";
    std::string rows = "Each technique's default variant";
    if (!spec.where.empty()) rows += ", rows with " + scopeText(spec.where);
    rows += "; the best " + spec.column_key + " in bold; — : no figure";
    if (!spec.valid_flag.empty()) rows += " or " + spec.valid_flag + " = 0";
    if (!table.controls_left_out.empty()) {
      std::string controls;
      for (const std::string& c : table.controls_left_out)
        controls += (controls.empty() ? "" : ", ") + c;
      rows += "; controls left out: " + controls;
    }
    *out += rows + ".\n\n";
    appendComparisonTables(table, out);
  }
}

size_t countRows(const results::Results& results, const std::string& measure_id, RowFilter filter) {
  size_t count = 0;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const results::MetricRow& row : m.rows) count += filter(row) ? 1 : 0;
    }
  }
  return count;
}

// A measure with at most this many rows also gets its detail table in report.md (a small
// run reads whole); a larger one leaves its rows to tables/<measure>.csv and results.json.
constexpr size_t kDetailRowsInReport = 40;

}  // namespace

// A measure's section: its declaration, then one line per technique × variant over every
// asset, each headline metric as median / worst; the rows themselves only when few.
void appendMeasureSection(const results::Results& results, const std::string& measure,
                          std::string* out) {
  const results::MeasureDeclaration* declaration = results.findMeasure(measure);
  *out += "### " + measure + "\n\n";
  if (declaration != nullptr) appendComparisons(results, *declaration, out);
  if (declaration != nullptr) appendDeclaration(*declaration, out);
  if (declaration != nullptr && !declaration->summary_scope.empty()) {
    std::string scope;
    for (const auto& [key, value] : declaration->summary_scope) {
      scope += (scope.empty() ? "" : ", ") + key + " = " + value;
    }
    *out += "Summaries read the rows with " + scope + ".\n\n";
  }
  const MeasureSummary summary =
      summarizeMeasure(results, measure, SummaryGrouping::kAcrossAssets, {},
                       summaryRowsOf(results, measure), /*split_paths=*/true);
  if (const std::string note = summaryRowsNote(results, measure); !note.empty()) {
    *out += "The summary below reads " + note + "; every row is in the CSV.\n\n";
  }
  // The pipeline's path (tessellator | compute) as a column where the measure keys rows by it.
  const bool paths = std::any_of(summary.lines.begin(), summary.lines.end(),
                                 [](const SummaryLine& line) { return !line.path.empty(); });
  std::vector<std::string> header{"technique", "variant"};
  if (paths) header.push_back("path");
  header.push_back("rows");
  for (const std::string& metric : summary.metrics) {
    header.push_back(metricHeader(results, measure, metric) + " median / worst");
  }
  header.push_back("not measured");
  appendHeader(out, header);
  for (const SummaryLine& line : summary.lines) {
    std::vector<std::string> cells{line.technique, line.variant};
    if (paths) cells.push_back(line.path);
    cells.push_back(std::to_string(line.ok_rows));
    for (const std::string& metric : summary.metrics) {
      const MetricStats* stats = line.find(metric);
      if (stats == nullptr) {
        cells.push_back("—");
        continue;
      }
      const std::string unit = unitOf(results, measure, metric);
      cells.push_back(formatFigure(stats->median, unit) + " / " +
                      formatFigure(worstOf(*stats, directionOf(results, measure, metric)), unit));
    }
    std::string status;
    if (line.skipped_rows > 0) status += fmt::format("{} skipped", line.skipped_rows);
    if (line.failed_rows > 0)
      status += fmt::format("{}{} failed", status.empty() ? "" : ", ", line.failed_rows);
    if (!status.empty()) status += ": " + line.first_reason;
    cells.push_back(status);
    appendRow(out, cells);
  }
  *out += "\n";
  const size_t rows = countRows(results, measure, [](const results::MetricRow&) { return true; });
  if (rows <= kDetailRowsInReport) {
    appendTable(
        results, measure, declaration, [](const results::MetricRow&) { return true; }, true, out);
    appendRecordNotes(results, measure, out);
  } else {
    *out += fmt::format("Every row ({}): `tables/{}.csv` and results.json.\n\n", rows, measure);
  }
}

}  // namespace tb::report::markdown_detail
