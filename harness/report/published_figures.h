// The published figures tessbench reproduces, and the sources they come from, in one place.
// Readers see sources by their published titles, never by internal file numbers: the
// published_figures measure keys its rows by source name ("the DirectX SDK SubD10 sample"),
// sourceCitationByName gives the full citation, and citeSources turns any "seed NNN" left in a
// text into the name.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tb::report {

struct PublishedSource {
  std::string_view seed;      // the measure rows' key: "000", "001", ...
  std::string_view name;      // what a table cell says: "NVIDIA's displacement ... talk"
  std::string_view citation;  // authors, title, year: what a footnote says
};

// Every source a published figure or a row key may name, by seed number.
const std::vector<PublishedSource>& publishedSources();

// The name of the source with seed number `seed` ("000"); "source <seed>" when unknown.
std::string sourceName(std::string_view seed);
// The full citation of the source with seed number `seed`; sourceName when unknown.
std::string sourceCitation(std::string_view seed);
// The full citation of the source named `name` (PublishedSource::name); `name` when unknown.
std::string sourceCitationByName(std::string_view name);

// `text` with every "seed NNN" replaced by the source's name.
std::string citeSources(std::string_view text);

// NVIDIA's displacement subdivision surfaces talk, its memory table: a plain triangle mesh
// against the displaced subdivision surface at uniform tessellation levels 8..64, in MB.
struct PublishedMemoryRow {
  int level = 0;
  double plain_mb = 0;      // the plain triangle mesh
  double technique_mb = 0;  // control mesh + 16-bit displacement map
};
const std::vector<PublishedMemoryRow>& publishedMemoryTable();
// The seed number of the source of publishedMemoryTable ("000").
extern const char* const kPublishedMemorySeed;
// The patch count the talk's table fits (about 943e6 B / (16 B x 64^2) = 14.4 thousand quad
// patches; memory_measure.cpp's notes derive it): ours are scaled to it per patch.
constexpr double kPublishedMemoryPatches = 14400;

}  // namespace tb::report
