// The side-by-side comparisons a measure declares (results::ComparisonSpec): per facet (an
// asset × camera path), one line per technique's default variant and one column per value of
// a row key (policies), then extra figures (uniform, ideal). report.md draws each group as
// a table opening the measure's section; report.html as a grouped bar chart (the PlotData
// below). Pure over the results model; no measure is named here.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/report/plot_data.h"
#include "harness/results/results_model.h"

namespace tb::report {

struct ComparisonCell {
  // The figure, in ComparisonTable::unit (triangles per frame: count; fewer best when the
  // metric is lower-is-better); nullopt when the line has no such row, the row lacks the
  // metric, or its valid flag is 0 (e.g. the 1 px target not reached).
  std::optional<double> value;
  // The spec's cell_metrics of the same row, in order (nullopt where the row lacks one).
  std::vector<std::optional<double>> more = {};
  // The best of the line's column_key cells (ties: each of them); never where the group has
  // one column_key value only.
  bool best = false;
};

struct ComparisonLine {
  std::string technique;
  std::string variant;                // the technique's default variant
  std::vector<ComparisonCell> cells;  // one per ComparisonGroup::columns
};

// One table (chart): the compared rows sharing one value of every facet.
struct ComparisonGroup {
  // The facets' values in order: {"asset", "opensubdiv/catmark_cube"}, {"camera_path", "orbit"}.
  std::vector<std::pair<std::string, std::string>> facets;
  std::vector<std::string> columns;   // the column_key values, then the extra columns' labels
  size_t key_columns = 0;             // how many of `columns` are column_key values
  std::vector<ComparisonLine> lines;  // in the run's technique order
  // "opensubdiv/catmark_cube, camera_path orbit": the asset bare, a row key with its name.
  std::string name() const;
};

struct ComparisonTable {
  std::string measure;
  results::ComparisonSpec spec;
  std::string unit;  // the metric's unit spelling ("count"); empty when undeclared
  results::Direction direction = results::Direction::kNone;  // the metric's; kNone: lower best
  // The column_key values of the control rows left out ("error_bound_loose"), first seen first.
  std::vector<std::string> controls_left_out;
  size_t rows_used = 0;  // compared rows (count): default variants, in spec.where, not controls
  std::vector<ComparisonGroup> groups;  // assets in the run's order, then as met
};

// The comparison of `spec` over the ok rows of `measure`'s ok results: records of each
// technique's default variant that is not a control variant; rows in spec.where with the
// column key, not control rows. A row key other than the facets and the column key that takes
// more than one value over those rows is a facet too (after the declared ones, by name). A
// column or extra column no line of a group has is left out of that group.
ComparisonTable comparisonTable(const results::Results& results,
                                const results::MeasureDeclaration& measure,
                                const results::ComparisonSpec& spec);

// The grouped bar chart of a comparison: a chart per group (facet = the group's name),
// categories = the techniques, a series per column (column_key values, then the extras); a
// missing cell is no bar. spec.kind = kBar, spec.title = the comparison's title.
PlotData comparisonPlot(const ComparisonTable& table);

}  // namespace tb::report
