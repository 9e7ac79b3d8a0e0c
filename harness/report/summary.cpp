#include "harness/report/summary.h"

#include <algorithm>
#include <tuple>

namespace tb::report {
namespace {

MetricStats statsOf(std::vector<double> values) {
  MetricStats stats;
  stats.rows = values.size();
  if (values.empty()) return stats;
  std::sort(values.begin(), values.end());
  stats.min = values.front();
  stats.max = values.back();
  const size_t mid = values.size() / 2;
  stats.median = values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
  return stats;
}

// A line under construction: every value of each metric, to reduce at the end.
struct LineValues {
  SummaryLine line;
  std::map<std::string, std::vector<double>> values;
};

// The row's path key ("" when the measure has none).
std::string pathKeyOf(const results::MetricRow& row) {
  const auto it = row.keys.find("path");
  return it == row.keys.end() ? std::string() : it->second;
}

void noteReason(SummaryLine* line, const std::string& reason) {
  if (line->first_reason.empty()) line->first_reason = reason;
}

}  // namespace

double worstOf(const MetricStats& stats, results::Direction direction) {
  switch (direction) {
    case results::Direction::kLowerIsBetter:
      return stats.max;
    case results::Direction::kHigherIsBetter:
      return stats.min;
    case results::Direction::kNone:
      return stats.median;
  }
  return stats.median;
}

const MetricStats* SummaryLine::find(const std::string& metric) const {
  const auto it = stats.find(metric);
  return it == stats.end() ? nullptr : &it->second;
}

MeasureSummary summarizeMeasure(const results::Results& results, const std::string& measure,
                                SummaryGrouping grouping, const std::vector<std::string>& metrics,
                                const std::function<bool(const results::MetricRow&)>& keep,
                                bool split_paths) {
  MeasureSummary summary;
  summary.measure = measure;
  summary.declaration = results.findMeasure(measure);
  summary.metrics = metrics;
  if (summary.metrics.empty() && summary.declaration != nullptr) {
    summary.metrics = summary.declaration->headline;
  }
  const bool every_metric = summary.metrics.empty();
  const results::RowScope scope =
      summary.declaration != nullptr ? summary.declaration->summary_scope : results::RowScope{};

  std::vector<LineValues> lines;
  std::map<std::tuple<std::string, std::string, std::string, std::string>, size_t> line_index;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure) continue;
      const std::string asset = grouping == SummaryGrouping::kPerAsset ? record.asset : "";
      // The line of (this record, path): rows keyed by path split a record's line.
      const auto lineOf = [&](std::string path) -> LineValues& {
        if (!split_paths) path.clear();
        const auto key = std::make_tuple(record.technique, record.variant, asset, path);
        auto [it, added] = line_index.emplace(key, lines.size());
        if (added) {
          lines.emplace_back();
          lines.back().line.technique = record.technique;
          lines.back().line.variant = record.variant;
          lines.back().line.asset = asset;
          lines.back().line.path = path;
        }
        return lines[it->second];
      };
      const std::string first_path = m.rows.empty() ? std::string() : pathKeyOf(m.rows.front());
      if (m.status != results::MeasureStatus::kOk) {
        LineValues& target = lineOf(first_path);
        (m.status == results::MeasureStatus::kSkipped ? target.line.skipped_rows
                                                      : target.line.failed_rows)++;
        noteReason(&target.line, m.reason);
        continue;
      }
      lineOf(first_path);  // the record's first line, even when no row is in scope
      for (const results::MetricRow& row : m.rows) {
        LineValues& target = lineOf(pathKeyOf(row));
        if (row.status != results::MeasureStatus::kOk) {
          (row.status == results::MeasureStatus::kSkipped ? target.line.skipped_rows
                                                          : target.line.failed_rows)++;
          noteReason(&target.line, row.reason);
          continue;
        }
        if (!results::rowInScope(scope, row.keys) || (keep && !keep(row))) continue;
        if (summary.declaration != nullptr && results::isControlRow(*summary.declaration, row.keys))
          continue;  // made to fail: never part of a figure that ranks
        ++target.line.ok_rows;
        for (const results::Metric& metric : row.metrics) {
          const bool listed = std::find(summary.metrics.begin(), summary.metrics.end(),
                                        metric.name) != summary.metrics.end();
          if (!listed && !every_metric) continue;
          if (!listed) summary.metrics.push_back(metric.name);  // in order of appearance
          target.values[metric.name].push_back(metric.value);
        }
      }
    }
  }
  for (LineValues& values : lines) {
    for (auto& [name, list] : values.values) values.line.stats[name] = statsOf(std::move(list));
    summary.lines.push_back(std::move(values.line));
  }
  return summary;
}

std::vector<std::string> measureIds(const results::Results& results) {
  std::vector<std::string> ids;
  for (const results::MeasureDeclaration& declaration : results.measures)
    ids.push_back(declaration.measure);
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (std::find(ids.begin(), ids.end(), m.measure) == ids.end()) ids.push_back(m.measure);
    }
  }
  return ids;
}

std::vector<results::RunSelection::TechniqueVariants> techniquesOf(
    const results::Results& results) {
  std::vector<results::RunSelection::TechniqueVariants> techniques =
      results.context.selection.techniques;
  for (const results::Record& record : results.records) {
    auto it = std::find_if(techniques.begin(), techniques.end(),
                           [&](const auto& t) { return t.technique == record.technique; });
    if (it == techniques.end()) {
      techniques.push_back({record.technique, {}});
      it = techniques.end() - 1;
    }
    if (std::find(it->variants.begin(), it->variants.end(), record.variant) == it->variants.end()) {
      it->variants.push_back(record.variant);
    }
  }
  return techniques;
}

bool isControl(const results::Results& results, const std::string& technique,
               const std::string& variant) {
  for (const auto& t : results.context.selection.techniques) {
    if (t.technique == technique) {
      return std::find(t.controls.begin(), t.controls.end(), variant) != t.controls.end();
    }
  }
  return false;
}

results::Direction directionOf(const results::Results& results, const std::string& measure,
                               const std::string& metric) {
  const results::MeasureDeclaration* declaration = results.findMeasure(measure);
  const results::MetricSpec* spec = declaration != nullptr ? declaration->find(metric) : nullptr;
  return spec != nullptr ? spec->direction : results::Direction::kNone;
}

std::string unitOf(const results::Results& results, const std::string& measure,
                   const std::string& metric) {
  const results::MeasureDeclaration* declaration = results.findMeasure(measure);
  const results::MetricSpec* spec = declaration != nullptr ? declaration->find(metric) : nullptr;
  return spec != nullptr ? std::string(toString(spec->unit)) : std::string();
}

}  // namespace tb::report
