#include "harness/report/html_decisions.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "harness/report/html_escape.h"

namespace tb::report {
namespace {

using Json = nlohmann::ordered_json;

// Escaped text with each **x** as <strong>x</strong>.
std::string strongHtml(const std::string& text) {
  std::string out;
  bool open = false;
  size_t at = 0;
  while (true) {
    const size_t mark = text.find("**", at);
    out += escapeHtml(text.substr(at, mark == std::string::npos ? std::string::npos : mark - at));
    if (mark == std::string::npos) break;
    out += open ? "</strong>" : "<strong>";
    open = !open;
    at = mark + 2;
  }
  if (open) out += "</strong>";
  return out;
}

std::vector<const DecisionCandidate*> drawable(const AssetDecision& d) {
  std::vector<const DecisionCandidate*> points;
  for (const DecisionCandidate& c : d.candidates) {
    // A compute-path candidate sits on its tessellator twin's point (the same surface and
    // levels): the table lists it, the chart draws one point.
    if (c.path == kComputePath) continue;
    if (c.figures.error && c.figures.triangles_1px) points.push_back(&c);
  }
  return points;
}

Json tradeoffChart(const AssetDecision& d, const std::vector<const DecisionCandidate*>& points,
                   const std::vector<std::string>& technique_order, const std::string& canvas) {
  Json series = Json::array();
  std::vector<double> xs, ys;
  for (const DecisionCandidate* c : points) {
    const auto colour = std::find(technique_order.begin(), technique_order.end(), c->technique) -
                        technique_order.begin();
    Json point{{"x", *c->figures.triangles_1px},
               {"y", *c->figures.error},
               {"label", c->name() + (c->name() == d.recommended() ? " (recommended)" : "")},
               {"rows", 1}};
    if (c->on_front) point["front"] = true;
    if (c->name() == d.recommended()) point["recommended"] = true;
    series.push_back({{"name", c->name()}, {"colour", colour}, {"points", Json::array({point})}});
    xs.push_back(*c->figures.triangles_1px);
    ys.push_back(*c->figures.error);
  }
  return Json{{"canvas", canvas},
              {"kind", "scatter"},
              {"title", d.asset},
              {"x_label", "triangles per frame for a 1 px error (count)"},
              {"y_label", d.error_axis},
              {"log_x", logAxisSuits(xs)},
              {"log_y", logAxisSuits(ys)},
              {"pareto", true},
              {"categories", Json::array()},
              {"series", std::move(series)}};
}

}  // namespace

bool logAxisSuits(const std::vector<double>& values) {
  if (values.empty()) return false;
  std::set<int> decades;
  for (double v : values) {
    if (!(v > 0) || !std::isfinite(v)) return false;
    decades.insert(int(std::floor(std::log10(v))));
  }
  const int span = *decades.rbegin() - *decades.begin() + 1;
  if (span < 2) return false;  // within one decade: linear reads better
  return span - int(decades.size()) <= kMaxEmptyDecades;
}

std::string answersHtml(const std::vector<Answer>& answers) {
  std::string html = "<ul class=\"answers\">\n";
  for (const Answer& a : answers) {
    html += fmt::format("<li><strong>{}</strong> {} <span class=\"source\">({})</span></li>\n",
                        escapeHtml(a.question), strongHtml(a.answer), escapeHtml(a.source));
  }
  return html + "</ul>\n";
}

void appendTradeoffCharts(const std::vector<AssetDecision>& decisions,
                          const std::vector<std::string>& technique_order, bool charts_available,
                          std::string* body, Json* charts) {
  *body += "<section id=\"tradeoffs\">\n<h2>Trade-off per asset</h2>\n";
  *body +=
      "<p class=\"note\">Each technique's default variant: error (Hausdorff, fraction "
      "of the bounding-box diagonal) against triangles per frame for a 1 px tessellation "
      "error (best factor policy). Ringed points and dashed line: the Pareto front; star: "
      "the recommendation, by the rule in report.md's decision tables. Log axes only where "
      "the points span over a decade with at most 3 empty decades.</p>\n";
  std::vector<std::string> without;
  std::string boxes;
  for (const AssetDecision& d : decisions) {
    const auto points = drawable(d);
    if (points.size() < 2) {
      without.push_back(d.asset + ", recommended " + d.recommended());
      continue;
    }
    if (!charts_available) continue;
    const std::string canvas = fmt::format("chart-{}", charts->size());
    boxes += fmt::format(
        "<div class=\"chart-box\"><canvas id=\"{}\" role=\"img\" "
        "aria-label=\"{}\"></canvas></div>\n",
        canvas, escapeHtml("Trade-off: " + d.asset + ", recommended " + d.recommended()));
    charts->push_back(tradeoffChart(d, points, technique_order, canvas));
  }
  if (!boxes.empty()) *body += "<div class=\"charts\">\n" + boxes + "</div>\n";
  if (!without.empty()) {
    std::string list;
    for (const std::string& asset : without) list += (list.empty() ? "" : "; ") + asset;
    *body +=
        "<p class=\"note\">No chart (fewer than two candidates with both figures; the "
        "decision tables of report.md list them): " +
        escapeHtml(list) + ".</p>\n";
  }
  *body += "</section>\n";
}

}  // namespace tb::report
