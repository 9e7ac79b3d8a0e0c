// `tessbench compare BASE NEW`: the deterministic figures of two finished runs, metric by
// metric by each metric's declared direction (harness/results/compare.h).
#pragma once

#include <string>
#include <vector>

namespace tb::cli {

struct CompareArgs {
  std::string base, current;  // run folders (results/<run-id>)
  std::string threshold = "1e-9";  // relative; 0 = exact (checked by runCompare)
  std::vector<std::string> metric_thresholds;  // NAME=VALUE, per metric name
  size_t limit = 40;                           // changes shown in the table
};

// Exit 0 when nothing was lost or worsened, 1 on a regression or a missing figure (a row the
// new run skipped, e.g. without a Vulkan device, is missing), 2 on bad input (an unfinished
// or unreadable folder, a malformed NAME=VALUE).
int runCompare(const CompareArgs& args);

}  // namespace tb::cli
