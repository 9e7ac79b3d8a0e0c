// `tessbench list WHAT`: the techniques, bundled assets, scenarios, measures or Vulkan devices,
// as text or JSON.
#pragma once

#include <string>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct ListArgs {
  std::string what;  // techniques | assets | scenarios | measures | devices
  bool json = false;
};

CLI::App* addListCommand(CLI::App& app, ListArgs& args);

int runList(const ListArgs& args);

extern const Subcommand kListSubcommand;

}  // namespace tb::cli
