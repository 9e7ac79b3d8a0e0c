#include <gtest/gtest.h>

#include "harness/report/markdown.h"

namespace tb {
namespace {

TEST(Markdown, RendersOneTablePerMeasureWithUnits) {
  Results results;
  results.context.run_id = "r";
  Record record{"phong", "alpha0.75", "opensubdiv/catmark_cube", {}, {"12 polygons split"}, {}};
  MeasureResult memory;
  memory.measure = "memory";
  memory.rows.push_back({{{"level", "8"}}, {{"plain_bytes", 2048, "bytes"}, {"ratio", 1.5, "ratio"}}});
  memory.rows.push_back({{{"level", "16"}}, {{"plain_bytes", 8192, "bytes"}, {"ratio", 3, "ratio"}}});
  record.measures.push_back(memory);
  results.records.push_back(record);
  results.skipped.push_back({"acc", "loop_cube", "acc: face 0 has 3 vertices; ACC needs quads"});
  const std::string md = renderMarkdown(results);
  EXPECT_NE(md.find("## Measure: memory"), std::string::npos);
  EXPECT_NE(md.find("| technique | variant | asset | level | status | plain_bytes (bytes) | ratio (ratio) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| phong | alpha0.75 | opensubdiv/catmark_cube | 16 | ok | 8.00 KiB | 3 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("ACC needs quads"), std::string::npos);
  EXPECT_NE(md.find("12 polygons split"), std::string::npos);
}

// Rows keyed `summary` open the measure's section in their own table, with only their
// metrics; the other rows follow the declaration without the summary's columns.
TEST(Markdown, SummaryRowsComeFirstInTheirOwnTable) {
  Results results;
  MeasureDeclaration adaptivity{"adaptivity", "Adaptivity", "d", {}, {"ratio"}, {"a fixed note"}};
  adaptivity.metrics = {{"ratio", Unit::kRatio, Direction::kLowerIsBetter},
                        {"triangles", Unit::kCount, Direction::kLowerIsBetter}};
  results.measures.push_back(adaptivity);
  Record record{"acc", "default", "opensubdiv/catmark_cube", {}, {}, {}};
  MeasureResult m;
  m.measure = "adaptivity";
  m.rows.push_back({{{"frame", "0"}, {"policy", "p"}}, {{"triangles", 100, "count"}}});
  m.rows.push_back({{{"policy", "p"}, {"summary", "max_error_1px"}}, {{"ratio", 0.25, "ratio"}}});
  record.measures.push_back(m);
  results.records.push_back(record);
  const std::string md = renderMarkdown(results);
  const size_t section = md.find("## Measure: adaptivity\n\n");
  ASSERT_NE(section, std::string::npos);
  const std::string summary_header =
      "| technique | variant | asset | policy | summary | status | ratio (ratio, lower better) |";
  EXPECT_EQ(md.find(summary_header), section + std::string("## Measure: adaptivity\n\n").size())
      << md;
  EXPECT_LT(md.find(summary_header), md.find("a fixed note"));
  EXPECT_NE(md.find("| technique | variant | asset | frame | policy | status | triangles (count, "
                    "lower better) |"),
            std::string::npos)
      << md;
}

TEST(Markdown, SkippedMeasureShowsItsReason) {
  Results results;
  Record record{"phong", "alpha0.75", "a", {}, {}, {}};
  record.measures.push_back({"gpu", MeasureStatus::kSkipped, "no Vulkan device", {}, {}});
  results.records.push_back(record);
  EXPECT_NE(renderMarkdown(results).find("skipped: no Vulkan device"), std::string::npos);
}

// A row that could not run shows its status and reason in the status column, not figures.
TEST(Markdown, SkippedRowShowsItsStatusAndReason) {
  Results results;
  Record record{"acc", "default", "a", {}, {}, {}};
  MeasureResult cracks{"cracks", MeasureStatus::kOk, "", {}, {}};
  cracks.rows.push_back({{{"backend", "cpu_float"}}, {{"points_not_equal", 0, "count"}}});
  cracks.rows.push_back(
      unmeasuredRow({{"backend", "gpu"}}, MeasureStatus::kSkipped, "no Vulkan device"));
  record.measures.push_back(cracks);
  results.records.push_back(record);
  const std::string md = renderMarkdown(results);
  EXPECT_NE(md.find("| acc | default | a | cpu_float | ok | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| acc | default | a | gpu | skipped: no Vulkan device |"),
            std::string::npos)
      << md;
}

// Fixed notes come from the declaration, once; a record's own notes follow the table,
// each naming its record, whichever record has them (not only the first).
TEST(Markdown, RendersFixedNotesOnceAndEachRecordsOwnNotes) {
  Results results;
  MeasureDeclaration error{"error",       "Error against the limit",
                           "distances",   {},
                           {"hausdorff"}, {"distances are fractions of the bounding-box diagonal"}};
  error.metrics = {{"hausdorff", Unit::kDiagonal, Direction::kLowerIsBetter},
                   {"samples", Unit::kCount, Direction::kNone}};
  results.measures.push_back(error);
  for (const char* asset : {"opensubdiv/catmark_cube", "opensubdiv/catmark_pyramid"}) {
    Record record{"gregory_acc", "edge_symmetric", asset, {}, {}, {}};
    MeasureResult m;
    m.measure = "error";
    m.rows.push_back({{}, {{"hausdorff", 0.25, "rel_diag"}, {"samples", 81, "count"}}});
    if (std::string(asset).ends_with("pyramid")) {
      m.notes = {"4 triangle patches compared through sub-faces"};
    }
    record.measures.push_back(m);
    results.records.push_back(record);
  }
  const std::string md = renderMarkdown(results);
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
  EXPECT_EQ(formatBytes(812), "812 B");
  EXPECT_EQ(formatBytes(1536), "1.50 KiB");
  EXPECT_EQ(formatBytes(3.0 * 1024 * 1024), "3.00 MiB");
  EXPECT_EQ(formatMetricValue({"n", 42, "count"}), "42");
  EXPECT_EQ(formatMetricValue({"r", 0.123456, "ratio"}), "0.1235");
}

}  // namespace
}  // namespace tb
