// results.json reading and writing. Key order is fixed and floating-point values
// are printed in their shortest round-trip form, so identical results give
// byte-identical files.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "harness/results/results_model.h"

namespace tb::results {

nlohmann::ordered_json toJson(const Results& results);
// One measure's declaration as results.json's "measures" array holds it (also what
// `tessbench list measures --json` prints).
// Optional fields (summary_scope, plots, control_rows, comparisons) are left out when empty,
// and read as empty when absent (results.json files written before them). declaration_json.cpp.
nlohmann::ordered_json toJson(const MeasureDeclaration& declaration);
MeasureDeclaration declarationFromJson(const nlohmann::ordered_json& json,
                                       const std::string& where);
// Throws std::runtime_error naming the field when the document does not match
// the schema (or has another schema_version).
Results resultsFromJson(const nlohmann::ordered_json& document);

// One measure of a record as results.json's records[].measures[] holds it (rows as a table,
// no units: those are the declaration's), and back; the reader throws naming `where` and the
// field. `tessbench history` keeps each one as it is in the file.
nlohmann::ordered_json toJson(const MeasureResult& measure);
MeasureResult measureResultFromJson(const nlohmann::ordered_json& json, const std::string& where);

// One record as results.json's "records" array holds it, on one line (the run folder's
// journal of records measured so far).
std::string recordJsonLine(const Record& record);

// Pretty (2-space indent) with each row, and every other array without objects, on one
// line; final newline.
std::string serializeResults(const Results& results);
Results readResultsFile(const std::string& path);  // throws naming the file

}  // namespace tb::results
