#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>

#include "harness/cli/advise_command.h"
#include "harness/cli/bake_command.h"
#include "harness/cli/compare_command.h"
#include "harness/cli/history_command.h"
#include "harness/cli/list_command.h"
#include "harness/cli/merge_command.h"
#include "harness/cli/report_command.h"
#include "harness/cli/run_command.h"
#include "harness/cli/subcommand.h"
#include "harness/cli/table_command.h"
#include "harness/cli/tessellate_run.h"

namespace tb::cli {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> all{
      kListSubcommand,    kRunSubcommand,        kMergeSubcommand,  kReportSubcommand,
      kCompareSubcommand, kTessellateSubcommand, kAdviseSubcommand, kTableSubcommand,
      kBakeSubcommand,    kHistorySubcommand};
  return all;
}

int exitOnParseError(CLI::App& app, const CLI::ParseError& error) {
  // --help prints the usage and exits 0; any other parse error is bad input: one line
  // naming the option, exit 2, like every other bad input.
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);
  std::string what = error.what();
  std::replace(what.begin(), what.end(), '\n', ' ');
  fmt::print(stderr, "tessbench: error: {} (see --help)\n", what);
  return 2;
}

std::string commandLine(int argc, char** argv) {
  std::string command_line = "tessbench";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  return command_line;
}

}  // namespace tb::cli
