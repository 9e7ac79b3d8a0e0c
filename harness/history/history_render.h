// The history's two renderings: history.html, one self-contained page (Chart.js inlined as
// report.html does: a line per series over commits, steps marked, a click or hover on a
// point shows its run and figure), and history.md, the flagged steps worst first. Both
// read only the HistoryView and are byte-identical for the same view.
#pragma once

#include <string>

#include "harness/history/history_series.h"

namespace tb::history {

// Chart.js's UMD build, or empty with the reason the page gives for having no charts.
struct ChartScript {
  std::string source;
  std::string missing_reason;
};

std::string renderHistoryHtml(const HistoryView& view, const ChartScript& chartjs);
std::string renderHistoryMarkdown(const HistoryView& view);

// "regression", "changed", "improvement"; what the step tables call a step.
std::string stepChange(const StepFigure& figure);
// "+12.5%", "from 0", "" (NaN): the relative change from base to new.
std::string percentChange(double base, double current);
// A figure as the tables print it: integers whole, others to 6 significant digits.
std::string figureText(double value);

// The script that draws the charts of #chart-data (history_chart_script.cpp).
extern const char* const kHistoryChartScript;

}  // namespace tb::history
