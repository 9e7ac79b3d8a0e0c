// libFuzzer target: `tessbench tessellate`'s level parsing (harness/cli/tessellate_command.h,
// parseTessellateArgs) and the CPU tessellator on what it accepts (core/tess, tessellate),
// so NaN, infinite, negative and huge levels reach the tessellator; then the command's JSON.
// The input is the command's fields, one per line:
//   domain \n spacing \n outer \n inner [\n point]
// (a missing line is empty; a fifth line "point" is --point-mode). UsageError is the one
// expected exception; anything else, a sanitizer report or a broken property of the
// tessellation is a finding.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/tess/tessellator.h"
#include "harness/cli/tessellate_command.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using tb::fuzz::require;

tb::cli::TessellateArgs argsFromLines(std::string_view text) {
  std::array<std::string, 5> fields;
  for (std::string& field : fields) {
    const size_t end = text.find('\n');
    field = std::string(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  }
  tb::cli::TessellateArgs args;
  args.domain = fields[0];
  args.spacing = fields[1];
  args.outer = fields[2];
  args.inner = fields[3];
  args.point_mode = fields[4] == "point";
  return args;
}

// tessellator.h: points are gl_TessCoord (each coordinate in [0, 1], a multiple of 2^-16;
// barycentric on triangles), primitives index them, and a culled patch emits nothing.
void checkTessellation(tb::tess::Domain domain, bool point_mode,
                       const tb::tess::Tessellation& out) {
  if (out.culled) {
    require(out.points.empty() && out.triangles.empty() && out.lines.empty(),
            "a culled patch emits nothing");
    return;
  }
  require(!out.points.empty(), "a patch that is not culled has points");
  for (const tb::tess::DomainPoint& p : out.points) {
    for (float c : p) {
      require(c >= 0 && c <= 1, "coordinates are in [0, 1]");
      require(std::ldexp(double(c), 16) == std::floor(std::ldexp(double(c), 16)),
              "coordinates are multiples of 2^-16");
    }
    if (domain == tb::tess::Domain::kTriangle) {
      require(p[0] + p[1] + p[2] == 1.0f, "triangle coordinates sum to 1");
    } else {
      require(p[2] == 0, "quad and isoline points have w = 0");
    }
  }
  if (point_mode) {
    require(out.triangles.empty() && out.lines.empty(), "point mode emits no primitives");
  }
  const bool lines = domain == tb::tess::Domain::kIsoline;
  require(lines ? out.triangles.empty() : out.lines.empty(),
          "isolines emit lines, the other domains triangles");
  for (const auto& triangle : out.triangles) {
    for (uint32_t index : triangle) require(index < out.points.size(), "indices in range");
  }
  for (const auto& line : out.lines) {
    for (uint32_t index : line) require(index < out.points.size(), "indices in range");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const tb::cli::TessellateArgs args =
      argsFromLines(std::string_view(reinterpret_cast<const char*>(data), size));
  tb::cli::TessellateRequest request;
  try {
    request = tb::cli::parseTessellateArgs(args);
  } catch (const tb::cli::UsageError&) {
    return 0;
  }
  const tb::tess::Tessellation out =
      tb::tess::tessellate(request.domain, request.spacing, request.levels, request.options);
  checkTessellation(request.domain, request.options.point_mode, out);
  const std::string json = tb::cli::tessellationToJson(request.domain, out);
  require(!json.empty() && json.front() == '{', "the JSON output is an object");
  return 0;
}
