// Summaries of a measure's rows: per technique × variant × asset (or × variant alone), the
// min / median / max of each headline metric over the rows of the measure's summary scope
// (levels, spacings, backends, frames, ...). report.md, report.html, `table` and `advise`
// read these; none of them knows a measure by name: which metrics, which rows and which way
// is better all come from the measure's declaration.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

// min / median / max of one metric over the rows a summary line aggregates. median is the
// middle value, or the mean of the two middle ones.
struct MetricStats {
  double min = 0;
  double median = 0;
  double max = 0;
  size_t rows = 0;  // rows that emitted the metric
};

// The value a reader can count on: max when lower is better, min when higher is better,
// the median for a metric with no direction.
double worstOf(const MetricStats& stats, results::Direction direction);

// One technique × variant (× asset) of one measure.
struct SummaryLine {
  std::string technique;
  std::string variant;
  std::string asset;  // empty in a line aggregated over assets
  // The rows' path key (tessellator | compute) where the measure keys its rows by the
  // pipeline's path (cracks, memory): a line per path; empty where it does not.
  std::string path;
  std::map<std::string, MetricStats> stats;  // by metric name; absent: no row emitted it
  size_t ok_rows = 0;                        // rows in the summary scope
  size_t skipped_rows = 0;                   // rows (or whole records) skipped, in scope or not
  size_t failed_rows = 0;
  std::string first_reason;  // the first skipped/failed reason, for a status cell
  const MetricStats* find(const std::string& metric) const;
};

struct MeasureSummary {
  std::string measure;
  const results::MeasureDeclaration* declaration = nullptr;  // null for undeclared results
  std::vector<std::string> metrics;                          // the metrics summarised, in order
  std::vector<SummaryLine> lines;                            // in record order
};

enum class SummaryGrouping {
  kPerAsset,      // a line per technique × variant × asset
  kAcrossAssets,  // a line per technique × variant, over every asset's rows
};

// Summarises `measure` over the rows in its declaration's summary scope, its control rows
// (MeasureDeclaration::control_rows) left out. `metrics` empty:
// the declared headline metrics (every emitted metric when the declaration has none).
// `keep`, when given, further selects the rows (e.g. the conservative culling policies).
// `split_paths`: a line per value of the rows' path key (SummaryLine::path) where the
// measure has one; otherwise one line holds every path's rows.
MeasureSummary summarizeMeasure(const results::Results& results, const std::string& measure,
                                SummaryGrouping grouping,
                                const std::vector<std::string>& metrics = {},
                                const std::function<bool(const results::MetricRow&)>& keep = {},
                                bool split_paths = false);

// The measure ids of the run, in the order results.json declares them (sorted), then any
// undeclared one in order of appearance.
std::vector<std::string> measureIds(const results::Results& results);

// The techniques of the run in selection order (records' order when the selection is
// empty), each with its variants; the first variant is the technique's default.
std::vector<results::RunSelection::TechniqueVariants> techniquesOf(const results::Results& results);

// The direction of a declared metric; kNone when undeclared.
// Whether technique/variant is a control (results::RunSelection::TechniqueVariants::controls):
// made to show a failure, never a choice.
bool isControl(const results::Results& results, const std::string& technique,
               const std::string& variant);

results::Direction directionOf(const results::Results& results, const std::string& measure,
                               const std::string& metric);
// The unit spelling of a declared metric ("rel_diag"); empty when undeclared.
std::string unitOf(const results::Results& results, const std::string& measure,
                   const std::string& metric);

}  // namespace tb::report
