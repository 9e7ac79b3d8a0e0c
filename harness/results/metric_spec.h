// Metric declarations: what each figure a measure emits is, in which unit, and which way
// is better. A measure declares its metrics once (harness/measures/metric_table.h); the
// declarations travel in results.json at the measure level, and the renderers and a
// compare read them instead of knowing a measure by name.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/results/decision_input.h"

namespace tb::results {

// The closed set of units. A new metric picks one of these; a unit that does not fit is
// added here (with its spelling in metric_spec.cpp), never written as free text.
enum class Unit {
  kCount,          // "count": how many (points, edges, instructions, samples)
  kBytes,          // "bytes"
  kRatio,          // "ratio": one quantity over another of the same unit
  kDiagonal,       // "rel_diag": a length as a fraction of the bounding-box diagonal
  kDegrees,        // "deg": an angle
  kUlp,            // "ulp": float units in the last place, per component
  kScaleUlp,       // "scale_ulp": a gap over the float spacing at the model's largest |coordinate|
  kWorld,          // "world": a length in the asset's own units
  kPixels,         // "px"
  kSeconds,        // "s"
  kId,             // "id": an index (patch, local edge or corner); -1 for none
  kFlag,           // "flag": 0 or 1
  kEdgeParameter,  // "edge_parameter": position along an edge, 0 at its first corner, 1 at the next
  kCycles,         // "cycles": a compiler's estimate of shader clock cycles (ACO's latency)
};

// Which way a change is an improvement. kNone is declared explicitly for context figures
// (ids, flags, sizes of the input, counts of compared points): a compare never flags them.
enum class Direction { kLowerIsBetter, kHigherIsBetter, kNone };

struct MetricSpec {
  std::string name;  // snake_case, unique within its measure
  Unit unit = Unit::kCount;
  Direction direction = Direction::kNone;
  bool operator==(const MetricSpec&) const = default;
};

// Spellings in results.json. parseUnit / parseDirection return nullopt for anything else.
std::string_view toString(Unit unit);
std::string_view toString(Direction direction);
std::optional<Unit> parseUnit(std::string_view text);
std::optional<Direction> parseDirection(std::string_view text);

// For readers: "fraction of the bounding-box diagonal", "lower is better".
std::string_view describe(Unit unit);
std::string_view describe(Direction direction);
// Every unit, in declaration order (for tests and legends).
const std::vector<Unit>& allUnits();

// Which rows a measure's summary (report.md's matrices and summary tables, `table`,
// `advise`) aggregates: the ok rows whose keys match every entry. A value matches exactly,
// or as a glob when it holds '*' ("*.tese": every key value ending in ".tese"); an empty
// value matches only rows without the key ({"displacement": ""}: undisplaced rows). Empty
// scope: every ok row. Used where rows of one record are not alike (instructions: TCS and TES
// stages, SPIR-V and hand counts), so a median over all of them would mean nothing.
using RowScope = std::map<std::string, std::string>;
bool rowInScope(const RowScope& scope, const std::map<std::string, std::string>& keys);

// What a chart of a measure's rows shows (report.html draws it with Chart.js); declared by
// the measure so no renderer knows a measure by name.
enum class PlotKind { kLine, kScatter, kBar };
// How the rows of one series at one x become one point: their median, or their largest
// value (a count that is 0 on most rows and not on a few: cracks).
enum class PlotReduce { kMedian, kMax };
std::string_view toString(PlotReduce reduce);  // "median", "max"
std::optional<PlotReduce> parsePlotReduce(std::string_view text);
std::string_view toString(PlotKind kind);  // "line", "scatter", "bar"
std::optional<PlotKind> parsePlotKind(std::string_view text);
struct PlotSpec {
  std::string title;  // "Memory ratio against tessellation level"
  PlotKind kind = PlotKind::kScatter;
  // The x axis: a row key whose values are numbers ("level"), a metric of the same row, or
  // "<measure>.<metric>": another measure's summary figure (its worst value over that
  // measure's scope) for the same technique × variant × asset (error against instructions).
  // For kBar: a row key or "variant" (one bar per value).
  std::string x;
  std::string y;  // a metric of this measure
  // What one series (one colour) is: "technique", "variant" (technique/variant), "asset", or
  // a row key (one series per value: "backend", "policy"); harness/report/plot_data.h.
  std::string series = "technique";
  // "" (one chart), "asset" (one chart per asset) or a row key (one chart per value).
  std::string facet = {};
  // The rows plotted (as RowScope); rows of one series at one x reduce by `reduce`.
  RowScope where = {};
  bool log_x = false;
  bool log_y = false;
  // Mark the points no other point beats on both axes (lower x and better y).
  bool pareto_front = false;
  PlotReduce reduce = PlotReduce::kMedian;
  bool operator==(const PlotSpec&) const = default;
};

// A side-by-side comparison a measure declares: per facet (an asset, a camera path), a table
// that opens the measure's section of report.md and a grouped bar chart in report.html. One
// line (bar group) per technique, its default variant (control variants never); one column
// (bar) per value of `column_key` among the compared rows (control rows never), holding
// `metric`; then `extra_columns`, figures read from the same rows. The best `column_key`
// cell of a line (by the metric's direction; lower when it has none) is in bold.
struct ComparisonColumn {
  std::string label;   // the column's header and bar series: "uniform"
  std::string metric;  // a metric of the compared rows: "uniform_triangles_per_frame"
  bool operator==(const ComparisonColumn&) const = default;
};
struct ComparisonSpec {
  // The lead line: what the figures are and which way is better.
  std::string title;
  RowScope where = {};     // the rows compared ({"summary": "max_error_1px"})
  std::string column_key;  // "policy": a column per value
  std::string metric;      // "triangles_per_frame_at_target"
  // A flag metric: a row with it 0 shows no figure ("target_reached"); empty: none.
  std::string valid_flag = {};
  std::vector<ComparisonColumn> extra_columns = {};
  // "asset" or row keys: a table (chart) per combination of values. Any other row key of the
  // compared rows with more than one value splits the tables too (spacing in --suite full).
  std::vector<std::string> facets = {"asset"};
  // Row keys that never split the tables: they vary with the column (the name a compiler
  // gives an executable on each family).
  std::vector<std::string> ignore_keys = {};
  // More figures of the same row, shown after `metric` in each column_key cell
  // ("433 / 48 / 20"); the bold and the charts follow `metric` alone. Empty: none.
  std::vector<std::string> cell_metrics = {};
  bool operator==(const ComparisonSpec&) const = default;
};

// A compiler engineer's summary of a measure's rows, the way Mesa's shader-db reports a
// compiler change: per value of `group_key` (one summary per GPU family), each metric's
// total over the programs both runs have, over the programs it changed in, and how many
// it helped and hurt (by the metric's direction). A program is a row, named by its
// record's technique, variant and asset and its keys but `group_key` and `ignore_keys`.
struct ShaderDbSpec {
  std::string group_key;                 // "family"
  std::vector<std::string> ignore_keys;  // keys that do not name a program ("driver")
  std::vector<std::string> metrics;      // in print order
  bool operator==(const ShaderDbSpec&) const = default;
};

// A measure's declaration, as results.json and the renderers see it.
struct MeasureDeclaration {
  std::string measure;  // measure id, e.g. "memory"
  std::string title;
  std::string description;
  std::vector<MetricSpec> metrics;    // in the order rows emit them
  std::vector<std::string> headline;  // names from `metrics`, what a summary shows first
  // Notes that hold for every record of the measure (definitions, method); rendered once
  // under the measure's heading. Notes about one record live in MeasureResult::notes.
  std::vector<std::string> notes;
  RowScope summary_scope = {};       // the rows summaries aggregate (empty: every ok row)
  std::vector<PlotSpec> plots = {};  // charts of report.html, in order
  // Rows made to show a failure (a crack-unsafe policy, a deliberately loosened bound): never
  // recommended, marked as controls in reports, left out of summaries and comparisons. A row
  // is a control when it is in the scope of any entry (rowInScope).
  std::vector<RowScope> control_rows = {};
  // Side-by-side tables (report.md, opening the section) and bar charts (report.html).
  std::vector<ComparisonSpec> comparisons = {};
  // The figures a decision, the answers and the report's tables read (decision_input.h).
  std::vector<DecisionInput> decision_inputs = {};
  // The shader-db summary `compare` prints of the measure (empty group_key: none).
  ShaderDbSpec shader_db = {};
  const MetricSpec* find(std::string_view name) const;
};

// Whether a row of `declaration`'s measure is a control (MeasureDeclaration::control_rows).
bool isControlRow(const MeasureDeclaration& declaration,
                  const std::map<std::string, std::string>& keys);

}  // namespace tb::results
