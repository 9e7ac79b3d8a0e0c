#include "harness/report/html_per_dispatch.h"

#include <fmt/format.h>

#include <map>
#include <vector>

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
std::map<std::string, std::vector<Curve>> curvesOf(const results::Results& results) {
  std::map<std::string, std::vector<Curve>> by_scenario;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != "convergence" || m.status != results::MeasureStatus::kOk) continue;
      double per_iteration = 0;
      for (const results::MetricRow& row : m.rows) {
        if (rowKey(row, "kind") == "summary" && rowKey(row, "goal_springs") == "false")
          per_iteration = rowMetric(row, "dispatches_per_iteration").value_or(0);
      }
      if (per_iteration <= 0) continue;
      Curve curve{record.variant};
      for (const results::MetricRow& row : m.rows) {
        if (rowKey(row, "kind") != "iteration" || rowKey(row, "goal_springs") != "false") continue;
        const auto residual = rowMetric(row, "residual");
        const double dispatches = std::stod(rowKey(row, "iteration")) * per_iteration;
        if (!residual || *residual <= 0 || dispatches > kMaxDispatches) continue;
        curve.points.push_back(
            {{"x", dispatches}, {"y", *residual}, {"label", record.variant}, {"rows", 1}});
      }
      if (!curve.points.empty()) by_scenario[record.asset].push_back(std::move(curve));
    }
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
      "iteration, up to {:g} dispatches: the comparison at a frame's budget that "
      "residual_at_8_dispatches summarises.</p>\n",
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
    charts->push_back(Json{{"canvas", canvas},
                           {"kind", "line"},
                           {"title", scenario},
                           {"x_label", "compute dispatches (count)"},
                           {"y_label", "residual (ratio)"},
                           {"log_x", false},
                           {"log_y", false},
                           {"pareto", false},
                           {"categories", Json::array()},
                           {"series", std::move(series)}});
  }
  *body += "</div>\n";
}

}  // namespace tb::report
