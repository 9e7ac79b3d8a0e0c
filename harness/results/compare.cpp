#include "harness/results/compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "harness/results/timing_compare.h"

namespace tb::results {
namespace {

std::string recordName(const Record& record) {
  return record.technique + "/" + record.variant + " " + record.asset;
}

std::string rowName(const MetricRow& row) {
  std::string text;
  for (const auto& [key, value] : row.keys) text += (text.empty() ? "" : " ") + key + "=" + value;
  return text.empty() ? "-" : text;
}

std::string statusText(MeasureStatus status, const std::string& reason) {
  return std::string(toString(status)) + ": " + reason;
}

// The direction a run declared for a metric; kNone when neither run declares it.
Direction directionOf(const Results& base, const Results& current, const std::string& measure,
                      const std::string& metric) {
  for (const Results* results : {&current, &base}) {
    if (const MeasureDeclaration* declaration = results->findMeasure(measure)) {
      if (const MetricSpec* spec = declaration->find(metric)) return spec->direction;
    }
  }
  return Direction::kNone;
}

class Comparer {
 public:
  Comparer(const Results& base, const Results& current, const CompareOptions& options)
      : base_(base), current_(current), options_(options) {}

  Comparison run() {
    std::map<std::string, const Record*> current_records;
    for (const Record& record : current_.records) current_records[recordName(record)] = &record;
    std::set<std::string> seen;
    for (const Record& base_record : base_.records) {
      const std::string name = recordName(base_record);
      seen.insert(name);
      auto it = current_records.find(name);
      if (it == current_records.end()) {
        add({ChangeKind::kMissing, name, "", "", "", 0, 0, "record not in the new run"});
        continue;
      }
      compareRecord(name, base_record, *it->second);
    }
    for (const Record& record : current_.records) {
      if (!seen.contains(recordName(record))) {
        add({ChangeKind::kAdded, recordName(record), "", "", "", 0, 0,
             "record only in the new run"});
      }
    }
    if (base_.context.vulkan_device != current_.context.vulkan_device) {
      result_.context_notes.push_back("Vulkan device differs: base '" +
                                      base_.context.vulkan_device + "', new '" +
                                      current_.context.vulkan_device + "'");
    }
    if (base_.context.selection.suite != current_.context.selection.suite) {
      result_.context_notes.push_back("suite differs: base " + base_.context.selection.suite +
                                      ", new " + current_.context.selection.suite);
    }
    return std::move(result_);
  }

 private:
  void add(MetricChange change) { result_.changes.push_back(std::move(change)); }

  void compareRecord(const std::string& name, const Record& base, const Record& current) {
    for (const MeasureResult& base_measure : base.measures) {
      const MeasureResult* current_measure = nullptr;
      for (const MeasureResult& m : current.measures) {
        if (m.measure == base_measure.measure) current_measure = &m;
      }
      if (base_measure.status != MeasureStatus::kOk) continue;  // nothing measured to lose
      if (current_measure == nullptr) {
        add({ChangeKind::kMissing, name, base_measure.measure, "", "", 0, 0,
             "measure not run in the new run"});
        continue;
      }
      if (current_measure->status != MeasureStatus::kOk) {
        add({ChangeKind::kMissing, name, base_measure.measure, "", "", 0, 0,
             statusText(current_measure->status, current_measure->reason)});
        continue;
      }
      compareRows(name, base_measure, *current_measure);
    }
  }

