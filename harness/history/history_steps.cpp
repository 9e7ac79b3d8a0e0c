// The steps of history_series.h: what moved between consecutive runs of one device and
// suite, by compare's own rules (results/compare.h, timing_compare.h), so that a step in
// the history is exactly what `tessbench compare` of the two runs would flag.
#include <algorithm>
#include <cassert>
#include <map>
#include <tuple>

#include "harness/history/history_series.h"
#include "harness/results/timing_compare.h"

namespace tb::history {
namespace {

using StepKey = std::pair<std::string, std::string>;  // technique/variant, measure

std::string resultKey(const StoredResult& r) {
  return r.technique + '\x1f' + r.variant + '\x1f' + r.asset + '\x1f' + r.parameters + '\x1f' +
         r.measure;
}

const results::MeasureDeclaration* declarationOf(const RunContent& run,
                                                 const std::string& measure) {
  for (const results::MeasureDeclaration& d : run.declarations)
    if (d.measure == measure) return &d;
  return nullptr;
}

// One record with one measure result, and that measure's declaration: what compare needs
// to judge one stored result against another.
results::Results oneResult(const RunContent& run, const StoredResult& stored,
                           const results::MeasureResult& result) {
  results::Results single;
  if (const results::MeasureDeclaration* d = declarationOf(run, stored.measure))
    single.measures.push_back(*d);
  results::Record record;
  record.technique = stored.technique;
  record.variant = stored.variant;
  record.asset = stored.asset;
  record.measures.push_back(result);
  single.records.push_back(std::move(record));
  return single;
}

bool moved(results::ChangeKind kind) {
  return kind == results::ChangeKind::kRegression || kind == results::ChangeKind::kChanged ||
         kind == results::ChangeKind::kImprovement;
}

void figureSteps(const RunContent& base, const RunContent& current, const ReportOptions& options,
                 PayloadCache& payloads, std::map<StepKey, Step>* steps) {
  std::map<std::string, const StoredResult*> before;
  for (const StoredResult& r : base.results) before[resultKey(r)] = &r;
  for (const StoredResult& now : current.results) {
    const auto it = before.find(resultKey(now));
    if (it == before.end() || it->second->payload == now.payload) continue;  // same bytes
    if (!assetPicked(options.assets, now.asset)) continue;
    const results::Comparison comparison = results::compareResults(
        oneResult(base, *it->second, payloads.get(it->second->payload)),
        oneResult(current, now, payloads.get(now.payload)), options.compare);
    for (const results::MetricChange& change : comparison.changes) {
      if (!moved(change.kind)) continue;
      Step& step = (*steps)[{now.technique + "/" + now.variant, now.measure}];
      step.figures.push_back({change.kind, now.asset, change.row, change.metric, change.base,
                              change.current, NAN, change.relative_change()});
    }
  }
}

void timingSteps(const RunContent& base, const RunContent& current, const ReportOptions& options,
                 std::map<StepKey, Step>* steps) {
  if (!base.timings || !current.timings || !options.compare.timings) return;
  results::Comparison comparison;
  results::compareTimings(*base.timings, *current.timings, options.compare, &comparison);
  for (const results::TimingComparison& t : comparison.timings) {
    if (t.kind == results::ChangeKind::kChanged) continue;  // not flagged
    const size_t space = t.record.find(' ');
    const std::string series = t.record.substr(0, space);
    const std::string asset = t.record.substr(space + 1);
    if (!assetPicked(options.assets, asset)) continue;
    const double scale = std::max(std::fabs(t.base), std::fabs(t.current));
    Step& step = (*steps)[{series, t.measure}];
    step.figures.push_back({t.kind, asset,
                            "timing, " + std::to_string(t.base_samples) + " vs " +
                                std::to_string(t.current_samples) + " samples",
                            "seconds", t.base, t.current, t.p_value,
                            scale > 0 ? std::fabs(t.current - t.base) / scale : 0});
  }
}

void sortFigures(Step* step) {
  std::stable_sort(step->figures.begin(), step->figures.end(),
                   [](const StepFigure& a, const StepFigure& b) {
                     if (a.kind != b.kind) return a.kind < b.kind;
                     return a.relative > b.relative;
                   });
}

}  // namespace

std::vector<Step> findSteps(const std::vector<RunContent>& runs, size_t group,
                            const ReportOptions& options, PayloadCache& payloads) {
  std::vector<Step> found;
  for (size_t run = 1; run < runs.size(); ++run) {
    std::map<StepKey, Step> figures, timings;
    figureSteps(runs[run - 1], runs[run], options, payloads, &figures);
    timingSteps(runs[run - 1], runs[run], options, &timings);
    for (auto* steps : {&figures, &timings}) {
      for (auto& [key, step] : *steps) {
        step.group = group;
        step.run = run;
        step.series = key.first;
        step.measure = key.second;
        step.timing = steps == &timings;
        sortFigures(&step);
        found.push_back(std::move(step));
      }
    }
  }
  return found;
}

}  // namespace tb::history
