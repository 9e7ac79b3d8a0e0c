#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <nlohmann/json.hpp>

#include "harness/history/history_render.h"
#include "harness/report/html_chart_script.h"
#include "harness/report/html_escape.h"

namespace tb::history {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kHistoryStyle = R"CSS(
body { font: 15px/1.45 system-ui, sans-serif; margin: 0; color: #222; background: #fafafa; }
main { max-width: 1400px; margin: 0 auto; padding: 1rem 2rem 3rem; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2rem; margin-top: 2.5rem; }
table { border-collapse: collapse; font-size: 13px; }
th, td { text-align: left; padding: 0.1rem 0.8rem 0.1rem 0; }
.note { color: #555; font-size: 13px; }
.warning { background: #fff3cd; border: 1px solid #e0c36b; padding: 0.5rem 0.8rem; }
#script-errors { background: #fde2e1; border: 1px solid #d9534f; padding: 0.5rem 2rem; }
#point-details { position: sticky; top: 0; background: #eef4fb; border: 1px solid #9bb8d8;
  padding: 0.4rem 0.8rem; font-family: ui-monospace, monospace; font-size: 13px; z-index: 1; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(460px, 1fr)); gap: 1rem; }
.chart-box { position: relative; height: 340px; background: #fff; border: 1px solid #ddd; }
)CSS";

std::string esc(const std::string& text) { return report::escapeHtml(text); }

std::string yLabel(const Chart& chart) {
  std::string direction =
      chart.direction == results::toString(results::Direction::kLowerIsBetter) ? ", lower is better"
      : chart.direction == results::toString(results::Direction::kHigherIsBetter)
          ? ", higher is better"
          : "";
  return chart.metric + " (" + chart.unit + direction + ")";
}

std::string chartTitle(const Chart& chart, const ReportOptions& options) {
  const std::string over = !options.assets.empty()                   ? "per asset"
                           : options.aggregate == Aggregate::kMedian ? "median over assets"
                                                                     : "worst over assets";
  return chart.measure + ": " +
         (chart.metric == "seconds" ? "wall time per record" : chart.metric) + " (" + over + ")";
}

// The text a step's point shows: how many figures moved and the worst of them.
std::string stepNote(const Step& step) {
  const StepFigure& f = step.worst();
  return fmt::format("{} figure{} moved; worst: {} {} {} {} -> {} ({})", step.figures.size(),
                     step.figures.size() == 1 ? "" : "s", stepChange(f), f.asset, f.metric,
                     figureText(f.base), figureText(f.current), percentChange(f.base, f.current));
}

Json chartJson(const HistoryView& view, const Chart& chart, const std::string& canvas) {
  const RunGroup& group = view.groups[chart.group];
  Json labels = Json::array(), runs = Json::array();
  for (const RunInfo& run : group.runs) {
    labels.push_back(runLabel(run));
    runs.push_back(
        {{"run_id", run.run_id}, {"sha", run.git_sha.substr(0, 12)}, {"date", run.orderTime()}});
  }
  Json series = Json::array();
  for (size_t s = 0; s < chart.series.size(); ++s) {
    const ChartSeries& line = chart.series[s];
    Json points = Json::array();
    for (const SeriesPoint& p : line.points) {
      Json point{{"x", p.run}, {"y", std::isfinite(p.value) ? Json(p.value) : Json()}};
      for (const Step& step : view.steps) {
        if (stepMarks(step, chart, line, p.run)) {
          point["step"] = stepNote(step);
          break;
        }
      }
      points.push_back(std::move(point));
    }
    series.push_back({{"name", line.name}, {"colour", s}, {"points", std::move(points)}});
  }
  return {{"canvas", canvas},           {"title", chartTitle(chart, view.options)},
          {"y_label", yLabel(chart)},   {"unit", chart.unit},
          {"labels", labels},           {"runs", runs},
          {"series", std::move(series)}};
}

void runsTable(const RunGroup& group, std::string* body) {
  *body +=
      "<table class=\"runs\"><tr><th>#</th><th>commit</th><th>run</th><th>git sha</th>"
      "<th>run date</th></tr>\n";
  for (size_t i = 0; i < group.runs.size(); ++i) {
    const RunInfo& run = group.runs[i];
    *body += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", i,
                         esc(run.orderTime()), esc(run.run_id), esc(run.git_sha), esc(run.date));
  }
  *body += "</table>\n";
}

void stepsSection(const HistoryView& view, std::string* body) {
  *body += fmt::format("<section id=\"steps\">\n<h2>Flagged steps ({})</h2>\n", view.steps.size());
  if (view.steps.empty()) {
    *body += "<p class=\"note\">No figure moved between consecutive runs.</p>\n</section>\n";
    return;
  }
  *body +=
      "<table><tr><th>change</th><th>from → to</th><th>device, suite</th><th>series</th>"
      "<th>measure</th><th>figures</th><th>worst</th></tr>\n";
  for (const Step& step : view.steps) {
    const RunGroup& group = view.groups[step.group];
    *body += fmt::format(
        "<tr class=\"step\"><td>{}</td><td>{} → {}</td><td>{}, {}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td></tr>\n",
        esc(stepChange(step.worst())), esc(runLabel(group.runs[step.run - 1])),
        esc(runLabel(group.runs[step.run])), esc(group.device), esc(group.suite), esc(step.series),
        esc(step.measure + (step.timing ? " (timing)" : "")), step.figures.size(),
        esc(stepNote(step)));
  }
  *body += "</table>\n</section>\n";
}

}  // namespace

