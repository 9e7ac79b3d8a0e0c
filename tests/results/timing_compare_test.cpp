// compare's timing part (harness/results/timing_compare.h): repeated samples and a
// Mann–Whitney U test; one sample is never flagged. The p-values are scipy's (see
// mann_whitney_test.cpp): 5 against 5 fully separated samples give p = 2/252 ≈ 0.0079.
#include "harness/results/timing_compare.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "harness/results/timings_json.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// One record with one deterministic figure, so the timings are the only thing that differs.
results::RunData runWith(std::vector<double> error_samples, std::vector<double> memory_samples) {
  results::RunData run;
  results::Record record{"acc", "default", "cube", {}, {}, {}};
  results::MeasureResult error{"error", results::MeasureStatus::kOk, "", {}, {}};
  error.rows.push_back({{{"reference", "limit"}}, {{"hausdorff", 0.01, "diagonal"}}});
  record.measures.push_back(error);
  run.results.records.push_back(record);
  run.results.measures.push_back(
      {"error",
       "Error",
       "",
       {{"hausdorff", results::Unit::kDiagonal, results::Direction::kLowerIsBetter}},
       {"hausdorff"},
       {}});
  results::RunTimings timings;
  timings.repetitions = int(error_samples.size());
  timings.measures.push_back({"acc", "default", "cube", "error", std::move(error_samples)});
  timings.measures.push_back({"acc", "default", "cube", "memory", std::move(memory_samples)});
  run.timings = timings;
  return run;
}

const std::vector<double> kBase{1.0, 1.1, 1.2, 1.3, 1.4};
const std::vector<double> kSlower{2.0, 2.1, 2.2, 2.3, 2.4};
const std::vector<double> kFaster{0.5, 0.51, 0.52, 0.53, 0.54};
const std::vector<double> kOverlapping{1.05, 1.15, 1.25, 1.35, 1.45};

TEST(TimingCompare, ClearlySlowerSamplesAreARegressionWithTheirPValue) {
  const results::Comparison c =
      results::compareRuns(runWith(kBase, kBase), runWith(kSlower, kBase), {});
  ASSERT_EQ(c.changes.size(), 1u);
  const results::MetricChange& change = c.changes[0];
  EXPECT_EQ(change.kind, results::ChangeKind::kRegression);
  EXPECT_EQ(change.measure, "error");
  EXPECT_EQ(change.metric, "seconds");
  EXPECT_DOUBLE_EQ(change.base, 1.2);  // the medians
  EXPECT_DOUBLE_EQ(change.current, 2.2);
  EXPECT_NEAR(change.p_value, 2.0 / 252, 1e-15);
  EXPECT_TRUE(c.failed());
  EXPECT_EQ(c.timings_tested, 2u);
  const std::string text = results::renderComparison(c, 10);
  EXPECT_NE(text.find("| regression | acc/default cube | error | timing, 5 vs 5 samples | seconds "
                      "| 1.2 | 2.2 | +83.3% | 0.00794 |"),
            std::string::npos)
      << text;
}

TEST(TimingCompare, FasterIsAnImprovementAndOverlappingIsNothing) {
  const results::Comparison faster =
      results::compareRuns(runWith(kBase, kBase), runWith(kFaster, kBase), {});
  ASSERT_EQ(faster.changes.size(), 1u);
  EXPECT_EQ(faster.changes[0].kind, results::ChangeKind::kImprovement);
  EXPECT_FALSE(faster.failed());
  const results::Comparison overlapping =
      results::compareRuns(runWith(kBase, kBase), runWith(kOverlapping, kBase), {});
  EXPECT_TRUE(overlapping.changes.empty());
  EXPECT_FALSE(overlapping.failed());
}

