// `tessbench bake`: a displacement map for one technique on one asset against a detailed
// target mesh (an OBJ, or the built-in analytic target of the baker's oracle), written as
// OpenEXR with a JSON sidecar (harness/bake, docs/derivations/displacement.md).
#pragma once

#include <cstdint>
#include <string>

#include "harness/cli/subcommand.h"

namespace tb::cli {

struct BakeArgs {
  std::string technique;
  std::string variant;  // empty: the technique's default (first) variant
  std::string asset;
  std::string out;     // FILE.exr; FILE.exr.json is written beside it
  std::string target;  // a detailed OBJ mesh, or empty with --analytic
  bool analytic = false;
  std::string kind = "scalar";      // scalar | vector
  std::string pixel_type = "half";  // half | float: how the EXR (and the GPU) store texels
  std::uint32_t resolution = 16;
  std::string layout = "tiles";  // tiles | uv (uv refused: not built yet)
  int target_rate = 32;          // the analytic target's limit tessellation rate
  std::string write_target;      // with --analytic: also write the target mesh as OBJ here
};

CLI::App* addBakeCommand(CLI::App& app, BakeArgs& args);

// Exit 0, or throws UsageError / InputError / UnsupportedInput (exit 2, nothing written).
int runBake(const BakeArgs& args);

extern const Subcommand kBakeSubcommand;

}  // namespace tb::cli
