// The declared comparisons (harness/report/comparison.h) and the control rows of a declaration:
// the table opening a measure's report.md section, the grouped bar chart of report.html, and
// control rows kept out of every ranking (summaries, answers, decisions). Synthetic adaptivity
// results: no measure is run.
#include "harness/report/comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "harness/report/answers.h"
#include "harness/report/decision.h"
#include "harness/report/html.h"
#include "harness/report/markdown.h"
#include "harness/report/summary.h"
#include "tests/report/results_builders.h"

namespace tb {
namespace {

using results::Direction;
using results::Unit;

const char* const kLead =
    "Triangles per frame at a 1 px tessellation error (fewer is better); ideal = the per-patch "
    "optimum every policy is held against";

results::ComparisonSpec trianglesAt1px() {
  return {.title = kLead,
          .where = {{"summary", "max_error_1px"}},
          .column_key = "policy",
          .metric = "triangles_per_frame_at_target",
          .valid_flag = "target_reached",
          .extra_columns = {{"uniform", "uniform_triangles_per_frame"},
                            {"ideal", "ideal_triangles_per_frame"}},
          .facets = {"asset", "camera_path"}};
}

results::MeasureDeclaration adaptivityDeclaration() {
  results::MeasureDeclaration d{
      "adaptivity", "Adaptivity", "d", {}, {"triangle_ratio_vs_uniform"}, {}};
  d.metrics = {{"triangles_per_frame_at_target", Unit::kCount, Direction::kLowerIsBetter},
               {"uniform_triangles_per_frame", Unit::kCount, Direction::kLowerIsBetter},
               {"ideal_triangles_per_frame", Unit::kCount, Direction::kLowerIsBetter},
               {"triangle_ratio_vs_uniform", Unit::kRatio, Direction::kLowerIsBetter},
               {"target_reached", Unit::kFlag, Direction::kNone},
               {"triangles", Unit::kCount, Direction::kNone}};
  d.control_rows = {{{"policy", "*_order_dependent"}}, {{"policy", "error_bound_loose"}}};
  d.comparisons = {trianglesAt1px()};
  return d;
}

// A summary row (summary = max_error_1px, camera_path = orbit); ideal < 0: no ideal figure.
results::MetricRow summaryRow(const std::string& policy, double triangles, double uniform,
                              double ideal, double reached = 1,
                              const std::string& spacing = "fractional_odd") {
  results::MetricRow r = testing::row({{"policy", policy},
                                       {"spacing", spacing},
                                       {"summary", "max_error_1px"},
                                       {"camera_path", "orbit"}},
                                      {{"triangles_per_frame_at_target", triangles},
                                       {"uniform_triangles_per_frame", uniform},
                                       {"triangle_ratio_vs_uniform", triangles / uniform},
                                       {"target_reached", reached}});
  if (ideal >= 0) r.metrics.push_back({"ideal_triangles_per_frame", ideal, ""});
  return r;
}

void addRecord(results::Results* results, const std::string& technique, const std::string& variant,
               const std::string& asset, std::vector<results::MetricRow> rows) {
  results::Record record{technique, variant, asset, {}, {}, {}};
  results::MeasureResult m = testing::measureResult("adaptivity");
  m.rows = std::move(rows);
  record.measures.push_back(std::move(m));
  results->records.push_back(std::move(record));
}

// acc (default and fast), pn, and cracky (a control variant) on cube; acc on torus. The
// control policy error_bound_loose always has the fewest triangles; acc/fast (not a default
// variant) and cracky fewer still.
results::Results adaptivityRun() {
  results::Results results;
  results.context.run_id = "r";
  results.measures.push_back(adaptivityDeclaration());
  results.context.selection.techniques = {
      {"acc", {"default", "fast"}}, {"pn", {"default"}}, {"cracky", {"default"}, {"default"}}};
  results.assets.push_back({"cube", "", 6, 8, "quads", false});
  results.assets.push_back({"torus", "", 16, 16, "quads", false});
  // torus first in the records: the tables follow the run's asset order.
  addRecord(&results, "acc", "default", "torus",
            {summaryRow("sphere_diameter", 700, 900, -1), summaryRow("lp2_edge", 700, 900, -1)});
  addRecord(
      &results, "acc", "default", "cube",
      {summaryRow("sphere_diameter", 1000, 4000, 500), summaryRow("lp2_edge", 800, 4000, 500),
       summaryRow("error_bound", 600, 4000, 500), summaryRow("error_bound_loose", 300, 4000, 500),
       testing::row({{"policy", "sphere_diameter"}, {"frame", "0"}, {"camera_path", "orbit"}},
                    {{"triangles", 999}})});
  addRecord(&results, "acc", "fast", "cube", {summaryRow("sphere_diameter", 100, 4000, 500)});
  addRecord(
      &results, "pn", "default", "cube",
      {summaryRow("sphere_diameter", 2000, 3000, -1), summaryRow("lp2_edge", 1500, 3000, -1, 0),
       summaryRow("error_bound", 2500, 3000, -1), summaryRow("error_bound_loose", 100, 3000, -1)});
  addRecord(&results, "cracky", "default", "cube", {summaryRow("sphere_diameter", 10, 4000, 500)});
  testing::withRegisteredDeclarations(&results);
  return results;
}

std::optional<double> cell(const report::ComparisonGroup& group, size_t line,
                           const std::string& column) {
  const auto it = std::find(group.columns.begin(), group.columns.end(), column);
  if (it == group.columns.end()) return std::nullopt;
  return group.lines.at(line).cells.at(size_t(it - group.columns.begin())).value;
}

TEST(ControlRows, AnyDeclaredScopeMarksARow) {
  const results::MeasureDeclaration d = adaptivityDeclaration();
  EXPECT_TRUE(results::isControlRow(d, {{"policy", "distance_order_dependent"}, {"frame", "1"}}));
  EXPECT_TRUE(results::isControlRow(d, {{"policy", "error_bound_loose"}}));
  EXPECT_FALSE(results::isControlRow(d, {{"policy", "error_bound"}}));
  EXPECT_FALSE(results::isControlRow(d, {}));
  results::MeasureDeclaration empty_entry = d;
  empty_entry.control_rows = {{}};  // an empty scope would match every row: it marks none
  EXPECT_FALSE(results::isControlRow(empty_entry, {{"policy", "error_bound"}}));
}

TEST(Comparison, OneGroupPerAssetAndPathDefaultVariantsNoControls) {
  const results::Results run = adaptivityRun();
  const report::ComparisonTable table =
      report::comparisonTable(run, run.measures[0], run.measures[0].comparisons[0]);
  EXPECT_EQ(table.unit, "count");
  EXPECT_EQ(table.controls_left_out, std::vector<std::string>{"error_bound_loose"});
  ASSERT_EQ(table.groups.size(), 2u);
  const report::ComparisonGroup& cube = table.groups[0];
  EXPECT_EQ(cube.name(), "cube, camera_path orbit");
  EXPECT_EQ(table.groups[1].name(), "torus, camera_path orbit");
  EXPECT_EQ(cube.columns, (std::vector<std::string>{"sphere_diameter", "lp2_edge", "error_bound",
                                                    "uniform", "ideal"}));
  EXPECT_EQ(cube.key_columns, 3u);
  ASSERT_EQ(cube.lines.size(), 2u);  // acc and pn: not acc/fast, not the control cracky
  EXPECT_EQ(cube.lines[0].technique, "acc");
  EXPECT_EQ(cube.lines[0].variant, "default");
  EXPECT_EQ(cell(cube, 0, "error_bound"), 600);
  EXPECT_TRUE(cube.lines[0].cells[2].best);
  EXPECT_FALSE(cube.lines[0].cells[0].best);
  EXPECT_FALSE(cube.lines[0].cells[4].best) << "extra columns are never the best";
  EXPECT_EQ(cell(cube, 0, "uniform"), 4000);
  EXPECT_EQ(cell(cube, 0, "ideal"), 500);
  EXPECT_EQ(cell(cube, 1, "lp2_edge"), std::nullopt) << "target_reached = 0";
  EXPECT_EQ(cell(cube, 1, "ideal"), std::nullopt) << "pn emits no ideal";
  EXPECT_TRUE(cube.lines[1].cells[0].best);  // sphere_diameter 2000 < error_bound 2500
}

TEST(Comparison, TiesAreAllBestAndAnAbsentExtraColumnIsLeftOut) {
  const results::Results run = adaptivityRun();
  const report::ComparisonGroup torus =
      report::comparisonTable(run, run.measures[0], run.measures[0].comparisons[0]).groups[1];
  EXPECT_EQ(torus.columns, (std::vector<std::string>{"sphere_diameter", "lp2_edge", "uniform"}));
  ASSERT_EQ(torus.lines.size(), 1u);
  EXPECT_TRUE(torus.lines[0].cells[0].best);
  EXPECT_TRUE(torus.lines[0].cells[1].best);
}

TEST(Comparison, AKeyWithSeveralValuesSplitsTheGroups) {
  results::Results run = adaptivityRun();
  run.records[1].measures[0].rows.push_back(
      summaryRow("sphere_diameter", 1200, 5000, 600, 1, "integer"));
  const report::ComparisonTable table =
      report::comparisonTable(run, run.measures[0], run.measures[0].comparisons[0]);
  ASSERT_EQ(table.groups.size(), 3u);  // torus has fractional_odd rows only
  EXPECT_EQ(table.groups[0].name(), "cube, camera_path orbit, spacing fractional_odd");
  EXPECT_EQ(table.groups[1].name(), "cube, camera_path orbit, spacing integer");
  EXPECT_EQ(table.groups[1].columns,
            (std::vector<std::string>{"sphere_diameter", "uniform", "ideal"}));
  EXPECT_FALSE(table.groups[1].lines[0].cells[0].best) << "one policy: nothing in bold";
  EXPECT_EQ(table.groups[2].name(), "torus, camera_path orbit, spacing fractional_odd");
}

// The section of the measure opens with the lead and the tables, before its declaration.
TEST(Comparison, OpensTheMeasureSectionOfReportMd) {
  const std::string md = report::renderMarkdown(adaptivityRun());
  const size_t section = md.find("### adaptivity\n\n");
  ASSERT_NE(section, std::string::npos) << md;
  EXPECT_EQ(md.find(std::string("### adaptivity\n\n") + kLead + "\n\n"), section) << md;
  const size_t declaration = md.find("**Adaptivity**", section);
  ASSERT_NE(declaration, std::string::npos);
  const std::string tables = md.substr(section, declaration - section);
  EXPECT_NE(tables.find("controls left out: error_bound_loose"), std::string::npos) << tables;
  // One table for the orbit, the asset its first column, cube's lines before torus's.
  EXPECT_NE(
      tables.find("**camera_path orbit**\n\n| asset | technique | sphere_diameter | lp2_edge | "
                  "error_bound | uniform | ideal |\n"),
      std::string::npos)
      << tables;
  EXPECT_NE(tables.find("| cube | acc | 1000 | 800 | **600** | 4000 | 500 |\n"
                        "|  | pn | **2000** | — | 2500 | 3000 | — |\n"
                        "| torus | acc | **700** | **700** | — | 900 | — |\n"),
            std::string::npos)
      << tables;
  for (const char* absent : {"cracky", "| 300 |", "| 100 |", "| 10 |"}) {
    EXPECT_EQ(tables.find(absent), std::string::npos) << absent;
  }
  // The rest of the section: the controls named, the control rows marked in the detail table.
  EXPECT_NE(md.find("- controls (rows made to show a failure", declaration), std::string::npos);
  EXPECT_NE(md.find("| ok (control) |", declaration), std::string::npos) << md;
}

TEST(Comparison, GroupedBarChartPerGroup) {
  const results::Results run = adaptivityRun();
  const report::PlotData plot = report::comparisonPlot(
      report::comparisonTable(run, run.measures[0], run.measures[0].comparisons[0]));
  EXPECT_EQ(plot.spec.kind, results::PlotKind::kBar);
  EXPECT_EQ(plot.y_label, "triangles_per_frame_at_target (count)");
  ASSERT_EQ(plot.charts.size(), 2u);
  const report::PlotChart& cube = plot.charts[0];
  EXPECT_EQ(cube.facet, "cube, camera_path orbit");
  EXPECT_EQ(cube.categories, (std::vector<std::string>{"acc", "pn"}));
  ASSERT_EQ(cube.series.size(), 5u);
  EXPECT_EQ(cube.series[3].name, "uniform");
  EXPECT_EQ(cube.series[4].name, "ideal");
  ASSERT_EQ(cube.series[1].points.size(), 1u) << "pn's lp2_edge did not reach the target";
  EXPECT_EQ(cube.series[1].points[0].x, 0);
  EXPECT_EQ(cube.series[1].points[0].y, 800);
  ASSERT_EQ(cube.series[4].points.size(), 1u) << "pn has no ideal";
  EXPECT_EQ(cube.series[0].points[1].label, "pn/default");
  EXPECT_EQ(plot.note,
            "8 rows of each technique's default variant with summary = max_error_1px; a bar per "
            "policy, uniform (uniform_triangles_per_frame), ideal (ideal_triangles_per_frame); "
            "controls left out: error_bound_loose; no bar: no figure or target_reached = 0.");

  const std::string html = report::renderHtml(run, {"window.Chart = function () {};", "", {}, {}});
  EXPECT_NE(html.find("data-charts=\"2\""), std::string::npos);
  EXPECT_NE(html.find("\"title\":\"cube, camera_path orbit\""), std::string::npos) << html;
  EXPECT_NE(html.find("\"categories\":[\"acc\",\"pn\"]"), std::string::npos);
  EXPECT_NE(html.find("{\"name\":\"ideal\""), std::string::npos);
  EXPECT_EQ(html.find("{\"name\":\"error_bound_loose\""), std::string::npos);
}

TEST(Comparison, ControlRowsNeverRankInSummariesAnswersOrDecisions) {
  const results::Results run = adaptivityRun();
  const report::MeasureSummary summary =
      report::summarizeMeasure(run, "adaptivity", report::SummaryGrouping::kPerAsset);
  const auto acc_cube = std::find_if(summary.lines.begin(), summary.lines.end(), [](const auto& l) {
    return l.technique == "acc" && l.variant == "default" && l.asset == "cube";
  });
  ASSERT_NE(acc_cube, summary.lines.end());
  EXPECT_DOUBLE_EQ(acc_cube->find("triangle_ratio_vs_uniform")->min, 600.0 / 4000);

  const report::DecisionFigures pn = report::decisionFigures(run, "pn", "default", "cube");
  EXPECT_EQ(pn.triangles_1px, 2000);
  EXPECT_EQ(pn.triangles_policy, "sphere_diameter");
  EXPECT_EQ(report::decisionFigures(run, "acc", "default", "cube").triangles_policy, "error_bound");

  for (const report::Answer& answer : report::answerQuestions(run, {})) {
    if (answer.question != "Does any factor policy beat uniform?") continue;
    EXPECT_NE(answer.answer.find("error_bound needs"), std::string::npos) << answer.answer;
    EXPECT_EQ(answer.answer.find("error_bound_loose"), std::string::npos) << answer.answer;
  }
}

}  // namespace
}  // namespace tb
