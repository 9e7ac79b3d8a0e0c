// The `tessbench` subcommands other than tessellate. Each returns the exit code.
#pragma once

#include <string>
#include <vector>

namespace tb::cli {

struct ListArgs {
  std::string what;  // techniques | assets | scenarios | measures
  bool json = false;
};

struct RunArgs {
  std::vector<std::string> techniques;
  std::vector<std::string> assets;
  // Scenario names (assets/scenarios) or .json paths, the inputs of simulation techniques;
  // empty = every bundled scenario.
  std::vector<std::string> scenarios;
  std::vector<std::string> measures;
  std::string out = "results";
  std::string run_id;
  bool quiet = false;
  std::string device;  // Vulkan device name substring; empty = best available
  int threads = 0;     // worker threads; 0 = every core
  std::string shard;   // "I/N": run shard I of N of the work list; empty = all of it
  std::string suite = "default";     // "default" or "full": which grid measures run
  std::vector<std::string> cameras;  // camera path names or .json files; empty = the suite's
  int repetitions = 1;  // runs of each measure per record; every one timed (timings.json)
  bool pictures = true;  // render pictures/ (harness/pictures/run_pictures.h); --no-pictures
};

struct ReportArgs {
  std::string run_dir;
  std::string format = "md";
};

int runList(const ListArgs& args);
int runRun(const RunArgs& args, const std::string& command_line);
int runReport(const ReportArgs& args);

}  // namespace tb::cli
