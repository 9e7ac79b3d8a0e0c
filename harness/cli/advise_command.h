// `tessbench advise ASSET`: which technique × variant to use on one asset under the reader's
// constraints (harness/report/advice.h), measured in-process or read from a finished run.
#pragma once

#include <string>
#include <vector>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct AdviseArgs {
  std::string asset;    // bundled asset name or OBJ path (as the run's records name it)
  std::string run_dir;  // a finished run folder to read; empty: measure in-process
  // Bounds as text, checked by runAdvise (finite, >= 0); empty: no constraint.
  std::string max_error, max_memory_ratio, max_instructions;
  bool allow_cracks = false;     // --allow-cracks: no watertight constraint (the default has one)
  bool watertight_flag = false;  // --watertight: the default, accepted for scripts
  int refine = 0;                // --refine N: the asset refined at load (suite::refinedAsset)
  std::vector<std::string> techniques;  // empty: every registered technique
  bool json = false;
};

// The measures advise needs (and runs in-process): error, cracks, memory, instructions.
const std::vector<std::string>& adviseMeasureIds();

// Adds the `advise` subcommand with its options bound to `args`.
CLI::App* addAdviseCommand(CLI::App& app, AdviseArgs& args);

// Exit 0 when at least one candidate meets every constraint, 1 when none does, 2 on bad
// input (an unknown asset, technique or number; a run folder without the asset).
int runAdvise(const AdviseArgs& args);

extern const Subcommand kAdviseSubcommand;

}  // namespace tb::cli
