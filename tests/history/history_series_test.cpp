// The history's lines and steps (history_series.h) on synthetic runs whose figures are set
// by hand, so the oracle is the hand-made change: a figure moved at exactly one commit is
// exactly one step; a device's runs never join another's lines; timings step by the U test.
#include "harness/history/history_series.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "harness/history/history_render.h"
#include "tests/history/history_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::SyntheticRun;
using testing::writeSyntheticRun;

SyntheticRun commit(int i, double hausdorff, std::string device = "llvmpipe (test)") {
  SyntheticRun run;
  run.run_id = "c" + std::to_string(i) + (device == "llvmpipe (test)" ? "" : "-other");
  run.sha = std::string(4, char('a' + i)) + "000000000000000000000000000000000000";
  run.commit_time = "2026-01-0" + std::to_string(i + 1) + "T00:00:00+00:00";
  run.date = "2026-02-01T00:00:00Z";
  run.device = std::move(device);
  run.acc_hausdorff = hausdorff;
  return run;
}

history::HistoryDb historyOf(const fs::path& dir, const std::vector<SyntheticRun>& runs) {
  history::HistoryDb db = history::openHistory((dir / "h.sqlite").string(), true);
  for (const SyntheticRun& run : runs) history::addRun(db, writeSyntheticRun(dir / "runs", run));
  return db;
}

TEST(HistorySeries, AFigureChangedAtOneCommitIsExactlyOneStep) {
  const fs::path dir = testing::scratchDirectory("history_step");
  history::HistoryDb db =
      historyOf(dir, {commit(0, 0.001), commit(1, 0.001), commit(2, 0.004), commit(3, 0.004)});
  const history::HistoryView view = history::buildHistory(db, {});
  ASSERT_EQ(view.groups.size(), 1u);
  ASSERT_EQ(view.steps.size(), 1u);
  const history::Step& step = view.steps[0];
  EXPECT_EQ(step.run, 2u);
  EXPECT_EQ(step.series, "acc/default");
  EXPECT_EQ(step.measure, "error");
  EXPECT_FALSE(step.timing);
  EXPECT_EQ(step.figures.size(), 4u);  // 2 assets × 2 levels
  EXPECT_EQ(step.worst().kind, results::ChangeKind::kRegression);
  // One chart (the headline), a line per technique/variant, a point per commit.
  ASSERT_EQ(view.charts.size(), 1u);
  ASSERT_EQ(view.charts[0].series.size(), 2u);
  EXPECT_EQ(view.charts[0].series[0].name, "acc/default");
  EXPECT_EQ(view.charts[0].series[0].points.size(), 4u);
  EXPECT_DOUBLE_EQ(view.charts[0].series[0].points[2].value, 0.004);
  const std::string markdown = history::renderHistoryMarkdown(view);
  EXPECT_EQ(markdown.find("| regression | cccc000 2026-01-03 → dddd000 2026-01-04"),
            std::string::npos)
      << "the step is from commit 1 to 2, not 2 to 3:\n"
      << markdown;
  EXPECT_NE(markdown.find("| regression | bbbb000 2026-01-02 → cccc000 2026-01-03 |"),
            std::string::npos)
      << markdown;
}

