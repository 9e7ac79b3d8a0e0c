#include "harness/report/markdown.h"

#include <gtest/gtest.h>

#include "tests/report/results_builders.h"

namespace tb {
namespace {

TEST(Markdown, RendersOneTablePerMeasureWithUnits) {
  results::Results results;
  results.context.run_id = "r";
  results::Record record{"phong", "alpha0.75",           "opensubdiv/catmark_cube",
                         {},      {"12 polygons split"}, {}};
  results::MeasureResult memory;
  memory.measure = "memory";
  memory.rows.push_back(
      {{{"level", "8"}}, {{"plain_bytes", 2048, "bytes"}, {"ratio", 1.5, "ratio"}}});
  memory.rows.push_back(
      {{{"level", "16"}}, {{"plain_bytes", 8192, "bytes"}, {"ratio", 3, "ratio"}}});
  record.measures.push_back(memory);
  results.records.push_back(record);
  results.skipped.push_back({"acc", "loop_cube", "acc: face 0 has 3 vertices; ACC needs quads"});
  const std::string md = report::renderMarkdown(results);
  EXPECT_NE(md.find("### memory"), std::string::npos);
  // A small measure also shows its rows.
  EXPECT_NE(
      md.find(
          "| technique | variant | asset | level | status | plain_bytes (bytes) | ratio (ratio) |"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("| phong | alpha0.75 | opensubdiv/catmark_cube | 16 | ok | 8.00 KiB | 3 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("ACC needs quads"), std::string::npos);
  EXPECT_NE(md.find("12 polygons split"), std::string::npos);
}

// A run's figures for the summary tests: `assets` × {acc/default, acc/fast}, a measure
// "error" with 3 rows per record (levels), hausdorff = base × (level index + 1).
results::Results summaryResults(size_t assets, size_t levels) {
  results::Results results;
  results::MeasureDeclaration error{"error", "Error", "d", {}, {"hausdorff"}, {"a fixed note"}};
  error.metrics = {{"hausdorff", results::Unit::kDiagonal, results::Direction::kLowerIsBetter},
                   {"samples", results::Unit::kCount, results::Direction::kNone}};
  results.measures.push_back(error);
  results.context.selection.techniques = {{"acc", {"default", "fast"}}, {"pn", {"pn"}}};
  for (size_t a = 0; a < assets; ++a) {
    const std::string asset = "asset" + std::to_string(a);
    results.assets.push_back({asset, "", 1, 4, "quads", false});
    results.skipped.push_back({"pn", asset, "pn: needs triangles"});
    for (const char* variant : {"default", "fast"}) {
      results::Record record{"acc", variant, asset, {}, {}, {}};
      results::MeasureResult m;
      m.measure = "error";
      const double base = std::string(variant) == "fast" ? 0.5 : 0.25;
      for (size_t level = 0; level < levels; ++level) {
        m.rows.push_back({{{"level", std::to_string(level)}},
                          {{"hausdorff", base * static_cast<double>(level + 1), "rel_diag"},
                           {"samples", 81, "count"}}});
      }
      record.measures.push_back(m);
      results.records.push_back(record);
    }
  }
  testing::withRegisteredDeclarations(&results);
  return results;
}

// report.md opens with the answers and the decision per asset, then the three jobs
// (regression, choice, publishing), then the matrices, then the measures; the run context and
// assets come last.
TEST(Markdown, SummaryFirstThenMatricesThenMeasures) {
  const std::string md = report::renderMarkdown(summaryResults(2, 3));
  const size_t answers = md.find("## Answers");
  const size_t decisions = md.find("## Decision per surface asset");
  const size_t regression = md.find("## Regression tracking");
  EXPECT_LT(answers, decisions);
  EXPECT_LT(decisions, regression);
  const size_t choice = md.find("## Choosing a technique per asset");
  const size_t publishing = md.find("## Publishing tables");
  const size_t matrices = md.find("## Technique × asset matrices");
  const size_t measures = md.find("## Measures");
  const size_t context = md.find("## Run context");
  ASSERT_NE(regression, std::string::npos) << md;
  EXPECT_LT(regression, choice);
  EXPECT_LT(choice, publishing);
  EXPECT_LT(publishing, matrices);
  EXPECT_LT(matrices, measures);
  EXPECT_LT(measures, context);
  // Decision: the only default variant with its worst error over the levels (0.25 × 3); no
  // column for the figures the run lacks.
  EXPECT_NE(
      md.find("### asset0\n\n| rank | technique/variant | path | error (hausdorff, rel_diag) |\n"),
      std::string::npos)
      << md;
  EXPECT_NE(md.find("| **1 (recommended)** | acc/default | tessellator | 0.75 |"),
            std::string::npos)
      << md;
  // Publishing: median (worst) over assets and levels of each variant.
  EXPECT_NE(md.find("| acc | fast | 1 (1.5) |"), std::string::npos) << md;
  // Matrix: the default variant; a technique that took no asset (pn: n/a everywhere) is no
  // column.
  EXPECT_NE(md.find("| asset | acc/default |\n|---|---|\n| asset0 | 0.75 |\n| asset1 | 0.75 |"),
            std::string::npos)
      << md;
  // Coverage: how many assets each technique measured and its first refusal.
  EXPECT_NE(md.find("| acc | 2 of 2 | 0 |  |"), std::string::npos) << md;
  EXPECT_NE(md.find("| pn | 0 of 2 | 2 | asset0: pn: needs triangles |"), std::string::npos) << md;
  // Measure section: median / worst per technique × variant.
  EXPECT_NE(md.find("| acc | default | 6 | 0.5 / 0.75 |"), std::string::npos) << md;
}

// A measure with many rows leaves them to tables/<measure>.csv; report.md stays short
// however many rows there are.
TEST(Markdown, ManyRowsGoToCsvNotToTheReport) {
  const results::Results small = summaryResults(2, 3);
  const results::Results large = summaryResults(2, 400);
  const auto lines = [](const std::string& text) {
    return std::count(text.begin(), text.end(), '\n');
  };
  EXPECT_NE(report::renderMarkdown(small).find("| acc | default | asset0 | 2 | ok |"),
            std::string::npos);
  const std::string md = report::renderMarkdown(large);
  EXPECT_EQ(md.find("| acc | default | asset0 | 2 | ok |"), std::string::npos);
  EXPECT_NE(md.find("Every row (1600): `tables/error.csv`"), std::string::npos) << md;
  // The answers and the decision tables add a fixed 20 lines or so, not one per row.
  EXPECT_LT(lines(md), 130) << md;
}

TEST(Markdown, SkippedMeasureShowsItsReason) {
  results::Results results;
  results::Record record{"phong", "alpha0.75", "a", {}, {}, {}};
  record.measures.push_back({"gpu", results::MeasureStatus::kSkipped, "no Vulkan device", {}, {}});
  results.records.push_back(record);
  EXPECT_NE(report::renderMarkdown(results).find("skipped: no Vulkan device"), std::string::npos);
}

// A row that could not run shows its status and reason in the status column, not figures.
TEST(Markdown, SkippedRowShowsItsStatusAndReason) {
  results::Results results;
  results::Record record{"acc", "default", "a", {}, {}, {}};
  results::MeasureResult cracks{"cracks", results::MeasureStatus::kOk, "", {}, {}};
  cracks.rows.push_back({{{"backend", "cpu_float"}}, {{"points_not_equal", 0, "count"}}});
  cracks.rows.push_back(results::unmeasuredRow(
      {{"backend", "gpu"}}, results::MeasureStatus::kSkipped, "no Vulkan device"));
  record.measures.push_back(cracks);
  results.records.push_back(record);
  const std::string md = report::renderMarkdown(results);
  EXPECT_NE(md.find("| acc | default | a | cpu_float | ok | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| acc | default | a | gpu | skipped: no Vulkan device |"), std::string::npos)
      << md;
}

// Fixed notes come from the declaration, once; a record's own notes follow the table,
// each naming its record, whichever record has them (not only the first).
TEST(Markdown, RendersFixedNotesOnceAndEachRecordsOwnNotes) {
  results::Results results;
  results::MeasureDeclaration error{
      "error",       "Error against the limit",
      "distances",   {},
      {"hausdorff"}, {"distances are fractions of the bounding-box diagonal"}};
  error.metrics = {{"hausdorff", results::Unit::kDiagonal, results::Direction::kLowerIsBetter},
                   {"samples", results::Unit::kCount, results::Direction::kNone}};
  results.measures.push_back(error);
  for (const char* asset : {"opensubdiv/catmark_cube", "opensubdiv/catmark_pyramid"}) {
    results::Record record{"gregory_acc", "edge_symmetric", asset, {}, {}, {}};
    results::MeasureResult m;
    m.measure = "error";
    m.rows.push_back({{}, {{"hausdorff", 0.25, "rel_diag"}, {"samples", 81, "count"}}});
    if (std::string(asset).ends_with("pyramid")) {
      m.notes = {"4 triangle patches compared through sub-faces"};
    }
    record.measures.push_back(m);
    results.records.push_back(record);
  }
  const std::string md = report::renderMarkdown(results);
  const std::string note = "distances are fractions of the bounding-box diagonal";
  const size_t fixed = md.find("- " + note);
  EXPECT_NE(fixed, std::string::npos) << md;
  EXPECT_EQ(md.find(note, fixed + 3), std::string::npos) << "rendered once";
  EXPECT_NE(md.find("| hausdorff (rel_diag, lower better) | samples (count) |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("- headline: hausdorff"), std::string::npos) << md;
  EXPECT_NE(md.find("Notes per record"), std::string::npos) << md;
  EXPECT_NE(md.find("- gregory_acc/edge_symmetric on opensubdiv/catmark_pyramid: 4 triangle "
                    "patches compared through sub-faces"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("on opensubdiv/catmark_cube: "), std::string::npos) << "the cube has no note";
}

TEST(Markdown, FormatsBytesAndValues) {
  EXPECT_EQ(report::formatBytes(812), "812 B");
  EXPECT_EQ(report::formatBytes(1536), "1.50 KiB");
  EXPECT_EQ(report::formatBytes(3.0 * 1024 * 1024), "3.00 MiB");
  EXPECT_EQ(report::formatMetricValue({"n", 42, "count"}), "42");
  EXPECT_EQ(report::formatMetricValue({"r", 0.123456, "ratio"}), "0.1235");
}

}  // namespace
}  // namespace tb

namespace tb {
namespace {

// A measure's matrix lists the inputs it ran on and the techniques that ran it: a
// simulation measure's matrix has its scenario and not the mesh assets, and a surface
// measure's leaves out the scenario.
TEST(Markdown, MatricesListOnlyTheInputsAndTechniquesOfTheirMeasure) {
  results::Results results = summaryResults(2, 1);
  results::MeasureDeclaration wave{"wave", "Wave", "d", {}, {"rms"}, {}};
  wave.metrics = {{"rms", results::Unit::kRatio, results::Direction::kLowerIsBetter}};
  results.measures.push_back(wave);
  results.context.selection.techniques.push_back({"sim", {"full"}});
  results::Record record{"sim", "full", "scenario_a", {}, {}, {}};
  results::MeasureResult m;
  m.measure = "wave";
  m.rows.push_back({{{"time", "1"}}, {{"rms", 0.125, "ratio"}}});
  record.measures.push_back(m);
  results.records.push_back(record);
  const std::string md = report::renderMarkdown(results);
  const size_t wave_matrix = md.find("### wave: rms");
  const size_t error_matrix = md.find("### error: hausdorff");
  ASSERT_NE(wave_matrix, std::string::npos) << md;
  ASSERT_NE(error_matrix, std::string::npos) << md;
  const std::string wave_text =
      md.substr(wave_matrix, md.find("\n\n", md.find("|", wave_matrix)) - wave_matrix);
  const std::string error_text =
      md.substr(error_matrix, md.find("\n\n", md.find("|", error_matrix)) - error_matrix);
  EXPECT_NE(wave_text.find("| asset | sim/full |"), std::string::npos) << wave_text;
  EXPECT_NE(wave_text.find("| scenario_a | 0.125 |"), std::string::npos) << wave_text;
  EXPECT_EQ(wave_text.find("asset0"), std::string::npos) << wave_text;
  EXPECT_EQ(error_text.find("scenario_a"), std::string::npos) << error_text;
  EXPECT_EQ(error_text.find("sim/full"), std::string::npos) << error_text;
  EXPECT_NE(error_text.find("| asset0 |"), std::string::npos) << error_text;
}

}  // namespace
}  // namespace tb
