#include "harness/report/comparison.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "harness/report/summary.h"

namespace tb::report {
// A named namespace, not an anonymous one: the unity build puts this file beside others.
namespace comparison_impl {

// One compared row and the record it came from.
struct Compared {
  const results::Record* record;
  const results::MetricRow* row;
};

std::optional<double> metricOf(const results::MetricRow& row, const std::string& name) {
  for (const results::Metric& metric : row.metrics) {
    if (metric.name == name && std::isfinite(metric.value)) return metric.value;
  }
  return std::nullopt;
}

std::string keyOf(const results::MetricRow& row, const std::string& key) {
  const auto it = row.keys.find(key);
  return it == row.keys.end() ? std::string() : it->second;
}

// "asset" is the record's; anything else a row key ("" when the row has none).
std::string facetValue(const Compared& c, const std::string& facet) {
  return facet == "asset" ? c.record->asset : keyOf(*c.row, facet);
}

template <class T>
void addUnique(std::vector<T>* items, const T& item) {
  if (std::find(items->begin(), items->end(), item) == items->end()) items->push_back(item);
}

// The rows a comparison reads (see comparisonTable), control rows' column values noted.
std::vector<Compared> comparedRows(const results::Results& results,
                                   const results::MeasureDeclaration& measure,
                                   const results::ComparisonSpec& spec, ComparisonTable* table) {
  std::map<std::string, std::string> default_variant;
  for (const auto& t : techniquesOf(results)) {
    if (!t.variants.empty()) default_variant[t.technique] = t.variants.front();
  }
  std::vector<Compared> rows;
  for (const results::Record& record : results.records) {
    if (default_variant[record.technique] != record.variant ||
        isControl(results, record.technique, record.variant))
      continue;
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure.measure || m.status != results::MeasureStatus::kOk) continue;
      for (const results::MetricRow& row : m.rows) {
        if (row.status != results::MeasureStatus::kOk ||
            !results::rowInScope(spec.where, row.keys) || !row.keys.contains(spec.column_key))
          continue;
        if (results::isControlRow(measure, row.keys)) {
          addUnique(&table->controls_left_out, keyOf(row, spec.column_key));
          continue;
        }
        rows.push_back({&record, &row});
      }
    }
  }
  return rows;
}

// The declared facets, then every other row key (not the column key, not an ignored key)
// with several values.
std::vector<std::string> facetsOf(const results::ComparisonSpec& spec,
                                  const std::vector<Compared>& rows) {
  std::vector<std::string> facets = spec.facets;
  std::map<std::string, std::set<std::string>> values;
  std::set<std::string> keys;
  for (const Compared& c : rows) {
    for (const auto& [key, value] : c.row->keys) keys.insert(key);
  }
  for (const Compared& c : rows) {
    for (const std::string& key : keys) values[key].insert(keyOf(*c.row, key));
  }
  for (const auto& [key, seen] : values) {
    const auto& ignored = spec.ignore_keys;
    if (seen.size() > 1 && key != spec.column_key &&
        std::find(ignored.begin(), ignored.end(), key) == ignored.end() &&
        std::find(facets.begin(), facets.end(), key) == facets.end()) {
      facets.push_back(key);
    }
  }
  return facets;
}

// One line's cells: each column_key value's figure, then the extras; the best marked.
ComparisonLine lineOf(const results::ComparisonSpec& spec, results::Direction direction,
                      const ComparisonGroup& group, const std::string& technique,
                      const std::vector<const Compared*>& rows) {
  ComparisonLine line{technique, rows.front()->record->variant, {}};
  for (size_t i = 0; i < group.columns.size(); ++i) {
    ComparisonCell cell;
    for (const Compared* c : rows) {
      if (i < group.key_columns) {
        if (keyOf(*c->row, spec.column_key) != group.columns[i]) continue;
        const bool valid =
            spec.valid_flag.empty() || metricOf(*c->row, spec.valid_flag).value_or(1) != 0;
        if (valid) cell.value = metricOf(*c->row, spec.metric);
        for (const std::string& more : spec.cell_metrics) {
          cell.more.push_back(valid ? metricOf(*c->row, more) : std::nullopt);
        }
        break;
      }
      cell.value = metricOf(*c->row, spec.extra_columns[i - group.key_columns].metric);
      if (cell.value) break;
    }
    line.cells.push_back(cell);
  }
  const bool higher = direction == results::Direction::kHigherIsBetter;
  std::optional<double> best;
  for (size_t i = 0; i < group.key_columns; ++i) {
    const auto& v = line.cells[i].value;
    if (v && (!best || (higher ? *v > *best : *v < *best))) best = v;
  }
  // One column: nothing to choose between, nothing in bold.
  if (group.key_columns < 2) return line;
  for (size_t i = 0; i < group.key_columns; ++i)
    line.cells[i].best = best && line.cells[i].value == best;
  return line;
}

