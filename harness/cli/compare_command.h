// `tessbench compare BASE NEW`: the deterministic figures of two finished runs, metric by
// metric by each metric's declared direction, and their timings by a Mann–Whitney U test on
// repeated samples (harness/results/compare.h, timing_compare.h).
#pragma once

#include <string>
#include <vector>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct CompareArgs {
  std::string base, current;  // run folders (results/<run-id>)
  std::string threshold = "1e-9";  // relative; 0 = exact (checked by runCompare)
  std::vector<std::string> metric_thresholds;  // NAME=VALUE, per metric name
  size_t limit = 40;                           // changes shown in the table
  std::string alpha = "0.05";           // the U test's significance level, in (0, 1)
  std::string time_threshold = "0.05";  // relative change of the median timing that counts
  bool no_timings = false;              // compare results.json only
};

CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args);

// Exit 0 when nothing was lost or worsened, 1 on a regression or a missing figure (a row the
// new run skipped, e.g. without a Vulkan device, is missing) or a timing regression, 2 on bad
// input (an unfinished or unreadable folder, a malformed NAME=VALUE or timings.json).
int runCompare(const CompareArgs& args);

extern const Subcommand kCompareSubcommand;

}  // namespace tb::cli
