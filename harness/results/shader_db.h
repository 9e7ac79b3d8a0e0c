// The shader-db summary of a comparison (Mesa's shader-db report format): for each measure
// that declares one (MeasureDeclaration::shader_db) and each value of its group key (a GPU
// family), each metric's total over the programs both runs have, over those it changed in,
// and how many programs it helped and hurt.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::results {

struct ShaderDbMetric {
  std::string metric;
  Direction direction = Direction::kLowerIsBetter;
  double total_base = 0, total_current = 0;        // over the shared programs
  double affected_base = 0, affected_current = 0;  // over the programs it changed in
  size_t affected = 0;                             // programs it changed in
  size_t helped = 0, hurt = 0;                     // by the metric's direction
  struct Program {
    std::string name;
    double base = 0, current = 0;
  };
  std::vector<Program> worst_hurt;  // at most 5, the largest relative change first
};

struct ShaderDbSummary {
  std::string measure;
  std::string group;             // the group key's value: "navi21"
  size_t shared_programs = 0;    // rows in both runs (ok, with the metric)
  size_t affected_programs = 0;  // shared programs any of the metrics changed in
  std::vector<ShaderDbMetric> metrics;
};

// Every declared summary, in the current run's declaration order and the groups' first
// appearance. Programs only in one run are left out (the comparison lists them).
std::vector<ShaderDbSummary> shaderDbSummaries(const Results& base, const Results& current);

// "total instructions in shared programs: A -> B (x.xx%)", "instructions in affected
// programs: ...", "helped: N", "HURT: M" per metric, then the worst-hurt programs.
std::string renderShaderDb(const std::vector<ShaderDbSummary>& summaries);
nlohmann::ordered_json shaderDbToJson(const std::vector<ShaderDbSummary>& summaries);

}  // namespace tb::results
