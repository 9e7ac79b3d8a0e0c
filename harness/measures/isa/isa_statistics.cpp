#include "harness/measures/isa/isa_statistics.h"

#include <string_view>
#include <utility>

namespace tb::measures::isa {
namespace {

using results::Direction;
using results::Unit;

struct Column {
  std::string_view driver_name;  // as vkGetPipelineExecutableStatisticsKHR names it
  results::MetricSpec spec;
};

// ACO's statistics (Mesa's aco_statistics.cpp and radv_pipeline.c), in the driver's order.
// Registers and spills: best 0, worst the hardware's limit (SGPRs 104 (GCN) or 106, VGPRs
// 256 per wave64 lane, or 512 in wave32 on RDNA3); more registers, fewer waves per SIMD.
const std::vector<Column>& columns() {
  constexpr Direction kLower = Direction::kLowerIsBetter;
  static const std::vector<Column> kColumns{
      // sgprs: scalar registers allocated per wave (count); 0 (best) to 106 (worst)
      {"SGPRs", {"sgprs", Unit::kCount, kLower}},
      // vgprs: vector registers allocated per lane (count); 0 (best) to 256 (worst)
      {"VGPRs", {"vgprs", Unit::kCount, kLower}},
      // spilled_sgprs: scalar registers spilled to memory (count); 0 (best), unbounded
      {"Spilled SGPRs", {"spilled_sgprs", Unit::kCount, kLower}},
      // spilled_vgprs: vector registers spilled to scratch (count); 0 (best), unbounded
      {"Spilled VGPRs", {"spilled_vgprs", Unit::kCount, kLower}},
      // code_size: bytes of machine code; 0 (best), unbounded
      {"Code size", {"code_size", Unit::kBytes, kLower}},
      // lds_size: bytes of local data share the executable declares; 0 (best) to 64 KiB
      {"LDS size", {"lds_size", Unit::kBytes, kLower}},
      // scratch_size: bytes of scratch per wave (spills, private arrays); 0 (best)
      {"Scratch size", {"scratch_size", Unit::kBytes, kLower}},
      // subgroups_per_simd: waves that fit on one SIMD by register use (count); 16 or 20
      //   (best) to 1 (worst); modelled, ignores the tessellation stages' LDS
      {"Subgroups per SIMD", {"subgroups_per_simd", Unit::kCount, Direction::kHigherIsBetter}},
      // instructions: machine instructions in the executable (count); 0 (best), unbounded
      {"Instructions", {"instructions", Unit::kCount, kLower}},
      // copies: register copies among them (count); 0 (best)
      {"Copies", {"copies", Unit::kCount, kLower}},
      // branches: branch instructions (count); 0 (best)
      {"Branches", {"branches", Unit::kCount, kLower}},
      // latency: ACO's estimate of one wave's cycles alone, issue plus stalls, loops
      //   weighted x8 (cycles); 0 (best), unbounded
      {"Latency", {"latency", Unit::kCycles, kLower}},
      // inverse_throughput: ACO's estimate of a wave64's busy cycles on one SIMD (cycles);
      //   0 (best), unbounded
      {"Inverse Throughput", {"inverse_throughput", Unit::kCycles, kLower}},
      // vmem_clauses: clauses of vector memory instructions (count); 0 (best)
      {"VMEM Clause", {"vmem_clauses", Unit::kCount, kLower}},
      // smem_clauses: clauses of scalar memory instructions (count); 0 (best)
      {"SMEM Clause", {"smem_clauses", Unit::kCount, kLower}},
      // presched_sgprs: scalar registers live before scheduling (count); 0 (best)
      {"Pre-Sched SGPRs", {"presched_sgprs", Unit::kCount, kLower}},
      // presched_vgprs: vector registers live before scheduling (count); 0 (best)
      {"Pre-Sched VGPRs", {"presched_vgprs", Unit::kCount, kLower}},
  };
  return kColumns;
}

// Statistics that identify rather than measure.
bool isIdentifier(std::string_view name) {
  return name == "Driver pipeline hash" || name == "Hash";
}

}  // namespace

std::vector<results::MetricSpec> statisticSpecs() {
  std::vector<results::MetricSpec> specs;
  for (const Column& c : columns()) specs.push_back(c.spec);
  // subgroup_size: lanes per wave the executable runs with (count); 32 or 64, context
  specs.push_back({"subgroup_size", Unit::kCount, Direction::kNone});
  // spirv_instructions: SPIR-V instructions after spirv-opt -O of the stages the executable
  //   runs (the instructions measure's vector total, summed over them; count); beside the
  //   machine count for comparison; 0 (best), unbounded
  specs.push_back({"spirv_instructions", Unit::kCount, Direction::kLowerIsBetter});
  // statistic_value: a statistic of another driver, as it reports it (its own unit); context
  specs.push_back({"statistic_value", Unit::kCount, Direction::kNone});
  return specs;
}

std::vector<results::MetricRow> executableRows(std::map<std::string, std::string> keys,
                                               const gpu::PipelineExecutable& executable,
                                               std::optional<double> spirv_instructions) {
  keys["executable"] = executable.name;
  keys["stages"] = gpu::stageNames(executable.stages);
  results::MetricRow row;
  row.keys = keys;
  std::vector<results::MetricRow> unknown;
  for (const Column& c : columns()) {
    for (const gpu::ExecutableStatistic& s : executable.statistics) {
      if (s.name == c.driver_name) {
        row.metrics.push_back({c.spec.name, s.value, std::string(toString(c.spec.unit))});
      }
    }
  }
  row.metrics.push_back({"subgroup_size", double(executable.subgroup_size), "count"});
  if (spirv_instructions)
    row.metrics.push_back({"spirv_instructions", *spirv_instructions, "count"});
  for (const gpu::ExecutableStatistic& s : executable.statistics) {
    bool known = isIdentifier(s.name);
    for (const Column& c : columns()) known |= s.name == c.driver_name;
    if (known) continue;
    results::MetricRow extra;
    extra.keys = keys;
    extra.keys["statistic"] = s.name;
    extra.metrics.push_back({"statistic_value", s.value, "count"});
    unknown.push_back(std::move(extra));
  }
  std::vector<results::MetricRow> rows{std::move(row)};
  for (results::MetricRow& r : unknown) rows.push_back(std::move(r));
  return rows;
}

}  // namespace tb::measures::isa