TEST(HistorySeries, AShaderDbMeasureGetsItsTotalPerFamilyOverTheCommits) {
  const fs::path dir = testing::scratchDirectory("history_shader_db");
  SyntheticRun a = commit(0, 0.001), b = commit(1, 0.001);
  a.isa_instructions = 100;
  b.isa_instructions = 120;
  history::HistoryDb db = historyOf(dir, {a, b});
  const history::HistoryView view = history::buildHistory(db, {});
  const history::Chart* total = nullptr;
  for (const history::Chart& chart : view.charts) {
    if (chart.measure == "isa" && chart.metric == "total instructions") total = &chart;
    // The control: a measure without a shader-db summary gets no total.
    EXPECT_FALSE(chart.measure == "error" && chart.metric.starts_with("total")) << chart.metric;
  }
  ASSERT_NE(total, nullptr);
  ASSERT_EQ(total->series.size(), 2u);  // navi21, polaris10
  EXPECT_EQ(total->series[0].name, "navi21");
  ASSERT_EQ(total->series[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(total->series[0].points[0].value, 210);  // 100 + 110
  EXPECT_DOUBLE_EQ(total->series[0].points[1].value, 250);  // 120 + 130
}

TEST(HistorySeries, AThresholdAboveTheChangeFlagsNothing) {
  const fs::path dir = testing::scratchDirectory("history_threshold");
  history::HistoryDb db = historyOf(dir, {commit(0, 0.001), commit(1, 0.0011)});
  history::ReportOptions options;
  EXPECT_EQ(history::buildHistory(db, options).steps.size(), 1u);
  options.compare.threshold = 0.2;  // the change is 9 %
  EXPECT_TRUE(history::buildHistory(db, options).steps.empty());
}

TEST(HistorySeries, DevicesNeverShareALine) {
  const fs::path dir = testing::scratchDirectory("history_devices");
  // The other device's figure differs, interleaved in commit order: no step, its own group.
  history::HistoryDb db = historyOf(dir, {commit(0, 0.001), commit(1, 0.009, "other gpu"),
                                          commit(2, 0.001), commit(3, 0.009, "other gpu")});
  const history::HistoryView view = history::buildHistory(db, {});
  ASSERT_EQ(view.groups.size(), 2u);
  EXPECT_TRUE(view.steps.empty());
  ASSERT_EQ(view.charts.size(), 2u);
  EXPECT_NE(view.charts[0].group, view.charts[1].group);
  for (const history::Chart& chart : view.charts) {
    for (const history::ChartSeries& line : chart.series) EXPECT_EQ(line.points.size(), 2u);
  }
}

TEST(HistorySeries, TimingsStepByTheUTestAndPickedAssetsGetTheirOwnLines) {
  const fs::path dir = testing::scratchDirectory("history_timings");
  SyntheticRun base = commit(0, 0.001), same = commit(1, 0.001), slow = commit(2, 0.001);
  base.samples = {1.0, 1.1, 1.2, 1.3, 1.4};
  same.samples = {1.05, 1.15, 1.25, 1.35, 1.45};  // overlapping: not significant
  slow.samples = {2.0, 2.2, 2.4, 2.6, 2.8};       // p = 2/252 < 0.05, median +92 %
  history::HistoryDb db = historyOf(dir, {base, same, slow});
  history::ReportOptions options;
  options.assets = {"loop_cube"};
  const history::HistoryView view = history::buildHistory(db, options);
  ASSERT_EQ(view.steps.size(), 2u);  // acc and phong on loop_cube, both at commit 2
  for (const history::Step& step : view.steps) {
    EXPECT_TRUE(step.timing);
    EXPECT_EQ(step.run, 2u);
    EXPECT_EQ(step.figures.size(), 1u);
    EXPECT_EQ(step.worst().asset, "opensubdiv/loop_cube");
    EXPECT_NEAR(step.worst().p_value, 2.0 / 252, 1e-12);
  }
  ASSERT_EQ(view.charts.size(), 2u);  // hausdorff and seconds
  EXPECT_EQ(view.charts[1].metric, "seconds");
  EXPECT_EQ(view.charts[1].series.at(0).name, "acc/default opensubdiv/loop_cube");
}

TEST(HistorySeries, TheSameDatabaseGivesTheSameReportBytes) {
  const fs::path dir = testing::scratchDirectory("history_bytes");
  history::HistoryDb db = historyOf(dir, {commit(0, 0.001), commit(1, 0.002), commit(2, 0.002)});
  const history::ChartScript chartjs{"/* Chart.js stands here */", ""};
  const history::HistoryView first = history::buildHistory(db, {});
  const history::HistoryView second = history::buildHistory(db, {});
  EXPECT_EQ(history::renderHistoryHtml(first, chartjs),
            history::renderHistoryHtml(second, chartjs));
  EXPECT_EQ(history::renderHistoryMarkdown(first), history::renderHistoryMarkdown(second));
  const std::string html = history::renderHistoryHtml(first, chartjs);
  EXPECT_NE(html.find("\"step\":\"4 figures moved; worst: regression"), std::string::npos) << html;
  EXPECT_NE(html.find("\"run_id\":\"c1\""), std::string::npos);
}

}  // namespace
}  // namespace tb
