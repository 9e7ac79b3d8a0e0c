#pragma once

#include "harness/cli/subcommand.h"
#include "harness/cli/tessellate_command.h"

namespace tb::cli {

// Runs `tessellate` on the chosen backend and prints the result; returns the exit
// code. Throws UsageError for bad arguments and std::runtime_error when the gpu
// backend has no usable Vulkan device.
int runTessellate(const TessellateArgs& args);

// `tessbench tessellate`: its options (addTessellateCommand, tessellate_command.h) run by
// runTessellate.
extern const Subcommand kTessellateSubcommand;

}  // namespace tb::cli
