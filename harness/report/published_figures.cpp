#include "harness/report/published_figures.h"

#include <regex>

namespace tb::report {

const char* const kPublishedMemorySeed = "000";

const std::vector<PublishedSource>& publishedSources() {
  static const std::vector<PublishedSource> kSources{
      {"000", "NVIDIA's displacement subdivision surfaces talk",
       "NVIDIA, \"Displaced Subdivision Surfaces\": real-time displaced subdivision surfaces "
       "on Direct3D 11 (ACC and Gregory patches, Bezier evaluation orders, memory against "
       "plain meshes), 2008"},
      {"001", "the DirectX SDK SubD10 sample",
       "Microsoft DirectX SDK, SubD10 sample: approximating Catmull-Clark subdivision surfaces "
       "with bicubic patches after Loop & Schaefer, ACM TOG 2008"},
      {"002", "Bryan Dudash, \"Dynamic Hardware Tessellation Basics\" (NVIDIA, 2012)",
       "Bryan Dudash, \"Dynamic Hardware Tessellation Basics\", NVIDIA, 2012"},
      {"003", "CAPCOM's \"Lost Planet 2: DirectX 11 Features\" talk",
       "CAPCOM, \"Lost Planet 2: DirectX 11 Features\""},
      {"004", "an introduction to the D3D11 tessellation stages",
       "an introduction to the Direct3D 11 tessellation stages (hull shader, tessellator, "
       "domain shader)"},
  };
  return kSources;
}

namespace {

const PublishedSource* findSource(std::string_view seed) {
  for (const PublishedSource& source : publishedSources()) {
    if (source.seed == seed) return &source;
  }
  return nullptr;
}

}  // namespace

std::string sourceName(std::string_view seed) {
  const PublishedSource* source = findSource(seed);
  return source != nullptr ? std::string(source->name) : "source " + std::string(seed);
}

std::string sourceCitation(std::string_view seed) {
  const PublishedSource* source = findSource(seed);
  return source != nullptr ? std::string(source->citation) : sourceName(seed);
}

std::string sourceCitationByName(std::string_view name) {
  for (const PublishedSource& source : publishedSources()) {
    if (source.name == name) return std::string(source.citation);
  }
  return std::string(name);
}

std::string citeSources(std::string_view text) {
  static const std::regex kSeed("seed ([0-9]{3})");
  std::string out;
  std::string rest(text);
  std::smatch match;
  while (std::regex_search(rest, match, kSeed)) {
    out += match.prefix().str() + sourceName(match[1].str());
    rest = match.suffix().str();
  }
  return out + rest;
}

// NVIDIA's displacement subdivision surfaces talk, memory table (x8 at every level).
const std::vector<PublishedMemoryRow>& publishedMemoryTable() {
  static const std::vector<PublishedMemoryRow> kRows{
      {8, 16, 1.9},
      {16, 59, 7.5},
      {32, 236, 30},
      {64, 943, 118},
  };
  return kRows;
}

}  // namespace tb::report
