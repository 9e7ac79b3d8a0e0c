// What `tessbench history report` shows, computed from the database: the runs grouped by
// device and suite (figures of two devices never share a line), per measure and headline
// metric a line per technique/variant over the group's runs in commit order, and the steps:
// figures that moved between consecutive runs of a group (deterministic figures beyond
// compare's threshold, timings by compare's U test). Rendered by history_html.h and
// history_markdown.h; deterministic for the same database and options.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "harness/history/history_store.h"
#include "harness/results/compare.h"

namespace tb::history {

// How a line joins the assets' figures at one run: their median or their worst (by the
// metric's direction; the largest when it has none). Each asset's figure is itself the worst
// of its rows in the measure's summary scope.
enum class Aggregate { kMedian, kWorst };

struct ReportOptions {
  // One line per technique/variant and picked asset (full or short name); empty: one line
  // per technique/variant, its assets joined by `aggregate`. Steps are looked for in the
  // picked assets only.
  std::vector<std::string> assets;
  Aggregate aggregate = Aggregate::kMedian;
  // threshold / metric_thresholds: when a deterministic figure moved; alpha and
  // time_threshold: when a timing did (compare's U test).
  results::CompareOptions compare;
};

// The runs of one device and suite, in commit order.
struct RunGroup {
  std::string device, suite;
  std::vector<RunInfo> runs;
};

// One figure that moved between two consecutive runs of a group.
struct StepFigure {
  results::ChangeKind kind = results::ChangeKind::kChanged;  // regression, changed, improvement
  std::string asset;
  std::string row;               // the row's keys "k=v k=v"; for a timing "timing, N vs M samples"
  std::string metric;            // "seconds" for a timing
  double base = 0, current = 0;  // the figure in its unit; a timing's sample medians, s
  double p_value = NAN;          // a timing's two-sided U test p; NaN for a figure
  double relative = 0;           // |new − base| / max(|base|, |new|)
};

// A step: the figures of one measure of one technique/variant that moved from one run of a
// group to the next (deterministic figures and timings are separate steps).
struct Step {
  size_t group = 0;    // in HistoryView::groups
  size_t run = 0;      // the later run, an index into the group's runs (>= 1)
  std::string series;  // "technique/variant"
  std::string measure;
  bool timing = false;
  std::vector<StepFigure> figures;  // worst first
  const StepFigure& worst() const { return figures.front(); }
};

struct SeriesPoint {
  size_t run = 0;    // index into the group's runs
  double value = 0;  // in the chart's unit
};

struct ChartSeries {
  std::string name;                 // "acc/default", or "acc/default opensubdiv/catmark_cube"
  std::string series;               // "technique/variant"
  std::string asset;                // the picked asset; empty for an aggregate over every asset
  std::vector<SeriesPoint> points;  // runs without the figure have no point
};

// One chart: a headline metric of a measure (or its timing: metric "seconds") in one group.
struct Chart {
  size_t group = 0;
  std::string measure, metric;
  std::string unit;                 // results::toString(Unit), "s" for a timing
  std::string direction;            // results::toString(Direction)
  std::vector<ChartSeries> series;  // by name
};

struct HistoryView {
  std::vector<RunGroup> groups;
  std::vector<Chart> charts;  // by group, measure, then the headline's order, timing last
  std::vector<Step> steps;    // worst first (kind, then relative change), ties in run order
  ReportOptions options;
};

HistoryView buildHistory(HistoryDb& history, const ReportOptions& options);

// Whether a step marks the point of `series` at `run` of `chart`: same group, run, measure,
// technique/variant, kind (timing or figure) and, for a picked asset's line, that asset.
bool stepMarks(const Step& step, const Chart& chart, const ChartSeries& series, size_t run);

// True when `asset` is among `picked` (by full or short name), or nothing is picked.
bool assetPicked(const std::vector<std::string>& picked, const std::string& asset);

// Internal to history_series.cpp and history_steps.cpp: a run's measure results as the
// database holds them, and the parsed figures (cached by payload).
struct StoredResult {
  std::string technique, variant, asset, parameters, measure;
  int64_t payload = 0;
};
struct RunContent {
  std::vector<StoredResult> results;  // in record order
  std::vector<results::MeasureDeclaration> declarations;
  std::optional<results::RunTimings> timings;
};
class PayloadCache {
 public:
  explicit PayloadCache(Database& db) : db_(db) {}
  const results::MeasureResult& get(int64_t payload);

 private:
  Database& db_;
  std::map<int64_t, results::MeasureResult> parsed_;
};
std::vector<Step> findSteps(const std::vector<RunContent>& runs, size_t group,
                            const ReportOptions& options, PayloadCache& payloads);

}  // namespace tb::history
