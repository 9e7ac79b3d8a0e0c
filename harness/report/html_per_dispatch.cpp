#include "harness/report/html_per_dispatch.h"

#include <fmt/format.h>

#include <map>
#include <vector>

#include "harness/report/decision_inputs.h"
#include "harness/report/html_escape.h"
#include "harness/report/row_values.h"

namespace tb::report {
namespace {

using Json = nlohmann::ordered_json;

// The dispatches spent on the chart's x axis: beyond them every solver has long converged or
// stalled, and 8 (a frame) would be a sliver of the axis.
constexpr double kMaxDispatches = 64;

struct Curve {
  std::string variant;
  Json points = Json::array();
};

// Per scenario, per variant: (dispatches, residual) of the iteration rows without goal springs.
// kResidualPerDispatch's rows: the residual, x = its chosen_key (the iteration) times the
// kDispatchesPerIteration figure of the same record.
std::map<std::string, std::vector<Curve>> curvesOf(const results::Results& results) {
  std::map<std::string, std::vector<Curve>> by_scenario;
  const auto residuals = inputFor(results, results::DecisionRole::kResidualPerDispatch);
  const auto dispatches = inputFor(results, results::DecisionRole::kDispatchesPerIteration);
  if (!residuals || !dispatches) return by_scenario;
  for (const results::Record& record : results.records) {
    const results::MeasureResult* m = resultOf(record, *residuals);
    const results::MeasureResult* d = resultOf(record, *dispatches);
    if (m == nullptr || d == nullptr || m->status != results::MeasureStatus::kOk) continue;
    const double per_iteration = readInput(*dispatches, *d).value.value_or(0);
    if (per_iteration <= 0) continue;
    Curve curve{record.variant};
    for (const results::MetricRow& row : m->rows) {
      if (row.status != results::MeasureStatus::kOk || !readsRow(*residuals->input, row)) continue;
      const auto residual = rowFigure(*residuals->input, row);
      const double x = std::stod(rowKey(row, residuals->input->chosen_key)) * per_iteration;
      if (!residual || *residual <= 0 || x > kMaxDispatches) continue;
      curve.points.push_back({{"x", x}, {"y", *residual}, {"label", record.variant}, {"rows", 1}});
    }
    if (!curve.points.empty()) by_scenario[record.asset].push_back(std::move(curve));
  }
  return by_scenario;
}

}  // namespace

void appendPerDispatchCharts(const results::Results& results, bool charts_available,
                             std::string* body, Json* charts) {
  const auto by_scenario = curvesOf(results);
  if (by_scenario.empty()) return;
  *body += fmt::format(
      "<h3>Residual against compute dispatches (a frame: 8)</h3>\n<p class=\"note\">The "
      "iteration rows without goal springs, x = iteration × the variant's dispatches per "
      "iteration, up to {:g} dispatches: the comparison at a frame's budget that the "
      "summary's residual at 8 dispatches gives.</p>\n",
      kMaxDispatches);
  if (!charts_available) return;
  *body += "<div class=\"charts\">\n";
  std::vector<std::string> order;
  for (const auto& [scenario, curves] : by_scenario) {
    Json series = Json::array();
    for (const Curve& curve : curves) {
      size_t colour = 0;
      while (colour < order.size() && order[colour] != curve.variant) ++colour;
      if (colour == order.size()) order.push_back(curve.variant);
      series.push_back({{"name", curve.variant}, {"colour", colour}, {"points", curve.points}});
    }
    const std::string canvas = fmt::format("chart-{}", charts->size());
    *body += fmt::format(
        "<div class=\"chart-box\"><canvas id=\"{}\" role=\"img\" "
        "aria-label=\"{}\"></canvas></div>\n",
        canvas, escapeHtml("Residual per dispatch: " + scenario));
    charts->push_back(
        Json{{"canvas", canvas},
             {"kind", "line"},
             {"title", scenario},
             {"x_label", "compute dispatches (count)"},
             {"y_label", headerOf(*inputFor(results, results::DecisionRole::kResidualPerDispatch))},
             {"log_x", false},
             {"log_y", false},
             {"pareto", false},
             {"categories", Json::array()},
             {"series", std::move(series)}});
  }
  *body += "</div>\n";
}

}  // namespace tb::report
