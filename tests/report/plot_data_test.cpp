#include "harness/report/plot_data.h"

#include <gtest/gtest.h>

namespace tb {
namespace {

results::MetricRow row(std::map<std::string, std::string> keys,
                       std::vector<results::Metric> metrics) {
  return {std::move(keys), std::move(metrics)};
}

results::Record record(const std::string& technique, const std::string& variant,
                       const std::string& asset, results::MeasureResult measure) {
  return {technique, variant, asset, {}, {}, {std::move(measure)}};
}

results::MeasureResult memoryResult(std::vector<results::MetricRow> rows) {
  results::MeasureResult m;
  m.measure = "memory";
  m.rows = std::move(rows);
  return m;
}

results::MeasureDeclaration memoryDeclaration() {
  results::MeasureDeclaration d{"memory", "Memory", "d", {}, {"ratio"}, {}};
  d.metrics = {{"ratio", results::Unit::kRatio, results::Direction::kHigherIsBetter}};
  return d;
}

results::PlotSpec linePlot() {
  return results::PlotSpec{.title = "t",
                           .kind = results::PlotKind::kLine,
                           .x = "level",
                           .y = "ratio",
                           .facet = "",
                           .where = {}};
}

TEST(PlotData, ParsesOnlyWholeFiniteNumbers) {
  EXPECT_EQ(report::parsePlotNumber("16"), 16.0);
  EXPECT_EQ(report::parsePlotNumber("0.5"), 0.5);
  EXPECT_EQ(report::parsePlotNumber("-1e-3"), -1e-3);
  EXPECT_FALSE(report::parsePlotNumber("16x"));
  EXPECT_FALSE(report::parsePlotNumber("fractional_odd"));
  EXPECT_FALSE(report::parsePlotNumber(""));
  EXPECT_FALSE(report::parsePlotNumber("nan"));
  EXPECT_FALSE(report::parsePlotNumber("inf"));
}

// Oracle: the median worked by hand; two assets' rows of one technique at one level reduce
// to one point, and the points come out in ascending x whatever the row order.
TEST(PlotData, RowsOfOneSeriesAtOneXReduceToTheirMedian) {
  results::Results results;
  results.measures.push_back(memoryDeclaration());
  for (const auto& [asset, at16] :
       {std::pair{"a", 1.0}, std::pair{"b", 3.0}, std::pair{"c", 8.0}}) {
    results.records.push_back(
        record("acc", "default", asset,
               memoryResult({row({{"level", "16"}}, {{"ratio", at16, "ratio"}}),
                             row({{"level", "8"}}, {{"ratio", 0.5, "ratio"}})})));
  }
  const report::PlotData data = report::plotData(results, results.measures[0], linePlot());
  ASSERT_EQ(data.charts.size(), 1u);
  ASSERT_EQ(data.charts[0].series.size(), 1u);
  const report::PlotSeries& series = data.charts[0].series[0];
  EXPECT_EQ(series.name, "acc");
  ASSERT_EQ(series.points.size(), 2u);
  EXPECT_EQ(series.points[0].x, 8);
  EXPECT_EQ(series.points[1].x, 16);
  EXPECT_EQ(series.points[1].y, 3.0);  // median of 1, 3, 8
  EXPECT_EQ(series.points[1].rows, 3u);
  EXPECT_EQ(series.points[1].label, "acc/default");
  EXPECT_EQ(data.rows_used, 6u);
  EXPECT_EQ(data.y_label, "ratio (ratio)");
  EXPECT_EQ(data.x_label, "level");
  // A plot declared with reduce max takes the largest of the same rows instead.
  results::PlotSpec largest = linePlot();
  largest.reduce = results::PlotReduce::kMax;
  const report::PlotData max_data = report::plotData(results, results.measures[0], largest);
  EXPECT_EQ(max_data.charts[0].series[0].points[1].y, 8.0);
  EXPECT_EQ(max_data.charts[0].series[0].points[0].y, 0.5);
}

TEST(PlotData, RowsWithANonNumericXAreSkippedAndCounted) {
  results::Results results;
  results.measures.push_back(memoryDeclaration());
  results::MeasureResult m =
      memoryResult({row({{"level", "8"}}, {{"ratio", 2, "ratio"}}),
                    row({{"level", "edge_pattern"}}, {{"ratio", 9, "ratio"}}),
                    row({{"other", "1"}}, {{"ratio", 9, "ratio"}}), row({{"level", "16"}}, {})});
  m.rows.push_back(
      results::unmeasuredRow({{"level", "32"}}, results::MeasureStatus::kSkipped, "no device"));
  results.records.push_back(record("acc", "default", "a", m));
  const report::PlotData data = report::plotData(results, results.measures[0], linePlot());
  EXPECT_EQ(data.rows_used, 1u);
  EXPECT_EQ(data.rows_without_x, 2u);
  EXPECT_EQ(data.rows_without_y, 1u);  // the skipped row is not a row of the plot at all
}

TEST(PlotData, WhereSelectsRowsAndSeriesMayBeARowKey) {
  results::Results results;
  results.measures.push_back(memoryDeclaration());
  results.records.push_back(record(
      "acc", "default", "a",
      memoryResult(
          {row({{"level", "8"}, {"backend", "cpu"}, {"part", "x"}}, {{"ratio", 1, "ratio"}}),
           row({{"level", "8"}, {"backend", "gpu"}, {"part", "x"}}, {{"ratio", 2, "ratio"}}),
           row({{"level", "8"}, {"backend", "gpu"}, {"part", "y"}}, {{"ratio", 7, "ratio"}})})));
  results::PlotSpec spec = linePlot();
  spec.series = "backend";
  spec.where = {{"part", "x"}};
  const report::PlotData data = report::plotData(results, results.measures[0], spec);
  ASSERT_EQ(data.charts.size(), 1u);
  ASSERT_EQ(data.charts[0].series.size(), 2u);
  EXPECT_EQ(data.charts[0].series[0].name, "cpu");
  EXPECT_EQ(data.charts[0].series[1].name, "gpu");
  EXPECT_EQ(data.charts[0].series[1].points[0].y, 2);
}

// A bar's categories are the x values in first-seen order; "variant" is technique/variant.
TEST(PlotData, BarsHaveCategoriesAndLogZerosAreCounted) {
  results::Results results;
  results.measures.push_back(memoryDeclaration());
  results.records.push_back(record("acc", "default", "a",
                                   memoryResult({row({{"level", "8"}}, {{"ratio", 0, "ratio"}})})));
  results.records.push_back(record(
      "acc", "asymmetric", "a", memoryResult({row({{"level", "8"}}, {{"ratio", 40, "ratio"}})})));
  results::PlotSpec spec{.title = "t",
                         .kind = results::PlotKind::kBar,
                         .x = "variant",
                         .y = "ratio",
                         .facet = "",
                         .where = {},
                         .log_y = true};
  const report::PlotData data = report::plotData(results, results.measures[0], spec);
  ASSERT_EQ(data.charts.size(), 1u);
  EXPECT_EQ(data.charts[0].categories, (std::vector<std::string>{"acc/default", "acc/asymmetric"}));
  const report::PlotSeries& series = data.charts[0].series[0];
  ASSERT_EQ(series.points.size(), 2u);
  EXPECT_EQ(series.points[1].x, 1);
  EXPECT_EQ(series.points[1].category, "acc/asymmetric");
  EXPECT_EQ(data.points_hidden_by_log, 1u);
}

// The error plot's x: the instructions measure's worst figure per record over its summary
// scope (here: rows with stage *.tese); each technique × variant its own point, even at an
// equal x; a facet per asset, those with one point dropped.
TEST(PlotData, CrossMeasureXComesFromTheOtherMeasuresSummary) {
  results::Results results;
  results::MeasureDeclaration error{"error", "Error", "d", {}, {"hausdorff"}, {}};
  error.metrics = {{"hausdorff", results::Unit::kDiagonal, results::Direction::kLowerIsBetter}};
  results::MeasureDeclaration instructions{"instructions", "Instructions", "d", {}, {"total"}, {}};
  instructions.metrics = {{"total", results::Unit::kCount, results::Direction::kLowerIsBetter}};
  instructions.summary_scope = {{"stage", "*.tese"}};
  results.measures = {error, instructions};
  auto add = [&](const std::string& variant, const std::string& asset, double tes,
                 double hausdorff) {
    results::Record r{"phong", variant, asset, {}, {}, {}};
    results::MeasureResult e;
    e.measure = "error";
    e.rows.push_back(row({}, {{"hausdorff", hausdorff, "rel_diag"}}));
    results::MeasureResult i;
    i.measure = "instructions";
    i.rows.push_back(row({{"stage", "p.tese"}}, {{"total", tes, "count"}}));
    i.rows.push_back(row({{"stage", "p.tesc"}}, {{"total", 10 * tes, "count"}}));
    r.measures = {e, i};
    results.records.push_back(r);
  };
  add("a", "cube", 100, 0.01);
  add("b", "cube", 100, 0.02);
  add("c", "cube", 200, 0.005);
  add("a", "lonely", 100, 0.01);
  results::PlotSpec spec{.title = "t",
                         .kind = results::PlotKind::kScatter,
                         .x = "instructions.total",
                         .y = "hausdorff",
                         .facet = "asset",
                         .where = {},
                         .pareto_front = true};
  const report::PlotData data = report::plotData(results, results.measures[0], spec);
  EXPECT_EQ(data.x_label, "instructions total (count)");
  EXPECT_TRUE(data.point_per_variant);
  EXPECT_EQ(data.charts_dropped, 1u);
  ASSERT_EQ(data.charts.size(), 1u);
  EXPECT_EQ(data.charts[0].facet, "cube");
  const std::vector<report::PlotPoint>& points = data.charts[0].series[0].points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0].x, 100);  // the .tese stage, not the 10x larger .tesc row
  EXPECT_EQ(points[0].label, "phong/a");
  EXPECT_EQ(points[1].label, "phong/b");
  EXPECT_EQ(points[2].x, 200);
  // a: cheapest and better than b; c: costlier but the most accurate; b is beaten by a.
  EXPECT_TRUE(points[0].on_front);
  EXPECT_FALSE(points[1].on_front);
  EXPECT_TRUE(points[2].on_front);
}

TEST(PlotData, ParetoFrontFollowsTheDirectionOfY) {
  report::PlotChart chart;
  chart.series.push_back({"s", {}});
  for (const auto& [x, y] : {std::pair{1.0, 1.0}, {2.0, 3.0}, {3.0, 2.0}, {2.0, 3.0}}) {
    report::PlotPoint p;
    p.x = x;
    p.y = y;
    chart.series[0].points.push_back(p);
  }
  report::markParetoFront(&chart, results::Direction::kHigherIsBetter);
  const auto& p = chart.series[0].points;
  // Higher y is better: (1,1) is cheapest; both (2,3) tie and beat (3,2).
  EXPECT_TRUE(p[0].on_front);
  EXPECT_TRUE(p[1].on_front);
  EXPECT_FALSE(p[2].on_front);
  EXPECT_TRUE(p[3].on_front);
  report::markParetoFront(&chart, results::Direction::kLowerIsBetter);
  EXPECT_TRUE(p[0].on_front);
  EXPECT_FALSE(p[1].on_front);
  EXPECT_FALSE(p[2].on_front);
}

}  // namespace
}  // namespace tb
