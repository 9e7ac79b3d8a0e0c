#include "harness/history/history_series.h"

#include <algorithm>
#include <cassert>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "harness/results/results_json.h"
#include "harness/results/timing_compare.h"

namespace tb::history {
namespace {

using Json = nlohmann::ordered_json;

RunContent loadContent(Database& db, int64_t run) {
  RunContent content;
  Statement header = db.prepare("SELECT header, timings FROM runs WHERE id = ?");
  header.bind(1, run);
  if (!header.step()) throw HistoryError(db.path() + ": no run " + std::to_string(run));
  Json document = Json::parse(header.text(0));
  document["records"] = Json::array();
  content.declarations = results::resultsFromJson(document).measures;
  if (!header.isNull(1)) content.timings.emplace();
  Statement query = db.prepare(
      "SELECT r.technique, r.variant, r.asset, r.parameters, mr.measure, mr.payload FROM "
      "measure_results AS mr JOIN records AS r ON r.run = mr.run AND r.ord = mr.ord WHERE "
      "mr.run = ? ORDER BY mr.ord, mr.position");
  query.bind(1, run);
  while (query.step()) {
    content.results.push_back({query.text(0), query.text(1), query.text(2), query.text(3),
                               query.text(4), query.integer(5)});
  }
  if (content.timings) {
    Statement timings = db.prepare(
        "SELECT technique, variant, asset, measure, samples FROM timings WHERE run = ? ORDER "
        "BY position");
    timings.bind(1, run);
    while (timings.step()) {
      content.timings->measures.push_back(
          {timings.text(0), timings.text(1), timings.text(2), timings.text(3),
           Json::parse(timings.text(4)).get<std::vector<double>>()});
    }
  }
  return content;
}

// Worse of two figures by the metric's direction (the larger when it has none).
bool worse(double a, double b, results::Direction direction) {
  return direction == results::Direction::kHigherIsBetter ? a < b : a > b;
}

// An asset's figure: the worst of the ok rows in the measure's summary scope, its control
// rows left out (as in report.md's summaries).
std::optional<double> assetFigure(const results::MeasureResult& result,
                                  const results::MeasureDeclaration& declaration,
                                  const results::MetricSpec& spec) {
  std::optional<double> figure;
  if (result.status != results::MeasureStatus::kOk) return figure;
  for (const results::MetricRow& row : result.rows) {
    if (row.status != results::MeasureStatus::kOk ||
        !results::rowInScope(declaration.summary_scope, row.keys) ||
        results::isControlRow(declaration, row.keys))
      continue;
    for (const results::Metric& metric : row.metrics) {
      if (metric.name != spec.name || std::isnan(metric.value)) continue;
      if (!figure || worse(metric.value, *figure, spec.direction)) figure = metric.value;
    }
  }
  return figure;
}

double aggregate(std::vector<double> values, Aggregate how, results::Direction direction) {
  assert(!values.empty());
  if (how == Aggregate::kMedian) return results::medianOf(std::move(values));
  double result = values.front();
  for (double v : values)
    if (worse(v, result, direction)) result = v;
  return result;
}

const results::MeasureDeclaration* latestDeclaration(const std::vector<RunContent>& runs,
                                                     const std::string& measure) {
  for (auto run = runs.rbegin(); run != runs.rend(); ++run) {
    for (const results::MeasureDeclaration& d : run->declarations)
      if (d.measure == measure) return &d;
  }
  return nullptr;
}

// Per line name, per run: the figures of its assets.
using LineValues = std::map<std::string, std::map<size_t, std::vector<double>>>;

std::string lineName(const std::string& series, const std::string& asset,
                     const ReportOptions& options) {
  return options.assets.empty() ? series : series + " " + asset;
}

void addChart(size_t group, const std::string& measure, const std::string& metric, std::string unit,
              std::string direction, const LineValues& lines, results::Direction sense,
              const ReportOptions& options, HistoryView* view) {
  Chart chart{group, measure, metric, std::move(unit), std::move(direction), {}};
  for (const auto& [name, per_run] : lines) {
    ChartSeries series;
    series.name = name;
    series.series = name.substr(0, name.find(' '));
    if (!options.assets.empty()) series.asset = name.substr(name.find(' ') + 1);
    for (const auto& [run, values] : per_run)
      series.points.push_back({run, aggregate(values, options.aggregate, sense)});
    chart.series.push_back(std::move(series));
  }
  if (!chart.series.empty()) view->charts.push_back(std::move(chart));
}

void metricCharts(size_t group, const std::vector<RunContent>& runs,
                  const results::MeasureDeclaration& declaration, const ReportOptions& options,
                  PayloadCache& payloads, HistoryView* view) {
  for (const std::string& headline : declaration.headline) {
    const results::MetricSpec* spec = declaration.find(headline);
    if (spec == nullptr) continue;
    LineValues lines;
    for (size_t run = 0; run < runs.size(); ++run) {
      for (const StoredResult& stored : runs[run].results) {
        if (stored.measure != declaration.measure || !assetPicked(options.assets, stored.asset))
          continue;
        const std::string series = stored.technique + "/" + stored.variant;
        const auto figure = assetFigure(payloads.get(stored.payload), declaration, *spec);
        if (figure) lines[lineName(series, stored.asset, options)][run].push_back(*figure);
      }
    }
    addChart(group, declaration.measure, spec->name, std::string(results::toString(spec->unit)),
             std::string(results::toString(spec->direction)), lines, spec->direction, options,
             view);
  }
}

// A measure with a shader-db summary (MeasureDeclaration::shader_db): per metric of the
// summary, a line per group value (a GPU family) through the total over every program.
void shaderDbCharts(size_t group, const std::vector<RunContent>& runs,
                    const results::MeasureDeclaration& declaration, PayloadCache& payloads,
                    HistoryView* view) {
  const results::ShaderDbSpec& db = declaration.shader_db;
  if (db.group_key.empty()) return;
  for (const std::string& metric : db.metrics) {
    const results::MetricSpec* spec = declaration.find(metric);
    if (spec == nullptr) continue;
    LineValues lines;
    for (size_t run = 0; run < runs.size(); ++run) {
      std::map<std::string, double> totals;
      for (const StoredResult& stored : runs[run].results) {
        if (stored.measure != declaration.measure) continue;
        for (const results::MetricRow& row : payloads.get(stored.payload).rows) {
          const auto key = row.keys.find(db.group_key);
          if (row.status != results::MeasureStatus::kOk || key == row.keys.end()) continue;
          for (const results::Metric& m : row.metrics) {
            if (m.name == metric) totals[key->second] += m.value;
          }
        }
      }
      for (const auto& [name, total] : totals) lines[name][run].push_back(total);
    }
    addChart(group, declaration.measure, "total " + spec->name,
             std::string(results::toString(spec->unit)),
             std::string(results::toString(spec->direction)), lines, spec->direction,
             ReportOptions{}, view);
  }
}

void timingChart(size_t group, const std::vector<RunContent>& runs, const std::string& measure,
                 const ReportOptions& options, HistoryView* view) {
  LineValues lines;
  for (size_t run = 0; run < runs.size(); ++run) {
    if (!runs[run].timings) continue;
    for (const results::TimingEntry& entry : runs[run].timings->measures) {
      if (entry.measure != measure || !assetPicked(options.assets, entry.asset)) continue;
      lines[lineName(entry.technique + "/" + entry.variant, entry.asset, options)][run].push_back(
          results::medianOf(entry.samples));
    }
  }
  addChart(group, measure, "seconds", "s",
           std::string(results::toString(results::Direction::kLowerIsBetter)), lines,
           results::Direction::kLowerIsBetter, options, view);
}

}  // namespace

const results::MeasureResult& PayloadCache::get(int64_t payload) {
  auto it = parsed_.find(payload);
  if (it != parsed_.end()) return it->second;
  Statement query = db_.prepare("SELECT json FROM payloads WHERE id = ?");
  query.bind(1, payload);
  if (!query.step()) throw HistoryError(db_.path() + ": no payload " + std::to_string(payload));
  return parsed_
      .emplace(payload, results::measureResultFromJson(Json::parse(query.text(0)),
                                                       "payload " + std::to_string(payload)))
      .first->second;
}

bool assetPicked(const std::vector<std::string>& picked, const std::string& asset) {
  if (picked.empty()) return true;
  const std::string short_name = asset.substr(asset.rfind('/') + 1);
  return std::any_of(picked.begin(), picked.end(),
                     [&](const std::string& p) { return p == asset || p == short_name; });
}

bool stepMarks(const Step& step, const Chart& chart, const ChartSeries& series, size_t run) {
  if (step.group != chart.group || step.run != run || step.measure != chart.measure ||
      step.series != series.series || step.timing != (chart.metric == "seconds"))
    return false;
  if (series.asset.empty()) return true;
  return std::any_of(step.figures.begin(), step.figures.end(),
                     [&](const StepFigure& f) { return f.asset == series.asset; });
}

HistoryView buildHistory(HistoryDb& history, const ReportOptions& options) {
  assert(history.db != nullptr);
  HistoryView view;
  view.options = options;
  for (RunInfo& run : listRuns(history)) {
    auto group = std::find_if(view.groups.begin(), view.groups.end(), [&](const RunGroup& g) {
      return g.device == run.device && g.suite == run.suite;
    });
    if (group == view.groups.end())
      group = view.groups.insert(view.groups.end(), {run.device, run.suite, {}});
    group->runs.push_back(std::move(run));
  }
  PayloadCache payloads(*history.db);
  for (size_t g = 0; g < view.groups.size(); ++g) {
    std::vector<RunContent> runs;
    for (const RunInfo& run : view.groups[g].runs) runs.push_back(loadContent(*history.db, run.id));
    std::vector<std::string> measures;
    for (const RunContent& run : runs)
      for (const results::MeasureDeclaration& d : run.declarations) measures.push_back(d.measure);
    std::sort(measures.begin(), measures.end());
    measures.erase(std::unique(measures.begin(), measures.end()), measures.end());
    for (const std::string& measure : measures) {
      metricCharts(g, runs, *latestDeclaration(runs, measure), options, payloads, &view);
      shaderDbCharts(g, runs, *latestDeclaration(runs, measure), payloads, &view);
      timingChart(g, runs, measure, options, &view);
    }
    std::vector<Step> steps = findSteps(runs, g, options, payloads);
    view.steps.insert(view.steps.end(), steps.begin(), steps.end());
  }
  std::stable_sort(view.steps.begin(), view.steps.end(), [](const Step& a, const Step& b) {
    if (a.worst().kind != b.worst().kind) return a.worst().kind < b.worst().kind;
    return a.worst().relative > b.worst().relative;
  });
  return view;
}

}  // namespace tb::history
