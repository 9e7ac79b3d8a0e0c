#include "harness/cli/tessellate_run.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <stdexcept>

#include "core/gpu/context.h"
#include "core/gpu/tess_capture.h"

namespace tb::cli {
namespace {

tess::Tessellation tessellateWithGpu(const TessellateArgs& args, const TessellateRequest& request) {
  gpu::ContextOptions options;
  options.device_name = args.device;
  auto context = gpu::Context::create(options);
  if (!context) throw std::runtime_error("--backend gpu: " + context.error());
  return gpu::tessellateOnGpu(*context.value(), request.domain, request.spacing, request.levels,
                              request.options);
}

// One point per line, then one primitive per line: readable, and diffable.
void printText(tess::Domain domain, const tess::Tessellation& result) {
  if (result.culled) {
    fmt::print("culled\n");
    return;
  }
  fmt::print("{} points\n", result.points.size());
  for (const auto& p : result.points) {
    if (domain == tess::Domain::kTriangle)
      fmt::print("{} {} {}\n", p[0], p[1], p[2]);
    else
      fmt::print("{} {}\n", p[0], p[1]);
  }
  if (domain == tess::Domain::kIsoline) {
    fmt::print("{} lines\n", result.lines.size());
    for (const auto& l : result.lines) fmt::print("{} {}\n", l[0], l[1]);
  } else {
    fmt::print("{} triangles\n", result.triangles.size());
    for (const auto& t : result.triangles) fmt::print("{} {} {}\n", t[0], t[1], t[2]);
  }
}

// Levels above the spacing's maximum are clamped by the tessellator, as hardware does;
// each is reported on one stderr line so a typo (640 for 64) is not silent.
void reportClampedLevels(const TessellateRequest& request) {
  const float high = tess::maxLevel(request.spacing);
  auto report = [&](const char* option, size_t index, float level) {
    if (!(level > high)) return;
    fmt::print(stderr,
               "tessbench: warning: {}[{}] = {} is above {}, the {} maximum: clamped to {}\n",
               option, index, level, high, tess::toString(request.spacing), high);
  };
  const LevelCounts counts = levelCounts(request.domain);
  for (size_t i = 0; i < counts.outer; ++i) report("--outer", i, request.levels.outer[i]);
  for (size_t i = 0; i < counts.inner; ++i) report("--inner", i, request.levels.inner[i]);
}

}  // namespace

int runTessellate(const TessellateArgs& args) {
  const TessellateRequest request = parseTessellateArgs(args);
  reportClampedLevels(request);
  const tess::Tessellation result =
      args.backend == "gpu"
          ? tessellateWithGpu(args, request)
          : tess::tessellate(request.domain, request.spacing, request.levels, request.options);
  if (args.json) {
    fmt::print("{}\n", tessellationToJson(request.domain, result));
  } else {
    printText(request.domain, result);
  }
  return 0;
}

namespace {

SubcommandRun addTessellate(CLI::App& app) {
  auto args = std::make_shared<TessellateArgs>();
  addTessellateCommand(app, *args);
  return [args](const Invocation&) { return runTessellate(*args); };
}

}  // namespace

const Subcommand kTessellateSubcommand{"tessellate", addTessellate};

}  // namespace tb::cli
