// The declared comparison and control rows over the committed default run
// (results/baseline/results.json, whose adaptivity declaration carries them): report.md's
// adaptivity section opens with the table, report.html draws one more chart per asset ×
// camera path than without the declaration. And the baseline's bytes: reading and writing it
// again changes none, and without the new fields they are left out.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "harness/report/comparison.h"
#include "harness/report/html.h"
#include "harness/report/markdown.h"
#include "harness/results/results_json.h"
#include "tests/test_paths.h"

namespace tb {
namespace {

std::string baselinePath() { return std::string(TB_SOURCE_DIR) + "/results/baseline/results.json"; }

const results::Results& declaredBaseline() {
  static const results::Results r = results::readResultsFile(baselinePath());
  return r;
}

// The baseline as a run from before the declarations would have written it.
const results::Results& plainBaseline() {
  static const results::Results r = [] {
    results::Results run = declaredBaseline();
    for (results::MeasureDeclaration& d : run.measures) {
      d.control_rows.clear();
      d.comparisons.clear();
    }
    return run;
  }();
  return r;
}

TEST(ComparisonBaseline, RewritingTheBaselineKeepsItsBytes) {
  std::ifstream file(baselinePath());
  std::stringstream bytes;
  bytes << file.rdbuf();
  EXPECT_TRUE(results::serializeResults(declaredBaseline()) == bytes.str());
  EXPECT_NE(bytes.str().find("\"control_rows\""), std::string::npos);
  // Empty declarations are left out, so a file from before them keeps its bytes.
  const std::string plain = results::serializeResults(plainBaseline());
  EXPECT_EQ(plain.find("\"control_rows\""), std::string::npos);
  EXPECT_EQ(plain.find("\"comparisons\""), std::string::npos);
}

TEST(ComparisonBaseline, AdaptivitySectionOpensWithTrianglesAt1px) {
  const results::Results& run = declaredBaseline();
  const results::MeasureDeclaration* adaptivity = run.findMeasure("adaptivity");
  ASSERT_NE(adaptivity, nullptr);
  const report::ComparisonTable table =
      report::comparisonTable(run, *adaptivity, adaptivity->comparisons[0]);
  ASSERT_GE(table.groups.size(), 10u) << "a table per asset of the default suite";
  for (const report::ComparisonGroup& group : table.groups) {
    EXPECT_EQ(group.facets.size(), 2u) << group.name() << ": one spacing in the default suite";
    EXPECT_GE(group.key_columns, 1u) << group.name();
    EXPECT_FALSE(group.lines.empty()) << group.name();
    EXPECT_EQ(group.columns.at(group.key_columns), "uniform") << group.name();
  }
  const std::string md = report::renderMarkdown(run);
  const size_t section = md.find("### adaptivity\n\nTriangles per frame at a 1 px");
  ASSERT_NE(section, std::string::npos);
  const size_t first = md.find("| " + table.groups[0].facets[0].second + " | ", section);
  EXPECT_LT(first, md.find("**Tessellation-factor adaptivity", section));
  // tests/baseline/check_baseline.sh's limit on the default run's report.md.
  EXPECT_LT(std::count(md.begin(), md.end(), '\n'), 1500);
  const std::string html = report::renderHtml(run, {"window.Chart = function () {};", "", {}, {}});
  const std::string plain =
      report::renderHtml(plainBaseline(), {"window.Chart = function () {};", "", {}, {}});
  const auto charts = [](const std::string& page) {
    const size_t at = page.find("data-charts=\"") + 13;
    return std::stoul(page.substr(at, page.find('"', at) - at));
  };
  // A bar chart per group of every declared comparison (adaptivity's and isa's).
  size_t groups = 0;
  for (const results::MeasureDeclaration& declaration : run.measures) {
    for (const results::ComparisonSpec& spec : declaration.comparisons) {
      groups += report::comparisonTable(run, declaration, spec).groups.size();
    }
  }
  EXPECT_GE(groups, table.groups.size());
  EXPECT_EQ(charts(html), charts(plain) + groups);
}

}  // namespace
}  // namespace tb
