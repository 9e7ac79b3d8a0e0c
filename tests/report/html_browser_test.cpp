// report.html in a real browser. Oracle: headless Chromium (Debian's chromium) loads the
// page a small `tessbench run` wrote, with a pictures index beside it, and its DOM after
// the scripts ran says what happened: each canvas Chart.js drew carries data-rendered, and
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
using testing::readFile;
using testing::runTessbenchSplit;

// A 4 x 4 RGB PNG (a colour gradient), made with Python's zlib and struct.
constexpr unsigned char kTinyPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
    0x52, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x04, 0x08, 0x02, 0x00, 0x00, 0x00, 0x26,
    0x93, 0x09, 0x29, 0x00, 0x00, 0x00, 0x2a, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x0d, 0xc9,
    0x41, 0x11, 0x00, 0x00, 0x0c, 0x83, 0xb0, 0x0a, 0xab, 0xb0, 0x0a, 0xc3, 0x1f, 0xdb, 0x8f,
    0x0b, 0x31, 0xb1, 0x71, 0x91, 0xaf, 0xd4, 0xd6, 0x55, 0xde, 0x32, 0x3b, 0x37, 0xf9, 0x1b,
    0x2c, 0x0e, 0xe1, 0x00, 0x82, 0x82, 0x1b, 0x31, 0x56, 0xca, 0x50, 0xce, 0x00, 0x00, 0x00,
    0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

bool chromiumOnPath() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

size_t occurrences(const std::string& text, const std::string& what) {
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// The text after the first `open` up to the next `close`; empty when there is none.
std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const size_t start = text.find(open);
  if (start == std::string::npos) return {};
  const size_t from = start + open.size();
  const size_t end = text.find(close, from);
  return end == std::string::npos ? std::string() : text.substr(from, end - from);
}

// The pictures index `run` writes (harness/pictures), with one picture pair and one
// failed entry, so the page embeds the first and notes the second.
void writePictures(const fs::path& run) {
  fs::create_directories(run / "pictures");
  for (const char* name : {"error.png", "wireframe.png"}) {
    std::ofstream(run / "pictures" / name, std::ios::binary)
        .write(reinterpret_cast<const char*>(kTinyPng), sizeof(kTinyPng));
  }
  testing::writeTextFile(run / "pictures" / "pictures.json", R"({
 "schema_version": 1, "status": "ok", "device": "llvmpipe", "error_unit": "rel_diag",
 "pictures": [
  {"technique": "phong", "variant": "alpha0.75", "asset": "opensubdiv/catmark_cube", "level": 8,
   "error_png": "pictures/error.png", "wireframe_png": "pictures/wireframe.png",
   "width_px": 4, "height_px": 4, "error_max": 0.0123, "error_statistic": "max_of_3_vertices",
   "scale_min": 0, "scale_max": 0.0123},
  {"technique": "gregory_acc", "variant": "default", "asset": "loop_cube", "status": "failed",
   "reason": "a device error", "error_png": "", "wireframe_png": ""}
 ]
})");
}

// Runs chromium headless on `page` with extra arguments; stdout goes to `out`, stderr (its
// log noise) is dropped. Returns the exit status.
int runChromium(const fs::path& profile, const std::string& arguments, const fs::path& page,
                const fs::path& out) {
  const std::string command =
      "timeout 120 chromium --headless=new --no-sandbox --disable-gpu "
      "--no-first-run --user-data-dir=" +
      profile.string() + " --virtual-time-budget=5000 " + arguments + " file://" + page.string() +
      " >" + out.string() + " 2>/dev/null";
  return std::system(command.c_str());
}

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
  writePictures(folder);

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
  EXPECT_EQ(occurrences(dom, "<img alt="), 2u);
  EXPECT_EQ(occurrences(dom, "src=\"data:image/png;base64,iVBORw0KGgo"), 2u);
  EXPECT_NE(dom.find("failed: a device error"), std::string::npos);

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
