// Comparing two runs record by record, row by row and metric by metric, by each metric's
// declared direction (metric_spec.h). This is the deterministic part of regression tracking:
// results.json holds no timings (they are in timings.json and Google Benchmark's JSON).
//
// A figure the base run measured and the new run does not have is *missing*, never a pass:
// a row the new run skipped (no Vulkan device) or failed, a row or record it lacks, a metric
// its row lacks. Missing figures fail a comparison like regressions do.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb {

struct CompareOptions {
  // A change counts when |new − base| > threshold × max(|base|, |new|): relative, so 0 vs
  // anything non-zero always counts. 0 = exact. Per metric name, `metric_thresholds` wins.
  double threshold = 1e-9;
  std::map<std::string, double> metric_thresholds;
};

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
  // |new − base| / max(|base|, |new|): 0 when equal, 1 from or to zero; 0 for missing/added.
  double relative_change() const;
};

struct Comparison {
  std::vector<MetricChange> changes;  // worst first: missing, regressions, changed, improvements, added
  size_t figures_compared = 0;        // base figures (metric values) looked at
  std::vector<std::string> context_notes;  // e.g. the two runs used different devices
  size_t count(ChangeKind kind) const;
  // What fails a comparison: a regression or a missing figure.
  bool failed() const { return count(ChangeKind::kMissing) + count(ChangeKind::kRegression) > 0; }
};

Comparison compareResults(const Results& base, const Results& current,
                          const CompareOptions& options);

const char* toString(ChangeKind kind);

// The comparison as markdown: a line of counts, the context notes, and a table of at most
// `limit` changes, worst first (the count of those left out is said).
std::string renderComparison(const Comparison& comparison, size_t limit);

}  // namespace tb
