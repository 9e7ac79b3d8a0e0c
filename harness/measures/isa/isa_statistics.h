// The ISA measure's columns: each statistic RADV's ACO names, with its unit and direction,
// and the rows one compiled executable gives.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/gpu/pipeline_executables.h"
#include "harness/results/results_model.h"

namespace tb::measures::isa {

// Every metric a row may carry: the driver's statistics in RADV's order, then
// subgroup_size, spirv_instructions, then `statistic_value` (a statistic the table does not know,
// in its own row).
std::vector<results::MetricSpec> statisticSpecs();

// The rows of one executable: one with `keys` plus executable and stages, holding every
// known statistic; one more per statistic the table does not know (another driver's),
// keyed by `statistic` with its figure as `statistic_value`. Identifiers (hashes) are left out.
// `spirv_instructions`: the SPIR-V count of the stages it runs, when known.
std::vector<results::MetricRow> executableRows(std::map<std::string, std::string> keys,
                                               const gpu::PipelineExecutable& executable,
                                               std::optional<double> spirv_instructions);

}  // namespace tb::measures::isa
