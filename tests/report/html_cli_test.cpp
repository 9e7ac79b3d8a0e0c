// The CLI side of report.html: `run` writes it, `report --format html` prints it, and both
// say what is missing (Chart.js, pictures) in the ways the user can act on.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::lineCount;
using testing::readFile;
using testing::runTessbenchSplit;

// A one-record run (phong on the cube, memory only: well under a second).
fs::path smallRun(const std::string& name) {
  const fs::path dir = testing::scratchDirectory(name);
  const testing::SplitResult run = runTessbenchSplit(
      "run --quiet --no-pictures --technique phong --asset catmark_cube --measure memory "
      "--run-id r --out " +
      dir.string());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return dir / "r";
}

// A run that measured error renders its pictures on the device (lavapipe) and report.html
// embeds the heat map of each technique x asset as a PNG data: URI (the wireframes stay in
// the run folder), under one colour scale for the asset, stated once.
TEST(HtmlCli, RunEmbedsTheHeatMapsUnderOneScalePerAsset) {
  const fs::path dir = testing::scratchDirectory("html_cli_real_pictures");
  const testing::SplitResult run = runTessbenchSplit(
      "run --quiet --technique phong --technique gregory_acc --asset catmark_cube --measure "
      "error --run-id r --out " +
      dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string index = readFile(dir / "r" / "pictures" / "pictures.json");
  if (index.find("\"status\": \"skipped\"") != std::string::npos) {
    GTEST_SKIP() << "no Vulkan device: " << index;
  }
  const std::string page = readFile(dir / "r" / "report.html");
  size_t images = 0;
  for (size_t at = page.find("src=\"data:image/png;base64,iVBORw0KGgo"); at != std::string::npos;
       at = page.find("src=\"data:image/png;base64,iVBORw0KGgo", at + 1)) {
    ++images;
  }
  EXPECT_EQ(images, 2u) << "2 techniques x error heat map";
  EXPECT_NE(page.find("one colour scale for every picture of the asset"), std::string::npos);
  EXPECT_TRUE(
      fs::exists(dir / "r" / "pictures" / "gregory_acc--opensubdiv--catmark_cube--wireframe.png"));
  EXPECT_TRUE(
      fs::exists(dir / "r" / "pictures" / "gregory_acc--opensubdiv--catmark_cube--error.png"));
  fs::remove_all(dir);
}

TEST(HtmlCli, WithoutChartJsRunWarnsOnceAndReportExitsTwoNamingTheFile) {
  const std::string missing = "TESSBENCH_CHARTJS=/nonexistent/chart.umd.js";
  const fs::path dir = testing::scratchDirectory("html_cli_nochart");
  const testing::SplitResult run = runTessbenchSplit(
      "run --quiet --technique phong --asset catmark_cube --measure memory --run-id r --out " +
          dir.string(),
      missing);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(lineCount(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("warning: /nonexistent/chart.umd.js"), std::string::npos) << run.err;
  const std::string page = readFile(dir / "r" / "report.html");
  EXPECT_NE(page.find("Charts unavailable: /nonexistent/chart.umd.js"), std::string::npos);

  const testing::SplitResult report =
      runTessbenchSplit("report --format html " + (dir / "r").string(), missing);
  EXPECT_EQ(report.exit_code, 2);
  EXPECT_EQ(report.out, "");
  EXPECT_EQ(lineCount(report.err), 1u) << report.err;
  EXPECT_NE(report.err.find("/nonexistent/chart.umd.js"), std::string::npos) << report.err;
  fs::remove_all(dir);
}

TEST(HtmlCli, ReportSaysWhyThereAreNoPictures) {
  const fs::path run = smallRun("html_cli_pictures");
  const testing::SplitResult absent = runTessbenchSplit("report --format html " + run.string());
  ASSERT_EQ(absent.exit_code, 0) << absent.err;
  EXPECT_NE(absent.out.find("No pictures: the run folder has no pictures/pictures.json."),
            std::string::npos);
  EXPECT_NE(absent.out.find("<canvas"), std::string::npos) << "the memory plot is drawn";

  // Another format (a list at the top): skipped with a note, the report still renders.
  fs::create_directories(run / "pictures");
  testing::writeTextFile(run / "pictures" / "pictures.json", "[{\"png\": \"x.png\"}]");
  const testing::SplitResult other = runTessbenchSplit("report --format html " + run.string());
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.out.find("is not an object with a &quot;pictures&quot; list"), std::string::npos);

  // An entry whose file is missing is left out by name.
  testing::writeTextFile(run / "pictures" / "pictures.json",
                         R"({"pictures": [{"technique": "phong", "variant": "alpha0.75", )"
                         R"("asset": "opensubdiv/catmark_cube", "error_png": "pictures/e.png"}]})");
  const testing::SplitResult missing = runTessbenchSplit("report --format html " + run.string());
  ASSERT_EQ(missing.exit_code, 0) << missing.err;
  EXPECT_NE(missing.out.find("pictures/e.png left out: cannot be read"), std::string::npos);
  fs::remove_all(run.parent_path());
}

// `markdown` is the format's one spelling (help, default); `md` stays accepted for it. Each
// prints the run's report.md.
TEST(HtmlCli, FormatMarkdownAndItsAliasMdPrintReportMd) {
  const fs::path run = smallRun("html_cli_markdown");
  const std::string expected = readFile(run / "report.md");
  for (const std::string format : {"", " --format markdown", " --format md"}) {
    const testing::SplitResult report = runTessbenchSplit("report " + run.string() + format);
    EXPECT_EQ(report.exit_code, 0) << format << ": " << report.err;
    EXPECT_EQ(report.out, expected) << format;
  }
  const testing::SplitResult help = runTessbenchSplit("report --help");
  EXPECT_NE(help.out.find("--format TEXT=markdown"), std::string::npos) << help.out;
  fs::remove_all(run.parent_path());
}

TEST(HtmlCli, UnknownFormatIsOneLineListingTheKnownOnes) {
  const fs::path run = smallRun("html_cli_format");
  const testing::SplitResult report = runTessbenchSplit("report --format pdf " + run.string());
  EXPECT_EQ(report.exit_code, 2);
  EXPECT_NE(report.err.find("known: markdown, html"), std::string::npos) << report.err;
  fs::remove_all(run.parent_path());
}

}  // namespace
}  // namespace tb
