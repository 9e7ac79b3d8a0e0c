#include "harness/results/compare_json.h"

#include <cmath>

namespace tb::results {
namespace {

using Json = nlohmann::ordered_json;

// NaN and infinities have no JSON spelling: null.
Json numberOrNull(double value) { return std::isfinite(value) ? Json(value) : Json(); }

}  // namespace

Json comparisonToJson(const Comparison& comparison) {
  Json counts = Json::object();
  for (ChangeKind kind : {ChangeKind::kMissing, ChangeKind::kRegression, ChangeKind::kChanged,
                          ChangeKind::kImprovement, ChangeKind::kAdded}) {
    counts[toString(kind)] = comparison.count(kind);
  }
  Json changes = Json::array();
  for (const MetricChange& c : comparison.changes) {
    const bool figures = c.kind != ChangeKind::kMissing && c.kind != ChangeKind::kAdded;
    changes.push_back({{"kind", toString(c.kind)},
                       {"record", c.record},
                       {"measure", c.measure},
                       {"row", c.row},
                       {"metric", c.metric},
                       {"base", c.metric.empty() ? Json() : numberOrNull(c.base)},
                       {"new", figures ? numberOrNull(c.current) : Json()},
                       {"relative_change", figures ? numberOrNull(c.relative_change()) : Json()},
                       {"p_value", numberOrNull(c.p_value)},
                       {"why", c.why}});
  }
  Json timings = Json::array();
  for (const TimingComparison& t : comparison.timings) {
    timings.push_back({{"kind", t.kind == ChangeKind::kChanged ? "same" : toString(t.kind)},
                       {"record", t.record},
                       {"measure", t.measure},
                       {"base_samples", t.base_samples},
                       {"new_samples", t.current_samples},
                       {"base", numberOrNull(t.base)},
                       {"new", numberOrNull(t.current)},
                       {"p_value", numberOrNull(t.p_value)}});
  }
  return {{"failed", comparison.failed()},
          {"only_common", !comparison.missing_fails},
          {"figures_compared", comparison.figures_compared},
          {"counts", counts},
          {"changes", changes},
          {"timings_tested", comparison.timings_tested},
          {"timings_untested", comparison.timings_untested},
          {"timings", timings},
          {"timing_notes", comparison.timing_notes},
          {"context_notes", comparison.context_notes}};
}

}  // namespace tb::results