  void compareRows(const std::string& name, const MeasureResult& base,
                   const MeasureResult& current) {
    std::map<std::map<std::string, std::string>, const MetricRow*> current_rows;
    for (const MetricRow& row : current.rows) current_rows[row.keys] = &row;
    std::set<std::map<std::string, std::string>> seen;
    for (const MetricRow& base_row : base.rows) {
      seen.insert(base_row.keys);
      auto it = current_rows.find(base_row.keys);
      const std::string row = rowName(base_row);
      if (base_row.status != MeasureStatus::kOk) {
        if (it != current_rows.end() && it->second->status == MeasureStatus::kOk) {
          add({ChangeKind::kAdded, name, base.measure, row, "", 0, 0,
               "measured in the new run; base " + statusText(base_row.status, base_row.reason)});
        }
        continue;
      }
      if (it == current_rows.end()) {
        add({ChangeKind::kMissing, name, base.measure, row, "", 0, 0, "row not in the new run"});
        continue;
      }
      const MetricRow& current_row = *it->second;
      if (current_row.status != MeasureStatus::kOk) {
        // Every figure of the row is gone: one line per row says why.
        add({ChangeKind::kMissing, name, base.measure, row, "", 0, 0,
             statusText(current_row.status, current_row.reason)});
        result_.figures_compared += base_row.metrics.size();
        continue;
      }
      for (const Metric& metric : base_row.metrics) {
        ++result_.figures_compared;
        auto found = std::find_if(current_row.metrics.begin(), current_row.metrics.end(),
                                  [&](const Metric& m) { return m.name == metric.name; });
        if (found == current_row.metrics.end()) {
          add({ChangeKind::kMissing, name, base.measure, row, metric.name, metric.value, 0,
               "metric not in the new row"});
          continue;
        }
        compareValue(name, base.measure, row, metric, found->value);
      }
      for (const Metric& metric : current_row.metrics) {
        const bool in_base = std::any_of(base_row.metrics.begin(), base_row.metrics.end(),
                                         [&](const Metric& m) { return m.name == metric.name; });
        if (!in_base) {
          add({ChangeKind::kAdded, name, base.measure, row, metric.name, 0, metric.value,
               "metric only in the new run"});
        }
      }
    }
    for (const MetricRow& row : current.rows) {
      if (!seen.contains(row.keys) && row.status == MeasureStatus::kOk) {
        add({ChangeKind::kAdded, name, current.measure, rowName(row), "", 0, 0,
             "row only in the new run"});
      }
    }
  }

  void compareValue(const std::string& name, const std::string& measure, const std::string& row,
                    const Metric& base, double current) {
    const auto override_it = options_.metric_thresholds.find(base.name);
    const double threshold =
        override_it != options_.metric_thresholds.end() ? override_it->second : options_.threshold;
    const bool both_nan = std::isnan(base.value) && std::isnan(current);
    const double scale = std::max(std::fabs(base.value), std::fabs(current));
    const bool changed = !both_nan && (std::isnan(base.value) != std::isnan(current) ||
                                       std::fabs(current - base.value) > threshold * scale);
    if (!changed) return;
    const Direction direction = directionOf(base_, current_, measure, base.name);
    ChangeKind kind = ChangeKind::kChanged;
    if (direction != Direction::kNone && !std::isnan(base.value) && !std::isnan(current)) {
      const bool worse =
          direction == Direction::kLowerIsBetter ? current > base.value : current < base.value;
      kind = worse ? ChangeKind::kRegression : ChangeKind::kImprovement;
    } else if (direction != Direction::kNone) {
      kind = ChangeKind::kRegression;  // a figure that became NaN (or stopped being one)
    }
    add({kind, name, measure, row, base.name, base.value, current, ""});
  }

  const Results& base_;
  const Results& current_;
  const CompareOptions& options_;
  Comparison result_;
};

// Worst first: by kind (missing, regressions, ...), then by the size of the change.
void sortChanges(Comparison* comparison) {
  std::stable_sort(comparison->changes.begin(), comparison->changes.end(),
                   [](const MetricChange& a, const MetricChange& b) {
                     if (a.kind != b.kind) return a.kind < b.kind;
                     return a.relative_change() > b.relative_change();
                   });
}

std::string formatValue(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15) {
    return fmt::format("{:.0f}", value);
  }
  return fmt::format("{:.6g}", value);
}

}  // namespace

double MetricChange::relative_change() const {
  if (kind == ChangeKind::kMissing || kind == ChangeKind::kAdded) return 0;
  const double scale = std::max(std::fabs(base), std::fabs(current));
  if (!(scale > 0)) return std::isnan(base) != std::isnan(current) ? 1 : 0;
  return std::fabs(current - base) / scale;
}

size_t Comparison::count(ChangeKind kind) const {
  return size_t(std::count_if(changes.begin(), changes.end(),
                              [&](const MetricChange& c) { return c.kind == kind; }));
}

