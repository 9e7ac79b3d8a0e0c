#include "harness/cli/compare_command.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/mesh/input_error.h"
#include "harness/results/compare.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"

namespace tb::cli {
namespace {

// results.json, and timings.json when the folder has one (a committed baseline has none).
RunData readFinishedRun(const std::string& folder, bool with_timings) {
  requireFinishedRunFolder(folder);
  RunData run{readResultsFile(folder + "/results.json"), std::nullopt};
  const std::string timings = folder + "/timings.json";
  if (with_timings && std::filesystem::exists(timings)) run.timings = readTimingsFile(timings);
  return run;
}

double parseThreshold(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < 0) {
    throw InputError(option, text, "a threshold is a finite number >= 0");
  }
  return value;
}

}  // namespace

int runCompare(const CompareArgs& args) {
  CompareOptions options;
  options.threshold = parseThreshold("--threshold", args.threshold);
  for (const std::string& item : args.metric_thresholds) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw InputError("--metric-threshold", item, "expected NAME=VALUE");
    }
    options.metric_thresholds[item.substr(0, equals)] =
        parseThreshold("--metric-threshold", item.substr(equals + 1));
  }
  options.alpha = parseThreshold("--alpha", args.alpha);
  if (!(options.alpha > 0 && options.alpha < 1)) {
    throw InputError("--alpha", args.alpha, "a significance level is in (0, 1)");
  }
  options.time_threshold = parseThreshold("--time-threshold", args.time_threshold);
  options.timings = !args.no_timings;
  const RunData base = readFinishedRun(args.base, options.timings);
  const RunData current = readFinishedRun(args.current, options.timings);
  const Comparison comparison = compareRuns(base, current, options);
  fmt::print("# Compare {} -> {}\n\n{}", args.base, args.current,
             renderComparison(comparison, args.limit));
  return comparison.failed() ? 1 : 0;
}

}  // namespace tb::cli
