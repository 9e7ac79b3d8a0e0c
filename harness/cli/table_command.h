// `tessbench table RUN_DIR --measure M`: a measure's summary, or a published table beside
// ours, as Markdown, CSV or LaTeX (harness/report/table.h).
#pragma once

#include <string>
#include <vector>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct TableArgs {
  std::string run_dir;
  std::string measure;               // required unless --published
  std::vector<std::string> metrics;  // empty: the declaration's headline metrics
  std::string format = "markdown";   // markdown (alias md) | csv | latex
  bool per_asset = false;
  bool published = false;    // the published figures beside ours (memory, seed_figures)
  bool comparisons = false;  // the measure's side-by-side tables (report.md's section opening)
};

CLI::App* addTableCommand(CLI::App& app, TableArgs& args);

// Exit 0, or 2 on bad input (an unfinished folder, a measure or metric the run lacks, an
// unknown format).
int runTable(const TableArgs& args);

extern const Subcommand kTableSubcommand;

}  // namespace tb::cli
