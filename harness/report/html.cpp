#include "harness/report/html.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "harness/report/base64.h"
#include "harness/report/comparison.h"
#include "harness/report/decision_inputs.h"
#include "harness/report/html_chart_script.h"
#include "harness/report/html_decisions.h"
#include "harness/report/html_escape.h"
#include "harness/report/html_per_dispatch.h"
#include "harness/report/plot_data.h"
#include "harness/report/summary.h"
#include "harness/results/device_identity.h"

namespace tb::report {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kStyle = R"CSS(
body { font: 15px/1.45 system-ui, sans-serif; margin: 0; color: #222; background: #fafafa; }
main { max-width: 1400px; margin: 0 auto; padding: 1rem 2rem 3rem; }
h1 { margin: 0.4rem 0 0.2rem; font-size: 1.6rem; }
#answers h2, #tradeoffs h2 { margin-top: 0.8rem; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2rem; margin-top: 2.5rem; }
table.context { border-collapse: collapse; }
table.context th { text-align: left; padding: 0.1rem 1rem 0.1rem 0; font-weight: 600; }
table.context td { font-family: ui-monospace, monospace; font-size: 13px; }
.note { color: #555; font-size: 13px; margin: 0.2rem 0 0.6rem; }
.warning { background: #fff3cd; border: 1px solid #e0c36b; padding: 0.5rem 0.8rem; }
#script-errors { background: #fde2e1; border: 1px solid #d9534f; padding: 0.5rem 2rem; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(430px, 1fr)); gap: 1rem; }
.charts.single { grid-template-columns: 1fr; }
.chart-box { position: relative; height: 320px; background: #fff; border: 1px solid #ddd; }
.charts.single .chart-box { height: 420px; }
.pictures { display: flex; flex-wrap: wrap; gap: 1rem; }
figure.picture-group { margin: 0 0 1.5rem; background: #fff; border: 1px solid #ddd; padding: 0.6rem; }
figure.picture-group img { max-width: 100%; display: block; }
.picture-row { display: flex; flex-wrap: wrap; gap: 0.8rem; }
.picture-row figure { margin: 0; }
figcaption { font-size: 13px; color: #444; max-width: 220px; }
.picture-row .square { width: fit-content; aspect-ratio: 1 / 1; overflow: hidden; }
ul.answers { font-size: 13px; line-height: 1.3; margin: 0.4rem 0; padding-left: 1.2rem; }
ul.answers li { margin-bottom: 0.25rem; }
ul.answers .source { color: #666; font-size: 12px; }
#tradeoffs .charts { grid-template-columns: repeat(auto-fill, minmax(330px, 1fr)); }
#tradeoffs .chart-box { height: 260px; }
details.plots > summary { cursor: pointer; font-weight: 600; margin: 0.6rem 0; }
)CSS";

// The page as it is assembled: markup in order, and the charts' data for the script.
struct Page {
  std::string body;
  Json charts = Json::array();
  bool charts_available = false;
};

void contextRow(std::string* out, const std::string& name, const std::string& value) {
  if (value.empty()) return;
  *out += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", escapeHtml(name), escapeHtml(value));
}

void contextSection(const results::Results& results, Page* page) {
  const results::RunContext& c = results.context;
  std::string rows;
  contextRow(&rows, "run", c.run_id);
  contextRow(&rows, "date (UTC)", c.date);
  contextRow(&rows, "git sha", c.git_sha);
  contextRow(&rows, "suite", c.selection.suite);
  contextRow(&rows, "Vulkan device",
             c.vulkan_device.empty() ? "none (GPU rows skipped)" : c.vulkan_device);
  contextRow(&rows, "device caveat", results::deviceCaveat(c.vulkan_device));
  contextRow(&rows, "host", c.host);
  contextRow(&rows, "CPU", c.cpu);
  contextRow(&rows, "compiler", c.compiler + (c.build_type.empty() ? "" : ", " + c.build_type));
  if (c.shard.count > 0)
    contextRow(&rows, "shard", fmt::format("{}/{}", c.shard.index, c.shard.count));
  if (!c.merged_from.empty())
    contextRow(&rows, "merged from", fmt::format("{} shards", c.merged_from.size()));
  contextRow(&rows, "command", c.command_line);
  contextRow(&rows, "records",
             fmt::format("{} ({} assets; {} technique × asset pairs skipped)",
                         results.records.size(), results.assets.size(), results.skipped.size()));
  page->body +=
      "<section id=\"context\">\n<h2>Run</h2>\n<table class=\"context\">\n" + rows +
      "</table>\n<p class=\"note\">Every figure, with its unit and the rows not measured, "
      "is in report.md and results.json beside this file.</p>\n</section>\n";
}

std::string plotNote(const PlotData& data) {
  if (!data.note.empty()) return data.note;
  std::vector<std::string> parts;
  parts.push_back(fmt::format(
      "{} rows; a point is the {} of {}", data.rows_used,
      data.spec.reduce == results::PlotReduce::kMax ? "largest value" : "median",
      data.point_per_variant ? "one technique × variant's rows" : "one series' rows at one x"));
  if (!data.spec.where.empty()) {
    std::string where;
    for (const auto& [key, value] : data.spec.where)
      where += (where.empty() ? "" : ", ") + key + " = " + value;
    parts.push_back("rows with " + where);
  }
  if (data.rows_without_x > 0) {
    parts.push_back(
        fmt::format("{} rows without a numeric {} left out", data.rows_without_x, data.spec.x));
  }
  if (data.rows_without_y > 0) {
    parts.push_back(fmt::format("{} rows without {} left out", data.rows_without_y, data.spec.y));
  }
  if (data.charts_dropped > 0) {
    parts.push_back(fmt::format("{} {} values with fewer than 2 points not drawn",
                                data.charts_dropped,
                                data.spec.facet.empty() ? "chart" : data.spec.facet));
  }
  if (data.points_hidden_by_log > 0) {
    parts.push_back(fmt::format("{} values at or below 0 not shown on the log axis",
                                data.points_hidden_by_log));
  }
  if (data.spec.pareto_front) {
    parts.push_back(
        "ringed points and the dashed line: the Pareto front (no other point has a "
        "lower or equal x and a better y)");
  }
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text + ".";
}

Json chartJson(const PlotData& data, const PlotChart& chart, const std::string& canvas,
               const std::vector<std::string>& series_order) {
  Json series = Json::array();
  for (const PlotSeries& s : chart.series) {
    Json points = Json::array();
    for (const PlotPoint& p : s.points) {
      Json point{{"x", p.x}, {"y", p.y}, {"label", p.label}, {"rows", p.rows}};
      if (p.on_front) point["front"] = true;
      points.push_back(std::move(point));
    }
    const auto colour =
        std::find(series_order.begin(), series_order.end(), s.name) - series_order.begin();
    series.push_back({{"name", s.name}, {"colour", colour}, {"points", std::move(points)}});
  }
  // The declared log axes, unless the data leave more than kMaxEmptyDecades empty decades.
  std::vector<double> xs, ys;
  for (const PlotSeries& s : chart.series) {
    for (const PlotPoint& p : s.points) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
  }
  const bool bar = data.spec.kind == results::PlotKind::kBar;
  return Json{{"canvas", canvas},
              {"kind", toString(data.spec.kind)},
              {"title", chart.facet},
              {"x_label", data.x_label},
              {"y_label", data.y_label},
              {"log_x", data.spec.log_x && !bar && logAxisSuits(xs)},
              {"log_y", data.spec.log_y && (bar || logAxisSuits(ys))},
              {"pareto", data.spec.pareto_front},
              {"categories", chart.categories},
              {"series", std::move(series)}};
}

void plotSection(const PlotData& data, Page* page) {
  page->body +=
      fmt::format("<h3>{}</h3>\n<p class=\"note\">{}: {} against {}. {}</p>\n",
                  escapeHtml(data.spec.title), escapeHtml(toString(data.spec.kind)),
                  escapeHtml(data.y_label), escapeHtml(data.x_label), escapeHtml(plotNote(data)));
  if (data.charts.empty()) {
    page->body += "<p class=\"note\">No rows to plot in this run.</p>\n";
    return;
  }
  if (!page->charts_available) return;  // the page says once why there are no charts
  // One colour per series value across the plot's facets.
  std::vector<std::string> series_order;
  for (const PlotChart& chart : data.charts) {
    for (const PlotSeries& s : chart.series) {
      if (std::find(series_order.begin(), series_order.end(), s.name) == series_order.end()) {
        series_order.push_back(s.name);
      }
    }
  }
  page->body +=
      data.charts.size() == 1 ? "<div class=\"charts single\">\n" : "<div class=\"charts\">\n";
  for (const PlotChart& chart : data.charts) {
    const std::string canvas = fmt::format("chart-{}", page->charts.size());
    page->body += fmt::format(
        "<div class=\"chart-box\"><canvas id=\"{}\" role=\"img\" "
        "aria-label=\"{}\"></canvas></div>\n",
        canvas, escapeHtml(data.spec.title + (chart.facet.empty() ? "" : ": " + chart.facet)));
    page->charts.push_back(chartJson(data, chart, canvas, series_order));
  }
  page->body += "</div>\n";
}

// Under a chart per solver iteration: what an iteration costs in dispatches, per variant, so
// the per-dispatch comparison (a frame's budget is dispatches) is not read off it.
std::string perDispatchNote(const results::Results& results, const std::string& measure) {
  const auto input = inputFor(results, results::DecisionRole::kDispatchesPerIteration);
  if (!input || input->measure() != measure || input->input->metrics.empty()) return "";
  const std::string& metric = input->input->metrics.front();
  const MeasureSummary summary =
      summarizeMeasure(results, measure, SummaryGrouping::kAcrossAssets, {metric});
  std::string parts;
  for (const SummaryLine& line : summary.lines) {
    const MetricStats* stats = line.find(metric);
    if (stats == nullptr) continue;
    parts += fmt::format("{}{} {:g}", parts.empty() ? "" : ", ", line.variant, stats->median);
  }
  if (parts.empty()) return "";
  return "<p class=\"note\">The x axis counts solver iterations, not dispatches: one iteration "
         "costs " +
         escapeHtml(parts) +
         " compute dispatches. At a frame's budget of 8 dispatches "
         "compare the chart per dispatch below (the residual at 8 dispatches: the answers above "
         "and report.md's simulations section).</p>\n";
}

void measureSections(const results::Results& results, Page* page) {
  for (const std::string& id : measureIds(results)) {
    const results::MeasureDeclaration* declaration = results.findMeasure(id);
    page->body += fmt::format("<section class=\"measure\" id=\"measure-{}\">\n", escapeHtml(id));
    if (declaration == nullptr) {
      page->body += fmt::format(
          "<h2>{}</h2>\n<p class=\"note\">Undeclared measure: no plots.</p>\n", escapeHtml(id));
    } else {
      page->body += fmt::format("<h2>{} <small>({})</small></h2>\n<p>{}</p>\n",
                                escapeHtml(declaration->title), escapeHtml(id),
                                escapeHtml(declaration->description));
      // The declared comparisons first: a grouped bar chart per asset (× camera path, ...).
      for (const results::ComparisonSpec& comparison : declaration->comparisons) {
        const ComparisonTable table = comparisonTable(results, *declaration, comparison);
        if (!table.groups.empty()) plotSection(comparisonPlot(table), page);
      }
      if (declaration->plots.empty() && declaration->comparisons.empty()) {
        page->body +=
            "<p class=\"note\">The measure declares no plots; its figures are in "
            "report.md.</p>\n";
      }
      for (const results::PlotSpec& declared : declaration->plots) {
        // A chart per asset (dozens) goes in a collapsed section, a colour per
        // technique/variant rather than per row key.
        const bool per_asset = declared.facet == "asset";
        results::PlotSpec spec = declared;
        if (per_asset && spec.series != "technique" && spec.series != "variant")
          spec.series = "variant";
        if (per_asset) {
          page->body +=
              "<details class=\"plots\"><summary>" + escapeHtml(spec.title) +
              ": one chart per asset, coloured by technique/variant (collapsed)</summary>\n";
        }
        plotSection(plotData(results, *declaration, spec), page);
        if (spec.x == "iteration") {
          page->body += perDispatchNote(results, id);
          appendPerDispatchCharts(results, page->charts_available, &page->body, &page->charts);
        }
        if (per_asset) page->body += "</details>\n";
      }
    }
    page->body += "</section>\n";
  }
}

void pictureGroup(const HtmlPictureGroup& group, const char* id, Page* page) {
  page->body += fmt::format("<figure class=\"picture-group\"{}>\n<h3>{}</h3>\n",
                            *id ? fmt::format(" id=\"{}\"", id) : "", escapeHtml(group.title));
  if (!group.note.empty())
    page->body += fmt::format("<p class=\"note\">{}</p>\n", escapeHtml(group.note));
  page->body += "<div class=\"picture-row\">\n";
  for (size_t i = 0; i < group.pictures.size(); ++i) {
    const HtmlPicture& picture = group.pictures[i];
    const bool crop = group.shared_scale && i > 0;  // the square render, not the bar again
    page->body += fmt::format(
        "<figure>{2}<img alt=\"{0}\" src=\"data:image/png;base64,{1}\">{3}<figcaption>{0}"
        "</figcaption></figure>\n",
        escapeHtml(picture.caption), base64Encode(picture.png_bytes),
        crop ? "<div class=\"square\">" : "", crop ? "</div>" : "");
  }
  page->body += "</div>\n</figure>\n";
}

void picturesSection(const HtmlAssets& assets, Page* page) {
  page->body += "<section id=\"pictures\">\n<h2>Pictures</h2>\n";
  for (const std::string& note : assets.picture_notes) {
    page->body += fmt::format("<p class=\"note\">{}</p>\n", escapeHtml(note));
  }
  if (assets.pictures.empty() && assets.picture_notes.empty()) {
    page->body += "<p class=\"note\">No pictures in this run.</p>\n";
  }
  for (const HtmlPictureGroup& group : assets.crack_pictures)
    pictureGroup(group, "crack-pictures", page);
  for (const HtmlPictureGroup& group : assets.pictures) pictureGroup(group, "", page);
  page->body += "</section>\n";
}

}  // namespace

std::string renderHtml(const results::Results& results, const HtmlAssets& assets) {
  Page page;
  page.charts_available = !assets.chartjs_source.empty();
  const std::vector<AssetDecision> decisions = decideAssets(results);
  page.body += "<section id=\"answers\">\n<h2>Answers</h2>\n" +
               answersHtml(answerQuestions(results, decisions)) + "</section>\n";
  std::vector<std::string> technique_order;
  for (const auto& t : techniquesOf(results)) technique_order.push_back(t.technique);
  appendTradeoffCharts(decisions, technique_order, page.charts_available, &page.body, &page.charts);
  contextSection(results, &page);
  measureSections(results, &page);
  picturesSection(assets, &page);

  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  html += fmt::format("<title>tessbench report {}</title>\n", escapeHtml(results.context.run_id));
  html += std::string("<style>") + kStyle + "</style>\n";
  html += std::string("<script>") + kHtmlErrorScript + "</script>\n";
  if (page.charts_available) {
    html += "<script>\n" + javascriptForScript(assets.chartjs_source) + "\n</script>\n";
  }
  html += "</head>\n<body>\n";
  html += fmt::format("<main data-charts=\"{}\">\n<h1>tessbench report</h1>\n", page.charts.size());
  html += "<ul id=\"script-errors\" hidden></ul>\n";
  if (!page.charts_available) {
    html += fmt::format(
        "<p class=\"warning\">Charts unavailable: {}.</p>\n",
        escapeHtml(assets.chartjs_missing_reason.empty() ? "no Chart.js given"
                                                         : assets.chartjs_missing_reason));
  }
  html += page.body + "</main>\n";
  if (page.charts_available) {
    const Json data{{"charts", page.charts}};
    html += "<script type=\"application/json\" id=\"chart-data\">" +
            jsonForScript(data.dump(-1, ' ', false, Json::error_handler_t::replace)) +
            "</script>\n";
    html += std::string("<script>") + kHtmlChartScript + "</script>\n";
  }
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace tb::report
