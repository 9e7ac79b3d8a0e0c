// The timing part of `tessbench compare`: timings.json of two runs, entry by entry
// (technique, variant, asset, measure), by the two-sided Mann–Whitney U test on the
// repeated samples (mann_whitney.h), the way Google Benchmark's compare.py tests its
// repetitions. A timing is never flagged on fewer than kMinTimingSamples samples a side:
// one sample says nothing about the spread of run-to-run noise.
#pragma once

#include "harness/results/compare.h"
#include "harness/results/timings_json.h"

namespace tb::results {

// The median of a non-empty sample (the mean of the middle two for an even count).
double medianOf(std::vector<double> samples);

// Adds a change (metric "seconds", base and new the sample medians, with the p-value) for
// each timing that changed significantly (p < options.alpha) by more than
// options.time_threshold of the base median, counts the timings tested and those with too
// few samples, and says both in comparison->timing_notes. Entries only one run has are
// ignored: the deterministic comparison already reports a record or measure gone.
void compareTimings(const RunTimings& base, const RunTimings& current,
                    const CompareOptions& options, Comparison* comparison);

}  // namespace tb::results
