// `tessbench run`: measures techniques on assets (the suite, harness/suite/suite.h) into a new
// results folder: results.json, timings.json, report.md, report.html, tables/, pictures/.
#pragma once

#include <string>
#include <vector>

#include "harness/cli/subcommand.h"

namespace tb::cli {

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
  std::string device;                // Vulkan device name substring; empty = best available
  int threads = 0;                   // worker threads; 0 = every core
  std::string shard;                 // "I/N": run shard I of N of the work list; empty = all of it
  std::string suite = "default";     // "default" or "full": which grid measures run
  std::vector<std::string> cameras;  // camera path names or .json files; empty = the suite's
  int repetitions = 1;   // runs of each measure per record; every one timed (timings.json)
  bool pictures = true;  // render pictures/ (harness/pictures/run_pictures.h); --no-pictures
  // --displacement FILE.exr (repeatable): displaced assets from baked maps. None given: the
  // bundled maps (assets/displacement) when the run does not narrow the assets.
  std::vector<std::string> displacements;
  // --refine N: every --asset refined N times by OpenSubdiv at load, with its creases
  // (suite::refinedAsset); 0 = as in the file.
  int refine = 0;
};

CLI::App* addRunCommand(CLI::App& app, RunArgs& args);

// Exit 0, or 1 when a measure failed on some record (the run is complete but not clean);
// throws on bad input (nothing written).
int runRun(const RunArgs& args, const std::string& command_line);

extern const Subcommand kRunSubcommand;

}  // namespace tb::cli
