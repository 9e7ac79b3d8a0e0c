// The pipeline's path (tessellator | compute) in the decision and publishing tables, over a
// small results model: a record measured on both paths gets a compute-path candidate beside its
// tessellator twin, with the compute path's own memory (transient buffers added) and device
// watertightness, and the summary tables get a path column. Oracles: the rows' own figures.
#include <gtest/gtest.h>

#include "harness/report/decision.h"
#include "harness/report/table.h"
#include "tests/report/results_builders.h"

namespace tb {
namespace {

using testing::measureResult;
using testing::row;

// acc/default on asset "a": exact enough, watertight on the CPU and through the tessellator;
// the compute path's gpu rows crack at `compute_points` points.
results::Results bothPaths(double compute_points) {
  results::Results r;
  results::MeasureDeclaration memory;
  memory.measure = "memory";
  memory.title = "Memory";
  memory.metrics = {
      {"transient_over_plain", results::Unit::kRatio, results::Direction::kLowerIsBetter}};
  r.measures = {memory};
  results::Record record;
  record.technique = "acc";
  record.variant = "default";
  record.asset = "a";
  results::MeasureResult error = measureResult("error");
  error.rows = {row({{"level", "16"}}, {{"hausdorff", 1e-4}})};
  results::MeasureResult cracks = measureResult("cracks");
  cracks.rows = {
      row({{"backend", "cpu_float"}, {"path", "tessellator"}}, {{"points_not_equal", 0}}),
      row({{"backend", "gpu"}, {"path", "tessellator"}}, {{"points_not_equal", 0}}),
      row({{"backend", "gpu"}, {"path", "compute"}}, {{"points_not_equal", compute_points}})};
  results::MeasureResult mem = measureResult("memory");
  for (const char* path : {"tessellator", "compute"}) {
    const bool compute = std::string(path) == "compute";
    mem.rows.push_back(
        row({{"level", "16"}, {"path", path}}, {{"plain_bytes", 1000},
                                                {"technique_with_displacement_bytes", 50},
                                                {"transient_vertex_bytes", compute ? 1500.0 : 0.0},
                                                {"transient_index_bytes", compute ? 500.0 : 0.0},
                                                {"transient_over_plain", compute ? 2.0 : 0.0}}));
  }
  record.measures = {error, cracks, mem};
  r.records = {record};
  r.assets = {{"a"}};
  testing::withRegisteredDeclarations(&r);
  return r;
}

TEST(PathColumn, ACandidateMeasuredOnBothPathsIsListedOnEachWithItsOwnFigures) {
  const report::AssetDecision d = report::decideAsset(bothPaths(0), "a");
  ASSERT_EQ(d.candidates.size(), 2u);
  const report::DecisionCandidate& hardware = d.candidates[0];
  const report::DecisionCandidate& compute = d.candidates[1];
  EXPECT_EQ(hardware.path, report::kTessellatorPath);
  EXPECT_EQ(compute.path, report::kComputePath);
  EXPECT_EQ(compute.name(), "acc/default (compute path)");
  EXPECT_DOUBLE_EQ(*hardware.figures.memory_ratio, 0.05);
  EXPECT_DOUBLE_EQ(*compute.figures.memory_ratio, 2.05);  // (50 + 1500 + 500) / 1000
  EXPECT_EQ(compute.figures.device, report::Watertightness::kWatertight);
  EXPECT_EQ(compute.figures.error, hardware.figures.error);
  // Control: the compute path's own cracks reach its candidate only.
  const report::AssetDecision cracked = report::decideAsset(bothPaths(3), "a");
  ASSERT_EQ(cracked.candidates.size(), 2u);
  EXPECT_EQ(cracked.candidates[0].path, report::kTessellatorPath);
  EXPECT_EQ(cracked.candidates[0].figures.device, report::Watertightness::kWatertight);
  EXPECT_EQ(cracked.candidates[1].figures.device, report::Watertightness::kCracked);
  EXPECT_EQ(cracked.candidates[1].figures.device_points, 3);
}

TEST(PathColumn, SummaryTablesSplitRowsKeyedByPath) {
  const report::TextTable table =
      report::summaryTable(bothPaths(0), {"memory", {"transient_over_plain"}, false});
  const std::string md = report::renderTable(table, report::TableFormat::kMarkdown);
  EXPECT_NE(md.find("| technique | variant | path |"), std::string::npos) << md;
  EXPECT_NE(md.find("| acc | default | tessellator | 0 | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| acc | default | compute | 2 | 2 |"), std::string::npos) << md;
}

}  // namespace
}  // namespace tb
