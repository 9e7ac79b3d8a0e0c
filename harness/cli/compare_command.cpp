#include "harness/cli/compare_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/mesh/input_error.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/complete_declarations.h"
#include "harness/results/compare.h"
#include "harness/results/compare_json.h"
#include "harness/results/device_identity.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "harness/results/shader_db.h"

namespace tb::cli {
namespace {

// results.json, and timings.json when the folder has one (a committed baseline has none).
results::RunData readFinishedRun(const std::string& folder, bool with_timings) {
  results::requireFinishedRunFolder(folder);
  results::RunData run{results::readResultsFile(folder + "/results.json"), std::nullopt};
  const std::string timings = folder + "/timings.json";
  if (with_timings && std::filesystem::exists(timings))
    run.timings = results::readTimingsFile(timings);
  return run;
}

double parseThreshold(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < 0) {
    throw UsageError(option, text, "a threshold is a finite number >= 0");
  }
  return value;
}

SubcommandRun addCompare(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  addCompareCommand(app, *args);
  return [args](const Invocation&) { return runCompare(*args); };
}

}  // namespace

CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args) {
  CLI::App* compare = app.add_subcommand(
      "compare",
      "compare two finished runs metric by metric by each metric's direction; exit 1 when the "
      "new run lost (skipped, failed, absent) or worsened a figure of the base");
  compare->add_option("base", args.base, "the base run folder (results/<run-id>)")->required();
  compare->add_option("new", args.current, "the new run folder")->required();
  addCompareOptions(compare, args);
  return compare;
}

void addCompareOptions(CLI::App* compare, CompareArgs& args) {
  compare
      ->add_option("--threshold", args.threshold,
                   "relative change that counts: |new - base| > t * max(|base|, |new|); 0 = exact")
      ->capture_default_str();
  compare->add_option("--metric-threshold", args.metric_thresholds,
                      "NAME=VALUE: the threshold for one metric name (repeatable)");
  compare->add_option("--limit", args.limit, "changes listed in the table, worst first")
      ->capture_default_str();
  compare
      ->add_option("--alpha", args.alpha,
                   "timings: significance level of the two-sided Mann-Whitney U test on "
                   "the repeated samples of timings.json (run --repetitions >= 2)")
      ->capture_default_str();
  compare
      ->add_option("--time-threshold", args.time_threshold,
                   "timings: relative change of the median that counts, with p < alpha")
      ->capture_default_str();
  compare->add_flag("--no-timings", args.no_timings, "compare results.json only, not timings.json");
  compare->add_option("--technique", args.techniques,
                      "compare only this technique's records (repeatable)");
  compare->add_option("--asset", args.assets,
                      "compare only this asset's records, by full or short name (repeatable)");
  compare->add_option("--measure", args.measures, "compare only this measure (repeatable)");
  compare->add_flag("--only-common", args.only_common,
                    "compare the figures both runs have: figures only the base has are listed "
                    "as missing but do not fail");
  compare->add_flag("--json", args.json, "print the comparison as JSON");
  compare->add_flag("--all-timings", args.all_timings,
                    "list every timing tested (base and new median, change, p-value), flagged "
                    "or not");
}

int printComparison(const std::string& base_name, const std::string& current_name,
                    results::RunData base, results::RunData current, const CompareArgs& args) {
  if (const auto mismatch =
          results::deviceMismatch(base.results.context, current.results.context)) {
    throw mesh::InputError(current_name + "/results.json", "context.vulkan_device", *mismatch);
  }
  const results::CompareOptions options = compareOptions(args);
  const results::RunFilter filter{args.techniques, args.assets, args.measures};
  const std::vector<std::string> unmatched =
      results::unmatchedFilterValues(filter, {&base, &current});
  if (!unmatched.empty()) {
    throw UsageError(unmatched.front(), "", "selects no record of either run");
  }
  results::filterRun(filter, &base);
  results::filterRun(filter, &current);
  const results::Comparison comparison = results::compareRuns(base, current, options);
  // Files written before a measure declared its shader-db summary get the registered one.
  measures::completeDeclarations(&base.results);
  measures::completeDeclarations(&current.results);
  const std::vector<results::ShaderDbSummary> shader_db =
      results::shaderDbSummaries(base.results, current.results);
  if (args.json) {
    nlohmann::ordered_json document{{"base", base_name}, {"new", current_name}};
    document.update(results::comparisonToJson(comparison));
    if (!shader_db.empty()) document["shader_db"] = results::shaderDbToJson(shader_db);
    fmt::print("{}\n",
               document.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  } else {
    fmt::print("# Compare {} -> {}\n\n{}", base_name, current_name,
               results::renderComparison(comparison, args.limit));
    if (!shader_db.empty()) {
      fmt::print("\n## Shader-db summary\n\n{}", results::renderShaderDb(shader_db));
    }
    if (args.all_timings) fmt::print("\n## Timings\n\n{}", results::renderTimingTable(comparison));
  }
  return comparison.failed() ? 1 : 0;
}

int runCompare(const CompareArgs& args) {
  const bool timings = !args.no_timings;
  return printComparison(args.base, args.current, readFinishedRun(args.base, timings),
                         readFinishedRun(args.current, timings), args);
}

results::CompareOptions compareOptions(const CompareArgs& args) {
  results::CompareOptions options;
  options.threshold = parseThreshold("--threshold", args.threshold);
  for (const std::string& item : args.metric_thresholds) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw UsageError("--metric-threshold", item, "expected NAME=VALUE");
    }
    options.metric_thresholds[item.substr(0, equals)] =
        parseThreshold("--metric-threshold", item.substr(equals + 1));
  }
  options.alpha = parseThreshold("--alpha", args.alpha);
  if (!(options.alpha > 0 && options.alpha < 1)) {
    throw UsageError("--alpha", args.alpha, "a significance level is in (0, 1)");
  }
  options.time_threshold = parseThreshold("--time-threshold", args.time_threshold);
  options.timings = !args.no_timings;
  options.only_common = args.only_common;
  return options;
}

const Subcommand kCompareSubcommand{"compare", addCompare};

}  // namespace tb::cli
