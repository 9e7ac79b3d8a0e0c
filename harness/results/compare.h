// Comparing two runs record by record, row by row and metric by metric, by each metric's
// declared direction (metric_spec.h): the deterministic figures of results.json by exact or
// relative thresholds. Timings (timings.json, one entry per record × measure) are compared
// apart, by repeated samples and a Mann–Whitney U test (timing_compare.h), as Google
// Benchmark's compare.py does for its own JSON; a timing with one sample is never flagged.
//
// A figure the base run measured and the new run does not have is *missing*, never a pass:
// a row the new run skipped (no Vulkan device) or failed, a row or record it lacks, a metric
// its row lacks. Missing figures fail a comparison like regressions do.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "harness/results/results_model.h"
#include "harness/results/timings_json.h"

namespace tb::results {

struct CompareOptions {
  // A change counts when |new − base| > threshold × max(|base|, |new|): relative, so 0 vs
  // anything non-zero always counts. 0 = exact. Per metric name, `metric_thresholds` wins.
  double threshold = 1e-9;
  std::map<std::string, double> metric_thresholds;
  // Timings: compared when both runs have timings.json and `timings` is set. A timing with
  // at least kMinTimingSamples samples on each side is a regression when the U test's
  // two-sided p < alpha and the new median exceeds the base median by more than
  // time_threshold (relative); an improvement when p < alpha and it is below by as much.
  bool timings = true;
  double alpha = 0.05;
  double time_threshold = 0.05;
  // Compare the figures both runs have (`compare --only-common`): a figure only the base has
  // is still listed as missing, but does not fail the comparison.
  bool only_common = false;
};

// compare.py's UTEST_MIN_REPETITIONS: fewer samples on either side and a timing is not
// tested. Below kRecommendedTimingSamples the test has little power (with 2 against 2 no
// p-value goes below 1/3; with 4 against 4 the smallest is 0.029), as compare.py warns.
inline constexpr size_t kMinTimingSamples = 2;
inline constexpr size_t kRecommendedTimingSamples = 9;

enum class ChangeKind {
  kMissing,      // base has the figure, new does not (skipped, failed or absent)
  kRegression,   // changed in the declared bad direction beyond the threshold
  kChanged,      // changed beyond the threshold, the metric has no direction
  kImprovement,  // changed in the declared good direction beyond the threshold
  kAdded,        // new has a figure base did not
};

struct MetricChange {
  ChangeKind kind = ChangeKind::kChanged;
  std::string record;  // "technique/variant asset"
  std::string measure;
  std::string row;     // the row's keys, "k=v k=v"
  std::string metric;  // empty when the whole row or record is missing or added
  double base = 0, current = 0;
  std::string why;  // for missing and added: what happened (e.g. "skipped: no Vulkan device")
  // A timing's two-sided Mann–Whitney p-value (metric "seconds"; base and current are the
  // medians of the samples); NaN for a deterministic figure.
  double p_value = NAN;
  // |new − base| / max(|base|, |new|): 0 when equal, 1 from or to zero; 0 for missing/added.
  double relative_change() const;
};

// One timing put to the U test (every one, flagged or not: `compare --all-timings`).
struct TimingComparison {
  std::string record;  // "technique/variant asset"
  std::string measure;
  size_t base_samples = 0, current_samples = 0;
  double base = 0, current = 0;            // median wall seconds of each side's samples, s
  double p_value = NAN;                    // two-sided Mann–Whitney U test
  ChangeKind kind = ChangeKind::kChanged;  // kRegression, kImprovement, or kChanged: neither
};

struct Comparison {
  std::vector<MetricChange>
      changes;                  // worst first: missing, regressions, changed, improvements, added
  size_t figures_compared = 0;  // base figures (metric values) looked at
  std::vector<std::string> context_notes;  // e.g. the two runs used different devices
  size_t timings_tested = 0;               // record × measure timings put to the U test
  size_t timings_untested = 0;             // in both runs, but with too few samples on a side
  // One line each: how timings were compared, or why they were not.
  std::vector<std::string> timing_notes;
  std::vector<TimingComparison> timings;  // every timing tested, in the base run's order
  bool missing_fails = true;              // false under CompareOptions::only_common
  size_t count(ChangeKind kind) const;
  // What fails a comparison: a regression, or a missing figure unless only common figures
  // are compared.
  bool failed() const {
    return count(ChangeKind::kRegression) + (missing_fails ? count(ChangeKind::kMissing) : 0) > 0;
  }
};

// The deterministic figures only (no timing is looked at).
Comparison compareResults(const Results& base, const Results& current,
                          const CompareOptions& options);

// What compare reads from a finished run folder: results.json, and timings.json when there.
struct RunData {
  Results results;
  std::optional<RunTimings> timings;
};

// The deterministic figures, then the timings (unless options.timings is off, or a run has
// no timings.json: a timing note says so), all changes worst first.
Comparison compareRuns(const RunData& base, const RunData& current, const CompareOptions& options);

const char* toString(ChangeKind kind);

// Which records, assets and measures a comparison looks at (`compare --technique/--asset/
// --measure`); an empty list keeps every one. An asset matches by its full name
// ("opensubdiv/loop_cube") or the part after the last '/' ("loop_cube").
struct RunFilter {
  std::vector<std::string> techniques, assets, measures;
  bool empty() const { return techniques.empty() && assets.empty() && measures.empty(); }
};
// Keeps the records (and timings) the filter selects, and of them the measures it selects.
void filterRun(const RunFilter& filter, RunData* run);
// The filter's values that select nothing in any of `runs` (a misspelt name), as
// "--technique X" one each.
std::vector<std::string> unmatchedFilterValues(const RunFilter& filter,
                                               const std::vector<const RunData*>& runs);

// The comparison as markdown: a line of counts, the timing notes, the context notes, and a
// table of at most `limit` changes, worst first (the count of those left out is said).
std::string renderComparison(const Comparison& comparison, size_t limit);
// Every timing tested, flagged or not, as a markdown table (old, new, change, p-value), like
// Google Benchmark's compare.py lists its benchmarks; one line when none was tested.
std::string renderTimingTable(const Comparison& comparison);

}  // namespace tb::results
