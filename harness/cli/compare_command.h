// `tessbench compare BASE NEW`: the deterministic figures of two finished runs, metric by
// metric by each metric's declared direction, and their timings by a Mann–Whitney U test on
// repeated samples (harness/results/compare.h, timing_compare.h).
#pragma once

#include <string>
#include <vector>

#include "harness/cli/subcommand.h"
#include "harness/results/compare.h"

namespace tb::cli {

struct CompareArgs {
  std::string base, current;                   // run folders (results/<run-id>)
  std::string threshold = "1e-9";              // relative; 0 = exact (checked by runCompare)
  std::vector<std::string> metric_thresholds;  // NAME=VALUE, per metric name
  size_t limit = 40;                           // changes shown in the table
  std::string alpha = "0.05";                  // the U test's significance level, in (0, 1)
  std::string time_threshold = "0.05";         // relative change of the median timing that counts
  bool no_timings = false;                     // compare results.json only
  std::vector<std::string> techniques, assets, measures;  // filters; empty: every one
  bool only_common = false;                               // missing figures listed, not failed
  bool json = false;         // one JSON document (results/compare_json.h) instead of markdown
  bool all_timings = false;  // list every timing tested, flagged or not
};

CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args);
// The options `compare` and `history compare` share (all but the two run folders).
void addCompareOptions(CLI::App* command, CompareArgs& args);

// compare's options from its arguments; throws UsageError for a malformed value.
results::CompareOptions compareOptions(const CompareArgs& args);

// Filters both runs by args' --technique/--asset/--measure (a value that selects nothing in
// either run is bad input), compares them and prints the comparison (markdown under a
// "# Compare BASE -> NEW" title, or JSON). Returns the exit code: 1 when it failed, else 0.
int printComparison(const std::string& base_name, const std::string& current_name,
                    results::RunData base, results::RunData current, const CompareArgs& args);

// Exit 0 when nothing was lost or worsened, 1 on a regression or a missing figure (a row the
// new run skipped, e.g. without a Vulkan device, is missing) or a timing regression, 2 on bad
// input (an unfinished or unreadable folder, a malformed NAME=VALUE or timings.json).
int runCompare(const CompareArgs& args);

extern const Subcommand kCompareSubcommand;

}  // namespace tb::cli