// Significant (every new sample above every base one, p = 2/252) and +26.7% in the median:
// flagged by default, not under a stricter alpha or a wider --time-threshold.
TEST(TimingCompare, BothTheTestAndTheThresholdMustBeMet) {
  const std::vector<double> slightly{1.5, 1.51, 1.52, 1.53, 1.54};  // median +26.7%
  results::CompareOptions strict;
  strict.alpha = 0.005;  // below 2/252
  EXPECT_FALSE(
      results::compareRuns(runWith(kBase, kBase), runWith(slightly, kBase), strict).failed());
  results::CompareOptions wide;
  wide.time_threshold = 0.5;
  EXPECT_FALSE(
      results::compareRuns(runWith(kBase, kBase), runWith(slightly, kBase), wide).failed());
  EXPECT_TRUE(results::compareRuns(runWith(kBase, kBase), runWith(slightly, kBase), {}).failed());
}

// One sample a side says nothing of the noise: never flagged, however far apart, and the
// count of timings left untested is said in one line.
TEST(TimingCompare, SingleSamplesAreNeverFlagged) {
  const results::Comparison c =
      results::compareRuns(runWith({1.0}, {1.0}), runWith({100.0}, {0.001}), {});
  EXPECT_TRUE(c.changes.empty());
  EXPECT_FALSE(c.failed());
  EXPECT_EQ(c.timings_untested, 2u);
  EXPECT_EQ(c.timings_tested, 0u);
  const std::string text = results::renderComparison(c, 10);
  EXPECT_NE(text.find("timings: 2 not tested (fewer than 2 samples per side; run --repetitions "
                      "≥ 2)"),
            std::string::npos)
      << text;
  // Two against two cannot reach p < 0.05 (its smallest p is 1/3): tested, never flagged.
  EXPECT_FALSE(
      results::compareRuns(runWith({1, 1.1}, {1, 1}), runWith({9, 9.1}, {1, 1}), {}).failed());
}

TEST(TimingCompare, WithoutTimingsOrWithNoTimingsNothingIsCompared) {
  results::RunData no_file = runWith(kSlower, kBase);
  no_file.timings.reset();
  const results::Comparison missing = results::compareRuns(runWith(kBase, kBase), no_file, {});
  EXPECT_FALSE(missing.failed());
  ASSERT_EQ(missing.timing_notes.size(), 1u);
  EXPECT_EQ(missing.timing_notes[0], "timings: not compared (the new run has no timings.json)");
  results::CompareOptions off;
  off.timings = false;
  const results::Comparison skipped =
      results::compareRuns(runWith(kBase, kBase), runWith(kSlower, kBase), off);
  EXPECT_FALSE(skipped.failed());
  EXPECT_EQ(skipped.timing_notes.at(0), "timings: not compared (--no-timings)");
}

TEST(TimingsJson, RoundTripsAndReadsOneSampleFiles) {
  const auto dir = testing::scratchDirectory("timings_json");
  results::RunTimings timings = *runWith(kBase, {0.25}).timings;
  timings.wall_seconds = 12.5;
  timings.threads = 2;
  const std::string path =
      testing::writeTextFile(dir / "timings.json", results::serializeTimings(timings));
  const results::RunTimings read = results::readTimingsFile(path);
  EXPECT_EQ(read.repetitions, 5);
  EXPECT_EQ(read.threads, 2);
  ASSERT_EQ(read.measures.size(), 2u);
  EXPECT_EQ(read.measures[0].samples, kBase);
  EXPECT_EQ(read.measures[1].samples, std::vector<double>{0.25});
  // A file written before samples existed: one sample, the seconds.
  const std::string old = testing::writeTextFile(
      dir / "old.json",
      R"({"wall_seconds": 3, "threads": 1, "measures": [{"technique": "acc", "variant": "default",
          "asset": "cube", "measure": "error", "seconds": 0.5}]})");
  const results::RunTimings old_read = results::readTimingsFile(old);
  EXPECT_EQ(old_read.repetitions, 1);
  EXPECT_EQ(old_read.measures.at(0).samples, std::vector<double>{0.5});
  const std::string bad = testing::writeTextFile(dir / "bad.json", R"({"threads": 1})");
  EXPECT_THROW(results::readTimingsFile(bad), std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(TimingCompare, MedianOfOddAndEvenSamples) {
  EXPECT_EQ(results::medianOf({3, 1, 2}), 2);
  EXPECT_EQ(results::medianOf({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(results::medianOf({7}), 7);
}

}  // namespace
}  // namespace tb
