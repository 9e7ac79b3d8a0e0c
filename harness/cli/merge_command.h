// `tessbench merge`: joins the run folders of a sharded suite into one new run folder.
#pragma once

#include <string>
#include <vector>

namespace tb::cli {

struct MergeArgs {
  std::vector<std::string> shards;  // run folders of `tessbench run --shard I/N`, any order
  std::string out;                  // the merged run's folder; must not exist yet
  bool quiet = false;
};

int runMerge(const MergeArgs& args, const std::string& command_line);

}  // namespace tb::cli
