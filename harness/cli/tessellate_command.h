// `tessbench tessellate`: tessellate one patch and print its domain points and
// primitives (as text or JSON), with the CPU tessellator or, via the caller, lavapipe.
#pragma once

#include <stdexcept>
#include <string>

#include "core/tess/tessellator.h"
#include "harness/cli/usage_error.h"

namespace CLI {
class App;
}  // namespace CLI

namespace tb::cli {

struct TessellateArgs {
  std::string domain;   // tri | quad | isoline
  std::string spacing;  // integer | pow2 | fractional_odd | fractional_even
  std::string outer;    // comma-separated: tri 3 values, quad 4, isoline 2 (density, detail)
  std::string inner;    // comma-separated: tri 1 value, quad 2, isoline none; empty = all 1
  std::string backend = "cpu";  // cpu | gpu
  bool json = false;
  bool point_mode = false;
  std::string device;  // Vulkan device name for the gpu backend; empty = default
};

// The validated form of TessellateArgs, for whichever backend runs it.
struct TessellateRequest {
  tess::Domain domain = tess::Domain::kTriangle;
  tess::Spacing spacing = tess::Spacing::kInteger;
  tess::Levels levels;
  tess::Options options;
};

// How many --outer and --inner values each domain takes (gl_TessLevelOuter/Inner use).
struct LevelCounts {
  size_t outer;
  size_t inner;
};
LevelCounts levelCounts(tess::Domain domain);

// Parses and validates; throws UsageError on an unknown domain, spacing or backend, a
// level that is not a number ("nan" and "inf" are numbers: they exercise culling and
// clamping), or a wrong count of --outer or --inner values for the domain.
TessellateRequest parseTessellateArgs(const TessellateArgs& args);

// parseTessellateArgs, then tb::tess::tessellate; *domain receives the parsed domain.
tess::Tessellation runCpuTessellate(const TessellateArgs& args, tess::Domain* domain);

// {"points": [[u, v], ...] (tri: [u, v, w]), "primitives": [[i, j, k], ...] (isoline:
// [i, j]; empty in point mode), "culled": bool}. Floats round-trip exactly.
std::string tessellationToJson(tess::Domain domain, const tess::Tessellation& tessellation);

// Registers the "tessellate" subcommand and its options, bound to args. The caller sets
// the callback (it chooses the backend and prints).
void addTessellateCommand(CLI::App& app, TessellateArgs& args);

}  // namespace tb::cli
