// How a `tessbench` subcommand plugs into the executable: each one's file (list_command.h,
// run_command.h, ..., bake_command.h; tessellate's in tessellate_run.h) defines one
// Subcommand, and main() adds and runs them from the table of subcommands().
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace tb::cli {

// What a subcommand's run gets besides its own options.
struct Invocation {
  std::string command_line;  // "tessbench ARGS...", as the run context records it
};

// Runs the subcommand on its parsed options; returns the exit code. Throws on bad input
// (main prints one line and exits 2).
using SubcommandRun = std::function<int(const Invocation&)>;

struct Subcommand {
  const char* name;  // as typed: "list", "run", ...
  // Adds the subcommand `name` with its options to `app`, bound to arguments that the
  // returned function reads once `app` has parsed the command line.
  SubcommandRun (*add)(CLI::App& app);
};

// Every subcommand, in the order `tessbench --help` lists them.
const std::vector<Subcommand>& subcommands();

// main()'s pieces. A parse error: --help prints the usage and exits 0; any other is bad
// input, one line naming the option, exit 2.
int exitOnParseError(CLI::App& app, const CLI::ParseError& error);
// "tessbench" and the arguments, space-separated.
std::string commandLine(int argc, char** argv);

}  // namespace tb::cli