const char* toString(ChangeKind kind) {
  switch (kind) {
    case ChangeKind::kMissing:
      return "missing";
    case ChangeKind::kRegression:
      return "regression";
    case ChangeKind::kChanged:
      return "changed";
    case ChangeKind::kImprovement:
      return "improvement";
    case ChangeKind::kAdded:
      return "added";
  }
  return "unknown";
}

Comparison compareResults(const Results& base, const Results& current,
                          const CompareOptions& options) {
  Comparison comparison = Comparer(base, current, options).run();
  comparison.missing_fails = !options.only_common;
  sortChanges(&comparison);
  return comparison;
}

Comparison compareRuns(const RunData& base, const RunData& current, const CompareOptions& options) {
  Comparison comparison = Comparer(base.results, current.results, options).run();
  comparison.missing_fails = !options.only_common;
  if (!options.timings) {
    comparison.timing_notes.push_back("timings: not compared (--no-timings)");
  } else if (!base.timings || !current.timings) {
    comparison.timing_notes.push_back(std::string("timings: not compared (") +
                                      (!base.timings && !current.timings ? "neither run has"
                                       : !base.timings                   ? "the base run has no"
                                                                         : "the new run has no") +
                                      " timings.json)");
  } else {
    compareTimings(*base.timings, *current.timings, options, &comparison);
  }
  sortChanges(&comparison);
  return comparison;
}

std::string renderComparison(const Comparison& comparison, size_t limit) {
  std::string out = fmt::format(
      "{} figures compared: {} missing, {} regressions, {} changed (no direction), {} "
      "improvements, {} added. {}\n",
      comparison.figures_compared, comparison.count(ChangeKind::kMissing),
      comparison.count(ChangeKind::kRegression), comparison.count(ChangeKind::kChanged),
      comparison.count(ChangeKind::kImprovement), comparison.count(ChangeKind::kAdded),
      comparison.failed() ? "FAIL: the new run lost or worsened figures of the base."
      : comparison.missing_fails || comparison.count(ChangeKind::kMissing) == 0
          ? "PASS."
          : "PASS (--only-common: the missing figures are listed, not failed).");
  for (const std::string& note : comparison.timing_notes) out += note + "\n";
  for (const std::string& note : comparison.context_notes) out += "\nNote: " + note + ".\n";
  if (comparison.changes.empty()) return out;
  out += "\n| change | record | measure | row | metric | base | new | relative | p (U test) |\n";
  out += "|---|---|---|---|---|---|---|---|---|\n";
  const size_t shown = std::min(limit, comparison.changes.size());
  for (size_t i = 0; i < shown; ++i) {
    const MetricChange& c = comparison.changes[i];
    const bool figures = c.kind != ChangeKind::kMissing && c.kind != ChangeKind::kAdded;
    out += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", toString(c.kind), c.record, c.measure,
        c.row, c.metric.empty() ? "(all)" : c.metric,
        figures || c.kind == ChangeKind::kMissing ? (c.metric.empty() ? "" : formatValue(c.base))
                                                  : "",
        figures ? formatValue(c.current) : c.why,
        !figures      ? ""
        : c.base != 0 ? fmt::format("{:+.3g}%", 100 * (c.current - c.base) / std::fabs(c.base))
                      : "from 0",
        std::isnan(c.p_value) ? "" : fmt::format("{:.3g}", c.p_value));
  }
  if (shown < comparison.changes.size()) {
    out +=
        fmt::format("\n{} more changes not shown (--limit).\n", comparison.changes.size() - shown);
  }
  return out;
}

std::string renderTimingTable(const Comparison& comparison) {
  if (comparison.timings.empty()) return "No timing was tested.\n";
  std::string out =
      "| timing | record | measure | samples | base median (s) | new median (s) | change | p "
      "(U test) |\n|---|---|---|---|---|---|---|---|\n";
  for (const TimingComparison& t : comparison.timings) {
    out += fmt::format(
        "| {} | {} | {} | {} vs {} | {} | {} | {} | {:.3g} |\n",
        t.kind == ChangeKind::kChanged ? "same" : toString(t.kind), t.record, t.measure,
        t.base_samples, t.current_samples, formatValue(t.base), formatValue(t.current),
        t.base != 0 ? fmt::format("{:+.3g}%", 100 * (t.current - t.base) / t.base) : "from 0",
        t.p_value);
  }
  return out;
}

}  // namespace tb::results
