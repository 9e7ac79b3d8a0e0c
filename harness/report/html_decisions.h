// report.html's opening (html.h): the answers (answers.h) and one trade-off chart per surface
// asset (decision.h: error against triangles per frame at 1 px, a colour per technique, the
// Pareto front drawn, the recommendation marked), and the axis rule every chart follows.
// Internal to harness/report.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/report/answers.h"
#include "harness/report/decision.h"

namespace tb::report {

// Whether a log axis suits `values`: every value positive, spanning more than one decade, and
// at most kMaxEmptyDecades decades between the smallest and largest value without a value
// (else a linear axis: 1e-13 px beside 1 px reads as 0 beside 1).
inline constexpr int kMaxEmptyDecades = 3;
bool logAxisSuits(const std::vector<double>& values);

// The answers as an HTML list (every text escaped; Markdown's **bold** as <strong>).
std::string answersHtml(const std::vector<Answer>& answers);

// One chart per asset with at least two candidates having both figures: appends the canvases
// to `body` and the charts' data to `charts` (html_chart_script.h's format). `technique_order`
// gives each technique its colour index, the same on every chart. Without Chart.js
// (`charts_available` false) only the notes.
void appendTradeoffCharts(const std::vector<AssetDecision>& decisions,
                          const std::vector<std::string>& technique_order, bool charts_available,
                          std::string* body, nlohmann::ordered_json* charts);

}  // namespace tb::report
