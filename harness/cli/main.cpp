// tessbench: benchmark and validation harness for real-time GPU surface techniques.
#include <fmt/format.h>
#include <malloc.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <utility>

#include "harness/cli/subcommand.h"
#include "tb_build_info.h"
#include "techniques/registry.h"

int main(int argc, char** argv) {
  // Measures build and drop buffers of tens of megabytes per patch chunk, capture and
  // reference mesh; glibc maps each such block afresh and unmaps it on free, so every one
  // costs its size in page faults (a third of the memory measure's time). Keep freed memory
  // in the heap instead: the run's peak stays what its largest measure needs.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  CLI::App app{"tessbench: benchmark and validation harness for GPU surface techniques"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tessbench ") + TB_VERSION + " (git " + TB_GIT_SHA +
                                        "), plug-in ABI " + std::to_string(kTessbenchPluginAbi));
  std::vector<std::string> plugins;
  app.add_option("--plugin", plugins, "load techniques from a shared library (repeatable)");
  std::vector<std::pair<CLI::App*, tb::cli::SubcommandRun>> commands;
  for (const tb::cli::Subcommand& command : tb::cli::subcommands()) {
    tb::cli::SubcommandRun run = command.add(app);
    commands.emplace_back(app.get_subcommand(command.name), std::move(run));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return tb::cli::exitOnParseError(app, error);
  }
  const tb::cli::Invocation invocation{tb::cli::commandLine(argc, argv)};
  try {
    for (const std::string& plugin : plugins) tb::techniques::loadPlugin(plugin);
    for (const auto& [subcommand, run] : commands) {
      if (*subcommand) return run(invocation);
    }
  } catch (const std::exception& error) {
    std::fflush(stdout);
    fmt::print(stderr, "tessbench: error: {}\n", error.what());
    return 2;
  }
  return 0;
}
