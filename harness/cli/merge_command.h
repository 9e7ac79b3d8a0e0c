// `tessbench merge`: joins the run folders of a sharded suite into one new run folder.
#pragma once

#include <string>
#include <vector>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct MergeArgs {
  std::vector<std::string> shards;  // run folders of `tessbench run --shard I/N`, any order
  std::string out;                  // the merged run's folder; must not exist yet
  bool quiet = false;
};

CLI::App* addMergeCommand(CLI::App& app, MergeArgs& args);

int runMerge(const MergeArgs& args, const std::string& command_line);

extern const Subcommand kMergeSubcommand;

}  // namespace tb::cli
