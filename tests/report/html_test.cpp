#include "harness/report/html.h"

#include <gtest/gtest.h>

#include <regex>

#include "tests/cli/cli_support.h"

namespace tb {
namespace {

// A stand-in for Chart.js: these tests read the page's text, never run it.
constexpr const char* kChartStub = "window.Chart = function () {};";

using testing::occurrences;

results::Results memoryRun(const std::string& technique) {
  results::Results results;
  results.context.run_id = "r";
  results.context.git_sha = "abc123";
  results.context.vulkan_device = "llvmpipe";
  results::MeasureDeclaration memory{"memory", "Memory", "bytes", {}, {"ratio"}, {}};
  memory.metrics = {{"ratio", results::Unit::kRatio, results::Direction::kHigherIsBetter}};
  memory.plots = {results::PlotSpec{.title = "Ratio against level",
                                    .kind = results::PlotKind::kLine,
                                    .x = "level",
                                    .y = "ratio",
                                    .facet = "",
                                    .where = {},
                                    .log_x = true}};
  results.measures.push_back(memory);
  results::Record record{technique, "default", "cube", {}, {}, {}};
  results::MeasureResult m;
  m.measure = "memory";
  m.rows.push_back({{{"level", "8"}}, {{"ratio", 2, "ratio"}}});
  m.rows.push_back({{{"level", "16"}}, {{"ratio", 5, "ratio"}}});
  record.measures.push_back(m);
  results.records.push_back(record);
  return results;
}

TEST(Html, OneCanvasPerChartWithItsDataAndTheRunContext) {
  const std::string html = report::renderHtml(memoryRun("acc"), {kChartStub, "", {}, {}});
  EXPECT_EQ(occurrences(html, "<canvas"), 1u);
  EXPECT_NE(html.find("data-charts=\"1\""), std::string::npos);
  EXPECT_NE(html.find("\"log_x\":true"), std::string::npos) << html;
  EXPECT_NE(html.find("\"x_label\":\"level\",\"y_label\":\"ratio (ratio)\""), std::string::npos);
  EXPECT_NE(html.find("Ratio against level"), std::string::npos);
  EXPECT_NE(html.find("abc123"), std::string::npos);
  EXPECT_NE(html.find("llvmpipe"), std::string::npos);
  EXPECT_NE(html.find(kChartStub), std::string::npos);
  EXPECT_EQ(html, report::renderHtml(memoryRun("acc"), {kChartStub, "", {}, {}}))
      << "deterministic";
}

// Works offline: nothing of the page points outside it (no http(s) anywhere, no src or
// href but data: URIs, no stylesheet links or imports).
TEST(Html, ReferencesNoExternalResource) {
  report::HtmlAssets assets{
      kChartStub, "", {{"acc/default on cube", "", {{"error", "\x89PNG\r\n\x1a\n"}}}}, {}};
  const std::string html = report::renderHtml(memoryRun("acc"), assets);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  const std::regex reference(R"re((src|href)\s*=\s*"([^"]*)")re");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), reference);
       it != std::sregex_iterator(); ++it) {
    EXPECT_EQ((*it)[2].str().rfind("data:", 0), 0u) << (*it)[0].str();
  }
  EXPECT_NE(html.find("src=\"data:image/png;base64,iVBORw0KGgo=\""), std::string::npos) << html;
}

// A name that closes the script element must stay text: in the markup as character
// references, in the JSON data as \u003c escapes; the page keeps exactly its own scripts.
TEST(Html, ScriptEndInATechniqueNameIsEscaped) {
  const std::string evil = "</script><script>window.pwned = 1</script>";
  const std::string html = report::renderHtml(memoryRun(evil), {kChartStub, "", {}, {}});
  EXPECT_EQ(html.find("window.pwned = 1</script>"), std::string::npos);
  EXPECT_EQ(occurrences(html, "</script>"), occurrences(html, "<script"));
  EXPECT_NE(html.find("\\u003c/script\\u003e\\u003cscript\\u003ewindow.pwned"), std::string::npos)
      << html;
  // And in Chart.js's own text (a string holding the end tag) it is split too.
  const std::string library = "var s = '</SCRIPT>'; var c = '<!--';";
  const std::string with_library = report::renderHtml(memoryRun("acc"), {library, "", {}, {}});
  EXPECT_NE(with_library.find("var s = '<\\/SCRIPT>'; var c = '<\\!--';"), std::string::npos);
}

TEST(Html, WithoutChartJsThePageSaysWhyAndDrawsNothing) {
  const std::string html = report::renderHtml(
      memoryRun("acc"), {"", "/x/chart.min.js: cannot read Chart.js", {}, {"No pictures: none."}});
  EXPECT_NE(html.find("Charts unavailable: /x/chart.min.js: cannot read Chart.js."),
            std::string::npos);
  EXPECT_EQ(html.find("<canvas"), std::string::npos);
  EXPECT_EQ(html.find("chart-data"), std::string::npos);
  EXPECT_NE(html.find("Ratio against level"), std::string::npos)
      << "the plot's title and note stay";
  EXPECT_NE(html.find("No pictures: none."), std::string::npos);
}

}  // namespace
}  // namespace tb
