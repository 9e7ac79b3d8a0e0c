// `tessbench report RUN_DIR`: a finished run's results.json rendered to stdout, as Markdown
// (report.md) or one self-contained HTML page (report.html).
#pragma once

#include <string>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct ReportArgs {
  std::string run_dir;
  std::string format = "markdown";  // markdown (alias md) | html
};

CLI::App* addReportCommand(CLI::App& app, ReportArgs& args);

// Exit 0, or throws on an unfinished folder or an unknown format.
int runReport(const ReportArgs& args);

extern const Subcommand kReportSubcommand;

}  // namespace tb::cli
