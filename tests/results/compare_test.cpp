#include "harness/results/compare.h"

#include <gtest/gtest.h>

#include "harness/results/device_identity.h"

namespace tb {
namespace {

// One record with a cracks-like measure: a CPU row and a GPU row, and the declarations.
results::Results runWith(double cpu_gap, double gpu_gap, double shared_edges,
                         bool gpu_skipped = false) {
  results::Results results;
  results.context.vulkan_device = gpu_skipped ? "none: no driver" : "llvmpipe";
  results::Record record{"acc", "default", "cube", {}, {}, {}};
  results::MeasureResult cracks{"cracks", results::MeasureStatus::kOk, "", {}, {}};
  cracks.rows.push_back(
      {{{"backend", "cpu_float"}},
       {{"max_gap_world", cpu_gap, "world"}, {"shared_edges", shared_edges, "count"}}});
  if (gpu_skipped) {
    cracks.rows.push_back(results::unmeasuredRow(
        {{"backend", "gpu"}}, results::MeasureStatus::kSkipped, "no Vulkan device"));
  } else {
    cracks.rows.push_back({{{"backend", "gpu"}}, {{"max_gap_world", gpu_gap, "world"}}});
  }
  record.measures.push_back(cracks);
  results.records.push_back(record);
  results.measures.push_back(
      {"cracks",
       "Cracks",
       "",
       {{"max_gap_world", results::Unit::kWorld, results::Direction::kLowerIsBetter},
        {"shared_edges", results::Unit::kCount, results::Direction::kNone}},
       {"max_gap_world"},
       {}});
  return results;
}

TEST(Compare, IdenticalRunsPass) {
  const results::Comparison c = results::compareResults(runWith(0, 0, 12), runWith(0, 0, 12), {});
  EXPECT_FALSE(c.failed());
  EXPECT_TRUE(c.changes.empty());
  EXPECT_EQ(c.figures_compared, 3u);
  EXPECT_NE(results::renderComparison(c, 10).find("PASS"), std::string::npos);
}

// A gap that grows is a regression (lower is better); one that shrinks an improvement; a
// figure without a direction that changes is listed but fails nothing.
TEST(Compare, DirectionDecidesRegressionAndImprovement) {
  const results::Comparison worse =
      results::compareResults(runWith(0, 1e-7, 12), runWith(0, 2e-7, 12), {});
  ASSERT_EQ(worse.changes.size(), 1u);
  EXPECT_EQ(worse.changes[0].kind, results::ChangeKind::kRegression);
  EXPECT_EQ(worse.changes[0].row, "backend=gpu");
  EXPECT_TRUE(worse.failed());
  const results::Comparison better =
      results::compareResults(runWith(0, 2e-7, 12), runWith(0, 1e-7, 12), {});
  EXPECT_EQ(better.changes[0].kind, results::ChangeKind::kImprovement);
  EXPECT_FALSE(better.failed());
  const results::Comparison neutral =
      results::compareResults(runWith(0, 0, 12), runWith(0, 0, 13), {});
  EXPECT_EQ(neutral.changes[0].kind, results::ChangeKind::kChanged);
  EXPECT_FALSE(neutral.failed());
  // From 0 any change counts, whatever the relative threshold.
  const results::Comparison from_zero =
      results::compareResults(runWith(0, 0, 12), runWith(1e-30, 0, 12), {});
  EXPECT_EQ(from_zero.changes[0].kind, results::ChangeKind::kRegression);
}

TEST(Compare, ThresholdsAreRelativeAndPerMetric) {
  const results::Results base = runWith(0, 1.0, 12), current = runWith(0, 1.001, 12);
  EXPECT_TRUE(results::compareResults(base, current, {}).failed());
  EXPECT_FALSE(results::compareResults(base, current, {0.01, {}}).failed());
  EXPECT_TRUE(results::compareResults(base, current, {0.01, {{"max_gap_world", 1e-6}}}).failed());
}

// The no-device case: the new run skipped the GPU row. Its figures are missing with the
// reason, and the comparison fails rather than passes. The reverse is "added".
TEST(Compare, SkippedRowsInTheNewRunAreMissingNotPassed) {
  const results::Comparison c =
      results::compareResults(runWith(0, 0, 12), runWith(0, 0, 12, true), {});
  ASSERT_EQ(c.count(results::ChangeKind::kMissing), 1u);
  EXPECT_TRUE(c.failed());
  EXPECT_EQ(c.changes[0].why, "skipped: no Vulkan device");
  EXPECT_EQ(c.context_notes.size(), 1u) << "the devices differ";
  const std::string text = results::renderComparison(c, 10);
  EXPECT_NE(text.find("| missing | acc/default cube | cracks | backend=gpu | (all) |"),
            std::string::npos)
      << text;
  const results::Comparison back =
      results::compareResults(runWith(0, 0, 12, true), runWith(0, 0, 12), {});
  EXPECT_FALSE(back.failed());
  EXPECT_EQ(back.count(results::ChangeKind::kAdded), 1u);
}

// A figure's device is part of its identity: two runs on different devices (or drivers) are
// never joined; the same device, or a run that had none (its GPU rows read as missing), may be.
TEST(Compare, FiguresOfTwoDevicesAreNeverJoined) {
  results::RunContext lavapipe, nvidia, nvidia_driver, none;
  lavapipe.vulkan_device = "llvmpipe (LLVM 15.0.6, 256 bits) (Mesa 22.3.6, Vulkan 1.3.230)";
  nvidia.vulkan_device = "NVIDIA H100 (NVIDIA 550.54.15, Vulkan 1.3.277)";
  nvidia_driver.vulkan_device = "NVIDIA H100 (NVIDIA 560.35.03, Vulkan 1.3.280)";
  none.vulkan_device = "none: no Vulkan driver";
  const auto mismatch = results::deviceMismatch(lavapipe, nvidia);
  ASSERT_TRUE(mismatch.has_value());
  EXPECT_NE(mismatch->find("NVIDIA H100"), std::string::npos) << *mismatch;
  EXPECT_TRUE(results::deviceMismatch(nvidia, nvidia_driver).has_value()) << "a driver update";
  EXPECT_FALSE(results::deviceMismatch(lavapipe, lavapipe).has_value()) << "the control";
  EXPECT_FALSE(results::deviceMismatch(lavapipe, none).has_value());
  EXPECT_FALSE(results::deviceMismatch(results::RunContext{}, nvidia).has_value());
}

// Reports say beside a data-centre GPU's timings that they are a lower bound; lavapipe and
// a gaming GPU get no caveat (the controls), nor does a name that merely contains "h20".
TEST(Compare, ADataCentreGpuIsNamedAsSuch) {
  EXPECT_NE(results::deviceCaveat("NVIDIA H100 80GB HBM3 (NVIDIA 550.54.15, Vulkan 1.3.277)")
                .find("lower bound"),
            std::string::npos);
  EXPECT_FALSE(results::deviceCaveat("NVIDIA H200 (NVIDIA 560.35.03, Vulkan 1.3.280)").empty());
  EXPECT_TRUE(results::deviceCaveat("llvmpipe (LLVM 15.0.6, 256 bits) (Mesa 22.3.6)").empty());
  EXPECT_TRUE(results::deviceCaveat("NVIDIA GeForce RTX 4090 (NVIDIA 550.54.15)").empty());
  EXPECT_TRUE(results::deviceCaveat("NVIDIA GeForce GTX H2000X").empty());
}

TEST(Compare, AMissingRecordOrMetricFails) {
  results::Results without_record = runWith(0, 0, 12);
  without_record.records.clear();
  EXPECT_TRUE(results::compareResults(runWith(0, 0, 12), without_record, {}).failed());
  results::Results without_metric = runWith(0, 0, 12);
  without_metric.records[0].measures[0].rows[0].metrics.pop_back();
  const results::Comparison c = results::compareResults(runWith(0, 0, 12), without_metric, {});
  ASSERT_EQ(c.count(results::ChangeKind::kMissing), 1u);
  EXPECT_EQ(c.changes[0].metric, "shared_edges");
}

// Worst first: missing, then regressions by relative size; the table is cut at the limit.
TEST(Compare, ChangesAreOrderedWorstFirstAndLimited) {
  results::Results base = runWith(1, 1, 12), current = runWith(1.5, 3, 12, false);
  const results::Comparison c = results::compareResults(base, current, {});
  ASSERT_EQ(c.changes.size(), 2u);
  EXPECT_EQ(c.changes[0].row, "backend=gpu");  // +200% before +50%
  const std::string text = results::renderComparison(c, 1);
  EXPECT_NE(text.find("1 more changes not shown"), std::string::npos) << text;
}

}  // namespace
}  // namespace tb
