#include <fmt/format.h>

#include <cassert>
#include <cmath>

#include "harness/history/history_render.h"

namespace tb::history {
namespace {

// Figures listed per step at most; the rest are counted.
constexpr size_t kFiguresPerStep = 10;

std::string aggregateText(const ReportOptions& options) {
  if (!options.assets.empty()) return "a line per picked asset";
  return options.aggregate == Aggregate::kMedian ? "the median over assets"
                                                 : "the worst over assets";
}

}  // namespace

std::string stepChange(const StepFigure& figure) { return results::toString(figure.kind); }

std::string percentChange(double base, double current) {
  if (std::isnan(base) || std::isnan(current)) return "";
  if (base == 0) return current == 0 ? "+0%" : "from 0";
  return fmt::format("{:+.3g}%", 100 * (current - base) / std::fabs(base));
}

std::string figureText(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15)
    return fmt::format("{:.0f}", value);
  return fmt::format("{:.6g}", value);
}

std::string renderHistoryMarkdown(const HistoryView& view) {
  const results::CompareOptions& compare = view.options.compare;
  size_t runs = 0;
  for (const RunGroup& group : view.groups) runs += group.runs.size();
  std::string out = fmt::format(
      "# tessbench history\n\n{} runs in {} device × suite group{}; {} steps flagged, worst "
      "first. A step: between two consecutive runs of one device and suite, a deterministic "
      "figure moved by more than compare's threshold ({:g} relative), or a timing moved by more "
      "than {:g}% with p < {:g} (two-sided Mann–Whitney U test). Charts (history.html) show "
      "{}.\n",
      runs, view.groups.size(), view.groups.size() == 1 ? "" : "s", view.steps.size(),
      compare.threshold, 100 * compare.time_threshold, compare.alpha, aggregateText(view.options));
  for (const RunGroup& group : view.groups) {
    out += fmt::format(
        "\n## {} — suite {}\n\n| # | commit | run | git sha | run date |\n"
        "|---|---|---|---|---|\n",
        group.device, group.suite);
    for (size_t i = 0; i < group.runs.size(); ++i) {
      const RunInfo& r = group.runs[i];
      out += fmt::format("| {} | {} | {} | {} | {} |\n", i, r.orderTime(), r.run_id, r.git_sha,
                         r.date);
    }
  }
  out += "\n## Flagged steps\n\n";
  if (view.steps.empty()) return out + "None: no figure moved between consecutive runs.\n";
  out +=
      "| change | from → to | device, suite | series | measure | figures moved | worst figure "
      "| base | new | change | p (U test) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Step& step : view.steps) {
    const RunGroup& group = view.groups[step.group];
    const StepFigure& f = step.worst();
    out += fmt::format("| {} | {} → {} | {}, {} | {} | {} | {} | {} {} {} | {} | {} | {} | {} |\n",
                       stepChange(f), runLabel(group.runs[step.run - 1]),
                       runLabel(group.runs[step.run]), group.device, group.suite, step.series,
                       step.measure + (step.timing ? " (timing)" : ""), step.figures.size(),
                       f.asset, f.row, f.metric, figureText(f.base), figureText(f.current),
                       percentChange(f.base, f.current),
                       std::isnan(f.p_value) ? "" : fmt::format("{:.3g}", f.p_value));
  }
  out += "\n### Figures of each step\n";
  for (const Step& step : view.steps) {
    const RunGroup& group = view.groups[step.group];
    out += fmt::format("\n{} → {}, {} {}{}:\n\n", runLabel(group.runs[step.run - 1]),
                       runLabel(group.runs[step.run]), step.series, step.measure,
                       step.timing ? " (timing)" : "");
    const size_t shown = std::min(step.figures.size(), kFiguresPerStep);
    for (size_t i = 0; i < shown; ++i) {
      const StepFigure& f = step.figures[i];
      out +=
          fmt::format("- {}: {} {} {}: {} → {} ({})\n", stepChange(f), f.asset, f.row, f.metric,
                      figureText(f.base), figureText(f.current), percentChange(f.base, f.current));
    }
    if (shown < step.figures.size())
      out += fmt::format("- … and {} more\n", step.figures.size() - shown);
  }
  return out;
}

}  // namespace tb::history
