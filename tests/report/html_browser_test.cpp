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

TEST(HtmlBrowser, ChromiumDrawsEveryChartWithoutAScriptError) {
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
  const size_t pictures = occurrences(index, "\"error_png\": \"pictures/");
  if (index.find("\"status\": \"skipped\"") == std::string::npos) {
    EXPECT_GE(pictures, 3u) << index;  // gregory_acc on the cube, phong on both
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
  EXPECT_EQ(occurrences(dom, "<img alt="), 2 * pictures);
  EXPECT_EQ(occurrences(dom, "src=\"data:image/png;base64,iVBORw0KGgo"), 2 * pictures);

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

}  // namespace
}  // namespace tb