// A group's columns (in `order`, only those its rows have) and its lines.
void fillGroup(const results::Results& results, const results::ComparisonSpec& spec,
               results::Direction direction, const std::vector<std::string>& order,
               const std::vector<const Compared*>& rows, ComparisonGroup* group) {
  for (const std::string& column : order) {
    const bool present = std::any_of(rows.begin(), rows.end(), [&](const Compared* c) {
      return keyOf(*c->row, spec.column_key) == column;
    });
    if (present) group->columns.push_back(column);
  }
  group->key_columns = group->columns.size();
  std::vector<results::ComparisonColumn> extras;
  for (const results::ComparisonColumn& extra : spec.extra_columns) {
    const bool present = std::any_of(rows.begin(), rows.end(), [&](const Compared* c) {
      return metricOf(*c->row, extra.metric).has_value();
    });
    if (!present) continue;
    group->columns.push_back(extra.label);
    extras.push_back(extra);
  }
  results::ComparisonSpec kept = spec;  // the extra columns this group shows
  kept.extra_columns = extras;
  for (const auto& t : techniquesOf(results)) {
    std::vector<const Compared*> own;
    for (const Compared* c : rows) {
      if (c->record->technique == t.technique) own.push_back(c);
    }
    if (!own.empty()) group->lines.push_back(lineOf(kept, direction, *group, t.technique, own));
  }
}

size_t assetRank(const results::Results& results, const ComparisonGroup& group) {
  for (const auto& [facet, value] : group.facets) {
    if (facet != "asset") continue;
    for (size_t i = 0; i < results.assets.size(); ++i) {
      if (results.assets[i].name == value) return i;
    }
  }
  return results.assets.size();
}

}  // namespace comparison_impl

std::string ComparisonGroup::name() const {
  std::string text;
  for (const auto& [facet, value] : facets) {
    text += (text.empty() ? "" : ", ") + (facet == "asset" ? value : facet + " " + value);
  }
  return text;
}

ComparisonTable comparisonTable(const results::Results& results,
                                const results::MeasureDeclaration& measure,
                                const results::ComparisonSpec& spec) {
  using namespace comparison_impl;
  ComparisonTable table;
  table.measure = measure.measure;
  table.spec = spec;
  if (const results::MetricSpec* metric = measure.find(spec.metric)) {
    table.unit = std::string(toString(metric->unit));
    table.direction = metric->direction;
  }
  const std::vector<Compared> rows = comparedRows(results, measure, spec, &table);
  table.rows_used = rows.size();
  const std::vector<std::string> facets = facetsOf(spec, rows);
  std::vector<std::string> order;  // column_key values, first seen first
  std::vector<std::vector<std::string>> group_keys;
  std::vector<std::vector<const Compared*>> group_rows;
  for (const Compared& c : rows) {
    addUnique(&order, keyOf(*c.row, spec.column_key));
    std::vector<std::string> key;
    for (const std::string& facet : facets) key.push_back(facetValue(c, facet));
    const auto it = std::find(group_keys.begin(), group_keys.end(), key);
    if (it == group_keys.end()) {
      group_keys.push_back(key);
      group_rows.push_back({&c});
    } else {
      group_rows[size_t(it - group_keys.begin())].push_back(&c);
    }
  }
  for (size_t g = 0; g < group_keys.size(); ++g) {
    ComparisonGroup group;
    for (size_t f = 0; f < facets.size(); ++f)
      group.facets.push_back({facets[f], group_keys[g][f]});
    fillGroup(results, spec, table.direction, order, group_rows[g], &group);
    table.groups.push_back(std::move(group));
  }
  std::stable_sort(table.groups.begin(), table.groups.end(),
                   [&](const ComparisonGroup& a, const ComparisonGroup& b) {
                     return assetRank(results, a) < assetRank(results, b);
                   });
  return table;
}

PlotData comparisonPlot(const ComparisonTable& table) {
  PlotData data;
  data.measure = table.measure;
  data.spec.title = table.spec.title;
  data.spec.kind = results::PlotKind::kBar;
  data.spec.x = "technique";
  data.spec.y = table.spec.metric;
  data.spec.series = table.spec.column_key;
  data.spec.where = table.spec.where;
  data.x_label = "technique (default variant)";
  data.y_label =
      table.unit.empty() ? table.spec.metric : table.spec.metric + " (" + table.unit + ")";
  data.y_direction = table.direction;
  data.rows_used = table.rows_used;
  std::string where;
  for (const auto& [key, value] : table.spec.where)
    where += (where.empty() ? "" : ", ") + key + " = " + value;
  std::string extras;
  for (const results::ComparisonColumn& c : table.spec.extra_columns)
    extras += ", " + c.label + " (" + c.metric + ")";
  std::string controls;
  for (const std::string& c : table.controls_left_out)
    controls += (controls.empty() ? "" : ", ") + c;
  data.note = std::to_string(table.rows_used) + " rows of each technique's default variant" +
              (where.empty() ? "" : " with " + where) + "; a bar per " + table.spec.column_key +
              extras + (controls.empty() ? "" : "; controls left out: " + controls) +
              "; no bar: no figure" +
              (table.spec.valid_flag.empty() ? "" : " or " + table.spec.valid_flag + " = 0") + ".";
  for (const ComparisonGroup& group : table.groups) {
    PlotChart chart;
    chart.facet = group.name();
    for (const ComparisonLine& line : group.lines) chart.categories.push_back(line.technique);
    for (size_t i = 0; i < group.columns.size(); ++i) {
      PlotSeries series{group.columns[i], {}};
      for (size_t l = 0; l < group.lines.size(); ++l) {
        const ComparisonCell& cell = group.lines[l].cells[i];
        if (!cell.value) continue;
        PlotPoint point;
        point.x = double(l);
        point.y = *cell.value;
        point.category = group.lines[l].technique;
        point.label = group.lines[l].technique + "/" + group.lines[l].variant;
        point.rows = 1;
        series.points.push_back(std::move(point));
      }
      chart.series.push_back(std::move(series));
    }
    data.charts.push_back(std::move(chart));
  }
  return data;
}

}  // namespace tb::report
