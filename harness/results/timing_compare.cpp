#include "harness/results/timing_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <map>
#include <tuple>

#include "harness/results/mann_whitney.h"

namespace tb::results {
namespace {

using TimingKey = std::tuple<std::string, std::string, std::string, std::string>;

TimingKey keyOf(const TimingEntry& entry) {
  return {entry.technique, entry.variant, entry.asset, entry.measure};
}

}  // namespace

double medianOf(std::vector<double> samples) {
  assert(!samples.empty());
  std::sort(samples.begin(), samples.end());
  const size_t middle = samples.size() / 2;
  return samples.size() % 2 == 1 ? samples[middle] : 0.5 * (samples[middle - 1] + samples[middle]);
}

void compareTimings(const RunTimings& base, const RunTimings& current,
                    const CompareOptions& options, Comparison* comparison) {
  std::map<TimingKey, const TimingEntry*> current_entries;
  for (const TimingEntry& entry : current.measures) current_entries[keyOf(entry)] = &entry;
  size_t few_samples = 0;  // tested, but with fewer than kRecommendedTimingSamples a side
  for (const TimingEntry& base_entry : base.measures) {
    const auto it = current_entries.find(keyOf(base_entry));
    if (it == current_entries.end()) continue;
    const TimingEntry& current_entry = *it->second;
    const size_t n_base = base_entry.samples.size(), n_current = current_entry.samples.size();
    if (std::min(n_base, n_current) < kMinTimingSamples) {
      ++comparison->timings_untested;
      continue;
    }
    ++comparison->timings_tested;
    if (std::min(n_base, n_current) < kRecommendedTimingSamples) ++few_samples;
    const double p = mannWhitneyU(base_entry.samples, current_entry.samples).p_value;
    const double base_median = medianOf(base_entry.samples);
    const double current_median = medianOf(current_entry.samples);
    ChangeKind kind = ChangeKind::kChanged;  // not flagged
    if (p < options.alpha && current_median > base_median * (1 + options.time_threshold)) {
      kind = ChangeKind::kRegression;
    } else if (p < options.alpha && current_median < base_median * (1 - options.time_threshold)) {
      kind = ChangeKind::kImprovement;
    }
    const std::string record =
        base_entry.technique + "/" + base_entry.variant + " " + base_entry.asset;
    comparison->timings.push_back(
        {record, base_entry.measure, n_base, n_current, base_median, current_median, p, kind});
    if (kind == ChangeKind::kChanged) continue;  // not significant, or within the threshold
    MetricChange change;
    change.kind = kind;
    change.record = record;
    change.measure = base_entry.measure;
    change.row = fmt::format("timing, {} vs {} samples", n_base, n_current);
    change.metric = "seconds";
    change.base = base_median;
    change.current = current_median;
    change.p_value = p;
    comparison->changes.push_back(std::move(change));
  }
  if (comparison->timings_tested > 0 || comparison->timings_untested == 0) {
    comparison->timing_notes.push_back(fmt::format(
        "timings: {} tested by a two-sided Mann–Whitney U test (a change when p < {:g} and the "
        "median moved by more than {:g}%)",
        comparison->timings_tested, options.alpha, 100 * options.time_threshold));
  }
  if (few_samples > 0) {
    comparison->timing_notes.push_back(fmt::format(
        "timings: {} of them with fewer than {} samples a side; the test has little power "
        "there (run --repetitions {} or more)",
        few_samples, kRecommendedTimingSamples, kRecommendedTimingSamples));
  }
  if (comparison->timings_untested > 0) {
    comparison->timing_notes.push_back(fmt::format(
        "timings: {} not tested (fewer than {} samples per side; run --repetitions ≥ {})",
        comparison->timings_untested, kMinTimingSamples, kMinTimingSamples));
  }
}

}  // namespace tb::results
