#include "harness/cli/tessellate_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <vector>

namespace tb::cli {
namespace {

std::string trim(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t");
  if (begin == std::string::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

// Comma-separated floats; strtof accepts nan and inf, which are meaningful levels.
std::vector<float> parseLevels(const std::string& option, const std::string& text) {
  std::vector<float> values;
  if (trim(text).empty()) return values;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string item =
        trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    char* end = nullptr;
    errno = 0;
    const float value = std::strtof(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size()) {
      throw UsageError(option + ": '" + item + "' is not a number");
    }
    values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

void requireCount(const std::string& option, tess::Domain domain, size_t expected, size_t got) {
  if (got == expected) return;
  throw UsageError(option + " for domain " + std::string(tess::toString(domain)) + " needs " +
                   std::to_string(expected) + " value" + (expected == 1 ? "" : "s") + ", got " +
                   std::to_string(got));
}

}  // namespace

LevelCounts levelCounts(tess::Domain domain) {
  switch (domain) {
    case tess::Domain::kTriangle:
      return {3, 1};
    case tess::Domain::kQuad:
      return {4, 2};
    case tess::Domain::kIsoline:
      break;
  }
  return {2, 0};
}

TessellateRequest parseTessellateArgs(const TessellateArgs& args) {
  TessellateRequest request;
  if (!tess::parseDomain(args.domain, &request.domain)) {
    throw UsageError("--domain: unknown domain '" + args.domain +
                     "' (expected tri, quad or isoline)");
  }
  if (!tess::parseSpacing(args.spacing, &request.spacing)) {
    throw UsageError("--spacing: unknown spacing '" + args.spacing +
                     "' (expected integer, pow2, fractional_odd or fractional_even)");
  }
  if (args.backend != "cpu" && args.backend != "gpu") {
    throw UsageError("--backend: unknown backend '" + args.backend + "' (expected cpu or gpu)");
  }
  const LevelCounts counts = levelCounts(request.domain);
  const std::vector<float> outer = parseLevels("--outer", args.outer);
  requireCount("--outer", request.domain, counts.outer, outer.size());
  std::copy(outer.begin(), outer.end(), request.levels.outer.begin());

  const std::vector<float> inner = parseLevels("--inner", args.inner);
  if (!inner.empty() || request.domain == tess::Domain::kIsoline) {
    requireCount("--inner", request.domain, counts.inner, inner.size());
  }
  std::copy(inner.begin(), inner.end(), request.levels.inner.begin());
  request.options.point_mode = args.point_mode;
  return request;
}

tess::Tessellation runCpuTessellate(const TessellateArgs& args, tess::Domain* domain) {
  const TessellateRequest request = parseTessellateArgs(args);
  if (domain != nullptr) *domain = request.domain;
  return tess::tessellate(request.domain, request.spacing, request.levels, request.options);
}

std::string tessellationToJson(tess::Domain domain, const tess::Tessellation& tessellation) {
  const bool barycentric = domain == tess::Domain::kTriangle;
  nlohmann::json points = nlohmann::json::array();
  for (const tess::DomainPoint& p : tessellation.points) {
    // nlohmann prints doubles in shortest round-trip form; float -> double is exact.
    nlohmann::json point = {static_cast<double>(p[0]), static_cast<double>(p[1])};
    if (barycentric) point.push_back(static_cast<double>(p[2]));
    points.push_back(std::move(point));
  }
  nlohmann::json primitives = nlohmann::json::array();
  for (const auto& t : tessellation.triangles) primitives.push_back({t[0], t[1], t[2]});
  for (const auto& l : tessellation.lines) primitives.push_back({l[0], l[1]});
  nlohmann::json out;
  out["points"] = std::move(points);
  out["primitives"] = std::move(primitives);
  out["culled"] = tessellation.culled;
  return out.dump();
}

void addTessellateCommand(CLI::App& app, TessellateArgs& args) {
  CLI::App* sub = app.add_subcommand(
      "tessellate", "Tessellate one patch and print its domain points and primitives");
  sub->add_option("--domain", args.domain, "tri | quad | isoline")->required();
  sub->add_option("--spacing", args.spacing, "integer | pow2 | fractional_odd | fractional_even")
      ->required();
  sub->add_option("--outer", args.outer,
                  "outer levels a,b[,c[,d]]: tri 3, quad 4, isoline 2 (density, detail); "
                  "write --outer=-1,2,3 when the first is negative")
      ->required();
  sub->add_option("--inner", args.inner, "inner levels x[,y]: tri 1, quad 2 (default 1)");
  sub->add_option("--backend", args.backend, "cpu (this tessellator) | gpu (lavapipe)")
      ->capture_default_str();
  sub->add_flag("--json", args.json, "print JSON instead of text");
  sub->add_flag("--point-mode", args.point_mode, "points only, no primitives");
  sub->add_option("--device", args.device, "Vulkan device name for --backend gpu");
}

}  // namespace tb::cli
