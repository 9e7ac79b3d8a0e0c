#include "harness/report/plot_data.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <tuple>

#include "harness/report/row_values.h"
#include "harness/report/summary.h"

namespace tb::report {
namespace {

using RecordKey = std::tuple<std::string, std::string, std::string>;  // technique, variant, asset

// "technique", "variant" (technique/variant), "asset", or a row key's value.
std::optional<std::string> axisText(const results::Record& record, const results::MetricRow& row,
                                    const std::string& name) {
  if (name == "technique") return record.technique;
  if (name == "variant") return record.technique + "/" + record.variant;
  if (name == "asset") return record.asset;
  const auto it = row.keys.find(name);
  if (it == row.keys.end()) return std::nullopt;
  return it->second;
}

const results::Metric* findMetric(const results::MetricRow& row, const std::string& name) {
  for (const results::Metric& metric : row.metrics) {
    if (metric.name == name) return &metric;
  }
  return nullptr;
}

std::string withUnit(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " (" + unit + ")";
}

// Where a line or scatter chart's x comes from.
enum class XSource { kNone, kKey, kMetric, kOtherMeasure };

// The other measure's figure per record, when spec.x is "<measure>.<metric>" naming a
// measure of the run.
struct CrossMeasureX {
  std::string measure, metric;
  std::map<RecordKey, double> by_record;
};

std::optional<CrossMeasureX> crossMeasureX(const results::Results& results, const std::string& x) {
  const size_t dot = x.find('.');
  if (dot == std::string::npos) return std::nullopt;
  CrossMeasureX cross{x.substr(0, dot), x.substr(dot + 1), {}};
  const std::vector<std::string> ids = measureIds(results);
  if (std::find(ids.begin(), ids.end(), cross.measure) == ids.end()) return std::nullopt;
  const MeasureSummary summary =
      summarizeMeasure(results, cross.measure, SummaryGrouping::kPerAsset, {cross.metric});
  const results::Direction direction = directionOf(results, cross.measure, cross.metric);
  for (const SummaryLine& line : summary.lines) {
    const MetricStats* stats = line.find(cross.metric);
    if (stats == nullptr || stats->rows == 0) continue;
    cross.by_record[{line.technique, line.variant, line.asset}] = worstOf(*stats, direction);
  }
  return cross;
}

// A point under construction: every y of its rows, reduced by PlotSpec::reduce at the end.
struct PointValues {
  double x = 0;
  std::string category;
  std::string record_label;  // set only when each technique × variant is its own point
  std::vector<std::string> labels;
  std::vector<double> ys;
};

struct SeriesValues {
  std::string name;
  std::vector<PointValues> points;
};

struct ChartValues {
  std::string facet;
  std::vector<std::string> categories;
  std::vector<SeriesValues> series;
};

template <class T, class Pred>
T& findOrAdd(std::vector<T>& items, Pred matches, T fresh) {
  auto it = std::find_if(items.begin(), items.end(), matches);
  if (it != items.end()) return *it;
  items.push_back(std::move(fresh));
  return items.back();
}

std::string joinLabels(const std::vector<std::string>& labels) {
  constexpr size_t kShown = 4;
  std::string text;
  for (size_t i = 0; i < labels.size() && i < kShown; ++i) text += (i == 0 ? "" : ", ") + labels[i];
  if (labels.size() > kShown) text += " and " + std::to_string(labels.size() - kShown) + " more";
  return text;
}

PlotChart finishChart(ChartValues&& values, bool bar, results::PlotReduce reduce) {
  PlotChart chart{std::move(values.facet), std::move(values.categories), {}};
  for (SeriesValues& series : values.series) {
    PlotSeries out{std::move(series.name), {}};
    for (PointValues& p : series.points) {
      PlotPoint point;
      point.x = p.x;
      point.category = std::move(p.category);
      point.label = joinLabels(p.labels);
      point.rows = p.ys.size();
      point.y = reduce == results::PlotReduce::kMax ? *std::max_element(p.ys.begin(), p.ys.end())
                                                    : medianValue(std::move(p.ys));
      out.points.push_back(std::move(point));
    }
    std::stable_sort(out.points.begin(), out.points.end(),
                     [&](const PlotPoint& a, const PlotPoint& b) {
                       if (a.x != b.x) return a.x < b.x;
                       return !bar && a.label < b.label;
                     });
    chart.series.push_back(std::move(out));
  }
  return chart;
}

bool hiddenByLog(const results::PlotSpec& spec, const PlotPoint& point) {
  const bool bar = spec.kind == results::PlotKind::kBar;
  return (spec.log_x && !bar && point.x <= 0) || (spec.log_y && point.y <= 0);
}

// Facets in the order the run lists its assets (results.assets), others after, as met.
void orderFacets(const results::Results& results, std::vector<ChartValues>* charts) {
  auto rank = [&](const ChartValues& chart) {
    for (size_t i = 0; i < results.assets.size(); ++i) {
      if (results.assets[i].name == chart.facet) return i;
    }
    return results.assets.size();
  };
  std::stable_sort(charts->begin(), charts->end(),
                   [&](const ChartValues& a, const ChartValues& b) { return rank(a) < rank(b); });
}

}  // namespace

size_t PlotChart::points() const {
  size_t count = 0;
  for (const PlotSeries& s : series) count += s.points.size();
  return count;
}

std::optional<double> parsePlotNumber(std::string_view text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || ptr != end || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

void markParetoFront(PlotChart* chart, results::Direction y_direction) {
  // better(a, b): y value a is strictly better than b.
  auto better = [&](double a, double b) {
    return y_direction == results::Direction::kHigherIsBetter ? a > b : a < b;
  };
  std::vector<PlotPoint*> points;
  for (PlotSeries& series : chart->series) {
    for (PlotPoint& point : series.points) points.push_back(&point);
  }
  for (PlotPoint* p : points) {
    p->on_front = std::none_of(points.begin(), points.end(), [&](const PlotPoint* q) {
      if (q == p || q->x > p->x || better(p->y, q->y)) return false;
      return q->x < p->x || better(q->y, p->y);
    });
  }
}

namespace {

// Where a row goes on the x axis: a category for bars, a number otherwise (a key, a metric
// of the row, or another measure's figure of the record); neither when the row has none.
struct RowX {
  std::optional<std::string> category;
  std::optional<double> x;
  XSource source = XSource::kNone;
};

RowX rowX(const results::Record& record, const results::MetricRow& row,
          const results::PlotSpec& spec, bool bar, const std::optional<CrossMeasureX>& cross) {
  RowX at;
  if (bar) {
    at.category = axisText(record, row, spec.x);
  } else if (const auto key = row.keys.find(spec.x); key != row.keys.end()) {
    at.x = parsePlotNumber(key->second);
    at.source = XSource::kKey;
  } else if (const results::Metric* metric = findMetric(row, spec.x); metric != nullptr) {
    if (std::isfinite(metric->value)) at.x = metric->value;
    at.source = XSource::kMetric;
  } else if (cross) {
    const auto it = cross->by_record.find({record.technique, record.variant, record.asset});
    if (it != cross->by_record.end() && std::isfinite(it->second)) at.x = it->second;
    at.source = XSource::kOtherMeasure;
  }
  return at;
}

// Adds the row's y value to its facet's chart, series and point.
void addValue(std::vector<ChartValues>* charts, const results::Record& record, RowX at,
              const std::string& facet, const std::string& series, double y) {
  ChartValues& chart = findOrAdd(
      *charts, [&](const ChartValues& c) { return c.facet == facet; }, ChartValues{facet, {}, {}});
  const std::optional<std::string>& category = at.category;
  std::optional<double>& x = at.x;
  if (category && std::find(chart.categories.begin(), chart.categories.end(), *category) ==
                      chart.categories.end()) {
    chart.categories.push_back(*category);
  }
  if (category) {
    x = double(std::find(chart.categories.begin(), chart.categories.end(), *category) -
               chart.categories.begin());
  }
  SeriesValues& line = findOrAdd(
      chart.series, [&](const SeriesValues& s) { return s.name == series; },
      SeriesValues{series, {}});
  const std::string record_label = record.technique + "/" + record.variant;
  const std::string own = at.source == XSource::kOtherMeasure ? record_label : "";
  PointValues& point = findOrAdd(
      line.points, [&](const PointValues& p) { return p.x == *x && p.record_label == own; },
      PointValues{*x, category.value_or(""), own, {}, {}});
  if (std::find(point.labels.begin(), point.labels.end(), record_label) == point.labels.end()) {
    point.labels.push_back(record_label);
  }
  point.ys.push_back(y);
}

// The x axis's label, by where the x values came from.
void labelX(const results::Results& results, const results::MeasureDeclaration& measure,
            const results::PlotSpec& spec, XSource x_source,
            const std::optional<CrossMeasureX>& cross, PlotData* data) {
  switch (x_source) {
    case XSource::kMetric:
      data->x_label = withUnit(spec.x, unitOf(results, measure.measure, spec.x));
      break;
    case XSource::kOtherMeasure:
      data->point_per_variant = true;
      data->x_label = cross->measure + " " +
                      withUnit(cross->metric, unitOf(results, cross->measure, cross->metric));
      break;
    default:
      data->x_label = spec.x;
  }
}

// The charts from their values: facets in order, the ones with too few points dropped,
// the Pareto front marked, the points a log axis hides counted.
void finishCharts(const results::Results& results, const results::PlotSpec& spec, bool bar,
                  std::vector<ChartValues> charts, PlotData* data) {
  if (spec.facet == "asset") orderFacets(results, &charts);
  for (ChartValues& values : charts) {
    PlotChart chart = finishChart(std::move(values), bar, spec.reduce);
    // A facet of one point says nothing a table would not; an unfaceted chart keeps it.
    if (chart.points() < (spec.facet.empty() ? 1u : 2u)) {
      ++data->charts_dropped;
      continue;
    }
    if (spec.pareto_front) markParetoFront(&chart, data->y_direction);
    for (const PlotSeries& series : chart.series) {
      data->points_hidden_by_log +=
          size_t(std::count_if(series.points.begin(), series.points.end(),
                               [&](const PlotPoint& p) { return hiddenByLog(spec, p); }));
    }
    data->charts.push_back(std::move(chart));
  }
}

}  // namespace

PlotData plotData(const results::Results& results, const results::MeasureDeclaration& measure,
                  const results::PlotSpec& spec) {
  PlotData data;
  data.measure = measure.measure;
  data.spec = spec;
  const results::MetricSpec* y_spec = measure.find(spec.y);
  data.y_direction = y_spec != nullptr ? y_spec->direction : results::Direction::kNone;
  data.y_label = withUnit(spec.y, y_spec != nullptr ? std::string(toString(y_spec->unit)) : "");
  const bool bar = spec.kind == results::PlotKind::kBar;
  const std::optional<CrossMeasureX> cross = bar ? std::nullopt : crossMeasureX(results, spec.x);

  XSource x_source = XSource::kNone;
  std::vector<ChartValues> charts;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& result : record.measures) {
      if (result.measure != measure.measure || result.status != results::MeasureStatus::kOk)
        continue;
      for (const results::MetricRow& row : result.rows) {
        if (row.status != results::MeasureStatus::kOk || !results::rowInScope(spec.where, row.keys))
          continue;
        const RowX at = rowX(record, row, spec, bar, cross);
        if (!at.category && !at.x) {
          ++data.rows_without_x;
          continue;
        }
        const results::Metric* y = findMetric(row, spec.y);
        if (y == nullptr || !std::isfinite(y->value)) {
          ++data.rows_without_y;
          continue;
        }
        const std::optional<std::string> series = axisText(record, row, spec.series);
        const std::optional<std::string> facet =
            spec.facet.empty() ? std::optional<std::string>("") : axisText(record, row, spec.facet);
        if (!series || !facet) {
          ++data.rows_without_x;  // no value to place the row by
          continue;
        }
        if (x_source == XSource::kNone) x_source = at.source;
        ++data.rows_used;
        addValue(&charts, record, at, *facet, *series, y->value);
      }
    }
  }
  labelX(results, measure, spec, x_source, cross, &data);
  finishCharts(results, spec, bar, std::move(charts), &data);
  return data;
}

}  // namespace tb::report
