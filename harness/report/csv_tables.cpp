#include "harness/report/csv_tables.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "harness/report/summary.h"

namespace tb::report {
namespace {

void appendLine(const std::vector<std::string>& cells, std::string* out) {
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) *out += ',';
    *out += csvCell(cells[i]);
  }
  *out += "\r\n";
}

// The measure's metric names: declared ones in declaration order, then undeclared ones in
// order of appearance.
std::vector<std::string> metricNames(const results::Results& results, const std::string& measure) {
  std::vector<std::string> seen;
  std::set<std::string> emitted;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure) continue;
      for (const results::MetricRow& row : m.rows) {
        for (const results::Metric& metric : row.metrics) {
          if (emitted.insert(metric.name).second) seen.push_back(metric.name);
        }
      }
    }
  }
  std::vector<std::string> names;
  if (const results::MeasureDeclaration* declaration = results.findMeasure(measure)) {
    for (const results::MetricSpec& spec : declaration->metrics) {
      if (emitted.contains(spec.name)) names.push_back(spec.name);
    }
  }
  for (const std::string& name : seen) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::string measureCsv(const results::Results& results, const std::string& measure) {
  std::set<std::string> key_set;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure) continue;
      for (const results::MetricRow& row : m.rows) {
        for (const auto& [key, value] : row.keys) key_set.insert(key);
      }
    }
  }
  const std::vector<std::string> keys(key_set.begin(), key_set.end());
  const std::vector<std::string> metrics = metricNames(results, measure);
  std::vector<std::string> header{"technique", "variant", "asset"};
  header.insert(header.end(), keys.begin(), keys.end());
  header.push_back("status");
  header.push_back("reason");
  for (const std::string& metric : metrics) {
    const std::string unit = unitOf(results, measure, metric);
    header.push_back(unit.empty() ? metric : metric + " [" + unit + "]");
  }
  std::string out;
  appendLine(header, &out);
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure) continue;
      const std::vector<std::string> record_cells{record.technique, record.variant, record.asset};
      if (m.status != results::MeasureStatus::kOk) {
        std::vector<std::string> cells = record_cells;
        cells.resize(cells.size() + keys.size());
        cells.push_back(toString(m.status));
        cells.push_back(m.reason);
        cells.resize(header.size());
        appendLine(cells, &out);
        continue;
      }
      for (const results::MetricRow& row : m.rows) {
        std::vector<std::string> cells = record_cells;
        for (const std::string& key : keys) {
          const auto it = row.keys.find(key);
          cells.push_back(it == row.keys.end() ? "" : it->second);
        }
        cells.push_back(toString(row.status));
        cells.push_back(row.reason);
        for (const std::string& metric : metrics) {
          const auto it = std::find_if(row.metrics.begin(), row.metrics.end(),
                                       [&](const results::Metric& x) { return x.name == metric; });
          cells.push_back(it == row.metrics.end() ? "" : fmt::format("{}", it->value));
        }
        appendLine(cells, &out);
      }
    }
  }
  return out;
}

}  // namespace

std::string csvCell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::vector<std::pair<std::string, std::string>> renderCsvTables(const results::Results& results) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const std::string& measure : measureIds(results)) {
    files.emplace_back("tables/" + measure + ".csv", measureCsv(results, measure));
  }
  std::string warnings;
  std::string notes;
  for (const results::Record& record : results.records) {
    for (const std::string& warning : record.warnings) {
      if (warnings.empty()) appendLine({"technique", "variant", "asset", "warning"}, &warnings);
      appendLine({record.technique, record.variant, record.asset, warning}, &warnings);
    }
    for (const results::MeasureResult& m : record.measures) {
      for (const std::string& note : m.notes) {
        if (notes.empty()) appendLine({"technique", "variant", "asset", "measure", "note"}, &notes);
        appendLine({record.technique, record.variant, record.asset, m.measure, note}, &notes);
      }
    }
  }
  if (!warnings.empty()) files.emplace_back("tables/warnings.csv", warnings);
  std::string skipped;
  for (const results::Skip& skip : results.skipped) {
    if (skipped.empty()) appendLine({"technique", "asset", "reason"}, &skipped);
    appendLine({skip.technique, skip.asset, skip.reason}, &skipped);
  }
  if (!skipped.empty()) files.emplace_back("tables/skipped.csv", skipped);
  if (!notes.empty()) files.emplace_back("tables/record_notes.csv", notes);
  return files;
}

}  // namespace tb::report