std::string renderHistoryHtml(const HistoryView& view, const ChartScript& chartjs) {
  const bool charts = !chartjs.source.empty();
  std::string body;
  Json chart_data = Json::array();
  size_t runs = 0;
  for (const RunGroup& group : view.groups) runs += group.runs.size();
  body += fmt::format(
      "<p>{} runs; {} device × suite group{}; {} steps flagged (also in history.md beside "
      "this page). Figures of different devices never share a chart.</p>\n",
      runs, view.groups.size(), view.groups.size() == 1 ? "" : "s", view.steps.size());
  body += "<p id=\"point-details\">Click a point: its run and figure.</p>\n";
  for (size_t g = 0; g < view.groups.size(); ++g) {
    const RunGroup& group = view.groups[g];
    body += fmt::format("<section class=\"group\">\n<h2>{} — suite {}</h2>\n", esc(group.device),
                        esc(group.suite));
    runsTable(group, &body);
    std::string measure;
    for (const Chart& chart : view.charts) {
      if (chart.group != g) continue;
      if (chart.measure != measure) {
        body += (measure.empty() ? "" : "</div>\n") +
                fmt::format("<h3 id=\"g{}-{}\">{}</h3>\n<div class=\"charts\">\n", g,
                            esc(chart.measure), esc(chart.measure));
        measure = chart.measure;
      }
      const std::string canvas = fmt::format("chart-{}", chart_data.size());
      body += fmt::format(
          "<div class=\"chart-box\"><canvas id=\"{}\" role=\"img\" aria-label=\"{}\"></canvas>"
          "</div>\n",
          canvas, esc(chartTitle(chart, view.options)));
      chart_data.push_back(chartJson(view, chart, canvas));
    }
    body += (measure.empty() ? "" : "</div>\n") + std::string("</section>\n");
  }
  stepsSection(view, &body);

  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<title>tessbench history</title>\n";
  html += std::string("<style>") + kHistoryStyle + "</style>\n";
  html += std::string("<script>") + report::kHtmlErrorScript + "</script>\n";
  if (charts) html += "<script>\n" + report::javascriptForScript(chartjs.source) + "\n</script>\n";
  html += fmt::format("</head>\n<body>\n<main data-charts=\"{}\">\n<h1>tessbench history</h1>\n",
                      charts ? chart_data.size() : 0);
  html += "<ul id=\"script-errors\" hidden></ul>\n";
  if (!charts) {
    html += fmt::format(
        "<p class=\"warning\">Charts unavailable: {}.</p>\n",
        esc(chartjs.missing_reason.empty() ? "no Chart.js given" : chartjs.missing_reason));
  }
  html += body + "</main>\n";
  if (charts) {
    const Json data{{"charts", chart_data}};
    html += "<script type=\"application/json\" id=\"chart-data\">" +
            report::jsonForScript(data.dump(-1, ' ', false, Json::error_handler_t::replace)) +
            "</script>\n";
    html += std::string("<script>") + kHistoryChartScript + "</script>\n";
  }
  return html + "</body>\n</html>\n";
}

}  // namespace tb::history
