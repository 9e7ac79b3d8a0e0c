// Every row of a run as CSV, one file per measure (results/<run-id>/tables/<measure>.csv):
// the detail report.md leaves out. Reads only the results model.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

// RFC 4180: a cell holding a comma, a quote or a line break is quoted, quotes doubled.
std::string csvCell(const std::string& text);

// (file name relative to the run folder, CSV text), in measure order: tables/<measure>.csv
// for every measure of the run, then tables/warnings.csv and tables/record_notes.csv when
// the run has any. A measure's file has the columns technique, variant, asset, every row
// key of the measure (sorted), status, reason, then every metric in declaration order (the
// unit in the header: "max_gap_world [world]"); a record whose whole measure was skipped
// or failed is one line with empty keys. Values print in their shortest round-trip form.
std::vector<std::pair<std::string, std::string>> renderCsvTables(const results::Results& results);

}  // namespace tb::report
