// report.html in a real browser. Oracle: headless Chromium (Debian's chromium) loads the
// page a small `tessbench run` wrote, with the pictures it rendered on the device, and its DOM
// after the scripts ran says what happened: each canvas Chart.js drew carries data-rendered, and
// any script error is a list item of #script-errors. A screenshot stays in the build tree
// (test-artefacts/report_html.png) for a person to look at. Skipped when chromium is not
// on PATH (scripts/install_deps.sh installs it; CI runs this test).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "harness/results/results_json.h"
#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::between;
using testing::chromiumOnPath;
using testing::occurrences;
using testing::readFile;
using testing::runChromium;
using testing::runTessbenchSplit;

// The browser's time dominates these tests; the report's own code runs under a sanitizer in
// tests/report (the same run folder's report.html, without a browser).
constexpr const char* kSanitizerSkip = "the browser check runs in the Release step";

TEST(HtmlBrowser, ChromiumDrawsEveryChartWithoutAScriptError) {
  if (testing::kUnderSanitizer) GTEST_SKIP() << kSanitizerSkip;
  if (!chromiumOnPath()) {
    GTEST_SKIP() << "chromium is not on PATH: the browser test of report.html needs Debian's "
                    "chromium package (scripts/install_deps.sh installs it)";
  }
  const fs::path dir = testing::scratchDirectory("report_browser");
  const testing::SplitResult run = runTessbenchSplit(
      "run --quiet --technique gregory_acc --technique phong --asset catmark_cube --asset "
      "loop_cube --measure memory --measure error --measure instructions --measure cracks "
      "--run-id r --out " +
      dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const fs::path folder = dir / "r";
  ASSERT_TRUE(fs::exists(folder / "report.html")) << "run writes report.html beside report.md";
  // The pictures the run rendered on the device (lavapipe): an error heat map and a
  // wireframe per technique x asset with an error record.
  const std::string index = readFile(folder / "pictures" / "pictures.json");
  // Every error picture and every crack picture (phong/alpha0.75 cracks on the cube).
  const size_t pictures = occurrences(index, "\"error_png\": \"pictures/") +
                          occurrences(index, "\"crack_png\": \"pictures/");
  if (index.find("\"status\": \"skipped\"") == std::string::npos) {
    EXPECT_GE(pictures, 4u) << index;  // gregory_acc on the cube, phong on both, phong's cracks
  }

  const testing::SplitResult report = runTessbenchSplit("report --format html " + folder.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const fs::path page = dir / "report.html";
  std::ofstream(page) << report.out;
  const std::string chart_count = between(report.out, "data-charts=\"", "\"");
  ASSERT_FALSE(chart_count.empty()) << "report.html names no chart count";
  const size_t expected = std::stoul(chart_count);
  // memory: 1 chart; error: 1 per asset; cracks: 1.
  EXPECT_GE(expected, 4u);

  const fs::path dom_file = dir / "dom.html";
  ASSERT_EQ(runChromium(dir / "profile", "--dump-dom", page, dom_file), 0);
  const std::string dom = readFile(dom_file);
  ASSERT_NE(dom.find("</html>"), std::string::npos) << "chromium dumped no page";
  EXPECT_EQ(occurrences(dom, "<canvas"), expected);
  EXPECT_EQ(occurrences(dom, "data-rendered=\"true\""), expected) << "a chart was not drawn";
  const std::string errors = between(dom, "<ul id=\"script-errors\"", "</ul>");
  EXPECT_EQ(errors.substr(errors.find('>') + 1), "") << "script errors in the page";
  // The error heat maps (the wireframes stay in the run folder: the page's size).
  EXPECT_EQ(occurrences(dom, "<img alt="), pictures);
  EXPECT_EQ(occurrences(dom, "src=\"data:image/png;base64,iVBORw0KGgo"), pictures);

  // The check can fail: the same page with a script that throws shows the error.
  const fs::path broken = dir / "broken.html";
  std::string broken_page = report.out;
  broken_page.insert(broken_page.rfind("</body>"),
                     "<script>throw new Error('tessbench test error');</script>\n");
  std::ofstream(broken) << broken_page;
  ASSERT_EQ(runChromium(dir / "profile", "--dump-dom", broken, dom_file), 0);
  EXPECT_NE(
      between(readFile(dom_file), "<ul id=\"script-errors\"", "</ul>").find("tessbench test error"),
      std::string::npos);

  const fs::path artefacts = fs::path(TB_BINARY_DIR) / "test-artefacts";
  fs::create_directories(artefacts);
  const fs::path screenshot = artefacts / "report_html.png";
  fs::remove(screenshot);
  fs::copy_file(page, artefacts / "report_html.html", fs::copy_options::overwrite_existing);
  EXPECT_EQ(runChromium(dir / "profile",
                        "--screenshot=" + screenshot.string() +
                            " --window-size=1280,2000 --hide-scrollbars",
                        page, dir / "screenshot.log"),
            0);
  EXPECT_TRUE(fs::exists(screenshot) && fs::file_size(screenshot) > 0);
  std::printf("report.html screenshot: %s\n", screenshot.string().c_str());
  fs::remove_all(dir);
}

// Measures the page as drawn and writes what it found on <body>: whether the answers and the
// first trade-off chart are on the first 1400 x 900 screen, the log axes spanning more than 3
// decades without a point, and the points whose dataset has no technique label.
constexpr const char* kFirstScreenProbe = R"JS(<script>
(function () {
  // The first screen is the 1400 x 900 screenshot's (headless Chromium's own viewport is
  // shorter than its window).
  var b = document.body, h = 900;
  var answers = document.getElementById('answers').getBoundingClientRect();
  var chart = document.querySelector('#tradeoffs canvas');
  var c = chart ? chart.getBoundingClientRect() : null;
  b.setAttribute('data-answers-on-screen', answers.top >= 0 && answers.bottom <= h);
  function onScreen(r) { return !!r && r.top >= 0 && r.bottom <= h; }
  b.setAttribute('data-chart-on-screen', onScreen(c));
  b.setAttribute('data-chart-bottom', c ? Math.round(c.bottom) + ' of ' + h : 'none');
  // The same test on a box below the first screen must say false (the check can fail).
  var below = document.createElement('div');
  below.style.cssText = 'position:absolute;top:' + (h + 50) + 'px;height:10px;width:10px';
  b.appendChild(below);
  b.setAttribute('data-below-on-screen', onScreen(below.getBoundingClientRect()));
  var violations = [], unlabelled = 0;
  Object.values(Chart.instances).forEach(function (chart) {
    ['x', 'y'].forEach(function (axis) {
      var scale = chart.scales[axis];
      if (!scale || scale.type !== 'logarithmic') return;
      var decades = {};
      chart.data.datasets.forEach(function (set) {
        set.data.forEach(function (p) {
          var v = typeof p === 'object' && p !== null ? p[axis] : p;
          if (v > 0) decades[Math.floor(Math.log10(v))] = true;
        });
      });
      var lo = Math.floor(Math.log10(scale.min)), hi = Math.ceil(Math.log10(scale.max));
      var empty = 0;
      for (var d = lo; d < hi; ++d) empty += decades[d] ? 0 : 1;
      if (empty > 3) violations.push(chart.canvas.id + ':' + axis + ':' + empty);
    });
    chart.data.datasets.forEach(function (set) {
      if (!set.label) unlabelled += set.data.length;
    });
  });
  b.setAttribute('data-axis-violations', violations.join(' '));
  b.setAttribute('data-unlabelled-points', unlabelled);
})();
</script>
)JS";

// Acceptance of issue 39 on the default run's page (rendered from the committed
// results/baseline: every bundled asset, no pictures): the first screen shows the answers and
// the first trade-off chart, no log axis spans more than 3 empty decades, every point has a
// technique label; a box placed below the screen shows the check can fail.
TEST(HtmlBrowser, DefaultRunFirstScreenAnswersAndTradeOffChart) {
  if (testing::kUnderSanitizer) GTEST_SKIP() << kSanitizerSkip;
  if (!chromiumOnPath()) GTEST_SKIP() << "chromium is not on PATH";
  const fs::path dir = testing::scratchDirectory("report_first_screen");
  const testing::SplitResult report = runTessbenchSplit(
      "report --format html " + (fs::path(TB_SOURCE_DIR) / "results" / "baseline").string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  std::string page = report.out;
  page.insert(page.rfind("</body>"), kFirstScreenProbe);
  std::ofstream(dir / "page.html") << page;
  ASSERT_EQ(runChromium(dir / "profile", "--dump-dom --window-size=1400,900 --hide-scrollbars",
                        dir / "page.html", dir / "dom.html"),
            0);
  const std::string dom = readFile(dir / "dom.html");
  EXPECT_NE(dom.find("data-answers-on-screen=\"true\""), std::string::npos);
  EXPECT_NE(dom.find("data-chart-on-screen=\"true\""), std::string::npos)
      << between(dom, "data-chart-bottom=\"", "\"");
  EXPECT_NE(dom.find("data-axis-violations=\"\""), std::string::npos)
      << between(dom, "data-axis-violations=\"", "\"");
  EXPECT_NE(dom.find("data-unlabelled-points=\"0\""), std::string::npos);
  EXPECT_EQ(between(dom, "<ul id=\"script-errors\"", "</ul>").find("<li>"), std::string::npos);
  EXPECT_NE(dom.find("data-below-on-screen=\"false\""), std::string::npos);
  fs::remove_all(dir);
}

// The comparison a measure declares, drawn (report.html's grouped bars): the committed default
// run with the adaptivity declaration given a comparison and control rows as results.json
// carries them, rendered by `report --format html` and loaded in Chromium: every canvas drawn,
// a bar chart per asset × camera path among them, and no script error.
TEST(HtmlBrowser, ComparisonBarChartsAreDrawn) {
  if (testing::kUnderSanitizer) GTEST_SKIP() << kSanitizerSkip;
  if (!chromiumOnPath()) GTEST_SKIP() << "chromium is not on PATH";
  const fs::path dir = testing::scratchDirectory("report_comparison");
  const std::string baseline = (fs::path(TB_SOURCE_DIR) / "results" / "baseline").string();
  results::Results run = results::readResultsFile(baseline + "/results.json");
  for (results::MeasureDeclaration& d : run.measures) {
    if (d.measure != "adaptivity") continue;
    d.control_rows = {{{"policy", "*_order_dependent"}}};
    d.comparisons = {{.title = "Triangles per frame at 1 px",
                      .where = {{"summary", "max_error_1px"}},
                      .column_key = "policy",
                      .metric = "triangles_per_frame_at_target",
                      .valid_flag = "target_reached",
                      .extra_columns = {{"uniform", "uniform_triangles_per_frame"}},
                      .facets = {"asset", "camera_path"}}};
  }
  fs::create_directories(dir / "run");
  std::ofstream(dir / "run" / "results.json") << results::serializeResults(run);
  const testing::SplitResult report =
      runTessbenchSplit("report --format html " + (dir / "run").string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const size_t expected = std::stoul(between(report.out, "data-charts=\"", "\""));
  EXPECT_GE(
      occurrences(report.out, ", camera_path orbit\",\"x_label\":\"technique (default variant)\""),
      30u)
      << "a bar chart per bundled asset on the orbit";
  std::ofstream(dir / "page.html") << report.out;
  ASSERT_EQ(runChromium(dir / "profile", "--dump-dom", dir / "page.html", dir / "dom.html"), 0);
  const std::string dom = readFile(dir / "dom.html");
  EXPECT_EQ(occurrences(dom, "<canvas"), expected);
  EXPECT_EQ(occurrences(dom, "data-rendered=\"true\""), expected) << "a chart was not drawn";
  EXPECT_EQ(between(dom, "<ul id=\"script-errors\"", "</ul>").find("<li>"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tb
