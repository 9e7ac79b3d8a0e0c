// The data of report.html's charts: a measure's declared PlotSpec applied to the rows of a
// run. Pure functions of the results model; the HTML renderer (html.h) only draws what
// these return, so which metric is plotted against what comes from the declaration alone.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

// One point of a series. Line and scatter charts use x; bar charts use category (x is the
// category's index). label names the technique/variants the point was reduced from.
struct PlotPoint {
  double x = 0;
  double y = 0;
  std::string category;   // bar charts: the x value as text; empty otherwise
  std::string label;      // "acc/default", or "phong/alpha0.5, phong/alpha0.75" when merged
  size_t rows = 0;        // rows whose median y this is
  bool on_front = false;  // on the Pareto front of its chart (PlotSpec::pareto_front)
};

struct PlotSeries {
  std::string name;  // the series value: a technique, "technique/variant", an asset, a key value
  std::vector<PlotPoint> points;  // ascending x (bars: in category order)
};

// One chart: the whole plot, or one facet of it.
struct PlotChart {
  std::string facet;                    // the facet value ("opensubdiv/catmark_cube"); "" unfaceted
  std::vector<std::string> categories;  // bar charts: the x values in first-seen order
  std::vector<PlotSeries> series;       // in first-seen order
  size_t points() const;
};

struct PlotData {
  std::string measure;
  results::PlotSpec spec;
  std::string x_label;  // "level", "hausdorff (rel_diag)", "instructions total (count)"
  std::string y_label;  // "plain_over_technique (ratio)"
  results::Direction y_direction = results::Direction::kNone;
  // x is another measure's figure of the record: each technique × variant is its own point.
  bool point_per_variant = false;
  // Facets in asset order; facets with fewer than 2 points and empty charts are dropped.
  std::vector<PlotChart> charts;
  size_t rows_used = 0;       // ok rows in `where` with a numeric x and a y
  size_t rows_without_x = 0;  // ok rows in `where` whose x is missing or not a number
  size_t rows_without_y = 0;  // ok rows in `where` with x but without the y metric
  size_t charts_dropped = 0;  // facets with fewer than 2 points (or an empty chart)
  // Points a log axis cannot show (x or y <= 0); they stay in the data, Chart.js skips them.
  size_t points_hidden_by_log = 0;
  // What the rows and bars are, when not a declared plot's (a comparison, comparison.h):
  // replaces the note report.html writes from the counts above.
  std::string note = {};
};

// The number a key value spells, when the whole text is one finite number ("16", "0.5",
// "1e-3"); nullopt for "fractional_odd", "16x", "" or "nan".
std::optional<double> parsePlotNumber(std::string_view text);

// The chart data of one declared plot of `measure`:
// - rows: the ok rows of ok results of `measure` whose keys match spec.where;
// - x (line, scatter): a row key whose value is a number, else a metric of the same row,
//   else "<measure>.<metric>", the other measure's summary figure for the same technique ×
//   variant × asset (worstOf its stats over that measure's summary scope);
// - x (bar), series, facet: "technique", "variant" (technique/variant), "asset" or a row key;
// - a point: the median y of the rows of one series at one x in one chart (a cross-measure x
//   keeps each technique × variant its own point);
// - pareto_front: no other point has x <= its x and a y at least as good, one strictly.
PlotData plotData(const results::Results& results, const results::MeasureDeclaration& measure,
                  const results::PlotSpec& spec);

// Marks PlotPoint::on_front over every series of `chart` (see plotData). A y without a
// direction counts as lower is better.
void markParetoFront(PlotChart* chart, results::Direction y_direction);

}  // namespace tb::report
