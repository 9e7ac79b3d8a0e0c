// `tessbench history add|list|report|compare`: the results database across commits
// (harness/history/): runs ingested into one SQLite file, a dashboard of every headline
// figure over commits with the steps flagged, and compare's output for two runs found by sha.
#pragma once

#include <string>
#include <vector>

#include "harness/cli/compare_command.h"
#include "harness/cli/subcommand.h"

namespace tb::cli {

struct HistoryArgs {
  std::string db = "results/history.sqlite";  // the database file (history_store.h)
  std::vector<std::string> run_dirs;          // add: finished run folders
  std::string out;                            // report: the folder of history.html and .md
  std::vector<std::string> assets;            // report: a line per picked asset
  std::string aggregate = "median";           // report: median | worst over assets
  std::string sha_a, sha_b;                   // compare: git shas (prefixes of 4+ characters)
  bool json = false;                          // list: JSON
  CompareArgs compare;                        // compare's thresholds (report's steps use them too)
};

extern const Subcommand kHistorySubcommand;

}  // namespace tb::cli
