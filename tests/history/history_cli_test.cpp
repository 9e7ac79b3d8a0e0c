// `tessbench history` on real runs. Acceptance: a history of runs at four commits, the
// `regress` plug-in built as it is at the first two and built broken at the last two
// (tests/cli/regress_plugin.cpp, as compare's acceptance tests use it), flags exactly the
// step between the second and third commit and nothing else; its page renders in headless
// Chromium (oracle: the DOM after the scripts ran) with a line per series. Also: two adds at
// once both land, an add killed midway leaves the database as it was, and bad input is one
// line and exit 2. Runs have no Vulkan device: CPU figures only, as in compare's tests.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/history/history_store.h"
#include "harness/results/results_json.h"
#include "tests/cli/cli_support.h"
#include "tests/history/history_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::readFile;
using testing::runTessbenchSplit;
using testing::SplitResult;

using testing::between;
using testing::kNoVulkanDevice;
using testing::occurrences;

// A run of regress and phong on the Loop cube (error and cracks) with `plugin`, made as if at
// commit `index` (its context's git sha and commit time rewritten: a run records the build's
// own). Returns the folder.
std::string runAtCommit(const fs::path& dir, const char* plugin, int index) {
  const std::string run_id = "c" + std::to_string(index);
  const SplitResult r = runTessbenchSplit(
      std::string("--plugin ") + plugin +
          " run --quiet --no-pictures --technique regress --technique phong --asset loop_cube "
          "--measure error --measure cracks --out " +
          (dir / "runs").string() + " --run-id " + run_id,
      kNoVulkanDevice);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const fs::path file = dir / "runs" / run_id / "results.json";
  results::Results results = results::readResultsFile(file.string());
  results.context.git_sha =
      std::string(4, char('a' + index)) + "000000000000000000000000000000000000";
  results.context.commit_time = "2026-01-0" + std::to_string(index + 1) + "T12:00:00+00:00";
  fs::remove(file);
  results::writeNewFile(file.string(), results::serializeResults(results));
  return (dir / "runs" / run_id).string();
}

// The page in headless Chromium: every chart drawn with its lines, no script error.
void expectRendersInChromium(const fs::path& dir, const fs::path& page,
                             const nlohmann::json& charts) {
  if (!testing::chromiumOnPath()) {
    std::printf("chromium is not on PATH: the browser check of history.html is skipped\n");
    return;
  }
  const fs::path dom_file = dir / "dom.html";
  ASSERT_EQ(testing::runChromium(dir / "profile", "--dump-dom", page, dom_file), 0);
  const std::string dom = readFile(dom_file);
  ASSERT_NE(dom.find("</html>"), std::string::npos) << "chromium dumped no page";
  EXPECT_EQ(occurrences(dom, "data-rendered=\"true\""), charts.size()) << "a chart was not drawn";
  const std::string errors = between(dom, "<ul id=\"script-errors\"", "</ul>");
  EXPECT_EQ(errors.substr(errors.find('>') + 1), "") << "script errors in the page";
  for (const auto& chart : charts) {
    const std::string canvas =
        between(dom, "id=\"" + chart["canvas"].get<std::string>() + "\"", ">");
    EXPECT_NE(canvas.find("data-series=\"" + std::to_string(chart["series"].size()) + "\""),
              std::string::npos)
        << chart["canvas"] << ": " << canvas;
  }
}

TEST(HistoryAcceptance, AFigureChangedAtOneCommitIsTheOneStepFlagged) {
  const fs::path dir = testing::scratchDirectory("history_acceptance");
  const std::string db = (dir / "h.sqlite").string();
  std::string folders;
  for (int i = 0; i < 4; ++i)
    folders += " " + runAtCommit(dir, i < 2 ? testing::regressGood() : testing::regressBroken(), i);
  const SplitResult add = runTessbenchSplit("history add --db " + db + folders);
  ASSERT_EQ(add.exit_code, 0) << add.out << add.err;
  EXPECT_EQ(testing::lineCount(add.out), 4u) << add.out;
  const SplitResult report =
      runTessbenchSplit("history report --db " + db + " --out " + (dir / "report").string());
  ASSERT_EQ(report.exit_code, 0) << report.out << report.err;

  // history.md: every flagged step is regress/default's, from commit 1 to commit 2.
  const std::string markdown = readFile(dir / "report" / "history.md");
  const std::string table = between(markdown, "## Flagged steps", "### Figures");
  size_t steps = 0;
  for (size_t at = table.find("\n| "); at != std::string::npos; at = table.find("\n| ", at + 1)) {
    const std::string line = table.substr(at + 1, table.find('\n', at + 1) - at - 1);
    if (line.rfind("| change", 0) == 0) continue;
    ++steps;
    EXPECT_NE(line.find("| regression | bbbb000 2026-01-02 → cccc000 2026-01-03 |"),
              std::string::npos)
        << line;
    EXPECT_NE(line.find("| regress/default |"), std::string::npos) << line;
  }
  EXPECT_EQ(steps, 2u) << markdown;  // its error and its cracks figures

  // history.html: the points marked are regress/default's at commit 2 only.
  const std::string html = readFile(dir / "report" / "history.html");
  const nlohmann::json data = nlohmann::json::parse(
      between(html, "<script type=\"application/json\" id=\"chart-data\">", "</script>"));
  const nlohmann::json& charts = data.at("charts");
  EXPECT_EQ(std::to_string(charts.size()), between(html, "data-charts=\"", "\""));
  size_t marked = 0;
  for (const auto& chart : charts) {
    EXPECT_EQ(chart.at("series").size(), 3u) << chart.at("title");  // regress, phong × 2
    for (const auto& series : chart.at("series")) {
      for (const auto& point : series.at("points")) {
        if (!point.contains("step")) continue;
        ++marked;
        EXPECT_EQ(series.at("name"), "regress/default");
        EXPECT_EQ(point.at("x"), 2);
      }
    }
  }
  EXPECT_GE(marked, 2u);
  EXPECT_EQ(charts.at(0).at("runs").at(2).at("run_id"), "c2");
  expectRendersInChromium(dir, dir / "report" / "history.html", charts);

  // history compare finds the runs by sha and fails like compare on the broken one.
  const SplitResult compare =
      runTessbenchSplit("history compare --db " + db + " bbbb cccc --limit 3");
  EXPECT_EQ(compare.exit_code, 1) << compare.out << compare.err;
  EXPECT_NE(compare.out.find("# Compare bbbb000 2026-01-02 (c1) -> cccc000 2026-01-03 (c2)"),
            std::string::npos)
      << compare.out;
  EXPECT_NE(compare.out.find("FAIL"), std::string::npos) << compare.out;
  EXPECT_EQ(runTessbenchSplit("history compare --db " + db + " aaaa bbbb").exit_code, 0);
  const SplitResult list = runTessbenchSplit("history list --db " + db);
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.out.find("4 runs in"), std::string::npos) << list.out;
}

// Two processes add at once, into a database neither has created yet; each holds the write
// lock 300 ms (history_add_hooked's pause), so they overlap for sure: both land, one after
// the other.
TEST(HistoryConcurrency, TwoAddsAtOnceBothLand) {
  const fs::path dir = testing::scratchDirectory("history_concurrent");
  const std::string a = testing::writeSyntheticRun(dir, {"a", "aaaa0000"});
  const std::string b = testing::writeSyntheticRun(dir, {"b", "bbbb0000"});
  const std::string db = (dir / "h.sqlite").string();
  const std::string add = std::string(testing::historyAddHooked()) + " pause=300 " + db + " ";
  const std::string command = "(" + add + a + " >/dev/null 2>&1; echo $? >" +
                              (dir / "rc_a").string() + ") & (" + add + b +
                              " >/dev/null 2>&1; echo $? >" + (dir / "rc_b").string() + ") & wait";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(readFile(dir / "rc_a"), "0\n");
  EXPECT_EQ(readFile(dir / "rc_b"), "0\n");
  history::HistoryDb history = history::openHistory(db, false);
  EXPECT_EQ(history::listRuns(history).size(), 2u);
}

// Every row of every table, in key order: the database's content.
std::string contentOf(const std::string& path) {
  history::HistoryDb history = history::openHistory(path, false);
  std::string content;
  for (const char* table :
       {"runs", "metrics", "records", "payloads", "measure_results", "timings"}) {
    history::Statement rows =
        history.db->prepare(std::string("SELECT * FROM ") + table + " ORDER BY 1, 2");
    while (rows.step()) {
      for (int c = 0; c < rows.columnCount(); ++c) content += rows.text(c) + "|";
      content += "\n";
    }
  }
  history::Statement check = history.db->prepare("PRAGMA integrity_check");
  EXPECT_TRUE(check.step());
  EXPECT_EQ(check.text(0), "ok");
  return content;
}

TEST(HistoryFaults, AnAddKilledMidwayLeavesTheDatabaseAsItWas) {
  const fs::path dir = testing::scratchDirectory("history_killed");
  const std::string db = (dir / "h.sqlite").string();
  testing::SyntheticRun second{"b", "bbbb0000"};
  second.samples = {0.1, 0.2};
  ASSERT_EQ(runTessbenchSplit("history add --db " + db + " " +
                              testing::writeSyntheticRun(dir, {"a", "aaaa0000"}))
                .exit_code,
            0);
  const std::string before = contentOf(db);
  const std::string folder = testing::writeSyntheticRun(dir, second);
  // SIGKILL inside the add's transaction, once the records are written (history_add_hooked).
  const SplitResult killed =
      testing::runSplit(testing::historyAddHooked(), "kill " + db + " " + folder);
  EXPECT_EQ(killed.exit_code, 128 + SIGKILL)
      << "not killed (the shell's status of a SIGKILL): " << killed.out << killed.err;
  EXPECT_EQ(contentOf(db), before);
  const SplitResult again = runTessbenchSplit("history add --db " + db + " " + folder);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(contentOf(db), before);
}

// Each: exit 2, one line on stderr naming the file or sha, nothing on stdout; the database
// (or the file given as one) unchanged.
TEST(HistoryBadInput, OneLineAndExitTwo) {
  const fs::path dir = testing::scratchDirectory("history_bad");
  const std::string db = (dir / "h.sqlite").string();
  const std::string run = testing::writeSyntheticRun(dir, {"a", "aaaa0000"});
  testing::SyntheticRun other_device{"o", "dddd0000"};
  other_device.device = "another gpu";
  const std::string other = testing::writeSyntheticRun(dir, other_device);
  ASSERT_EQ(runTessbenchSplit("history add --db " + db + " " + run + " " + other).exit_code, 0);
  fs::create_directories(dir / "unfinished.incomplete");
  std::ofstream(dir / "unfinished.incomplete" / "INCOMPLETE") << "";
  const std::string text_file = testing::writeTextFile(dir / "notes.txt", "not a database\n");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"history add --db " + db + " " + (dir / "missing").string(), "missing"},
      {"history add --db " + db + " " + (dir / "unfinished.incomplete").string(), "unfinished"},
      {"history add --db " + db + " " + run, "is already in"},
      {"history compare --db " + db + " aaaa eeee", "eeee"},
      {"history compare --db " + db + " aaaa dddd", "different devices"},
      {"history list --db " + text_file, text_file},
      {"history add --db " + text_file + " " + run, text_file},
      {"history report --db " + (dir / "none.sqlite").string() + " --out " + (dir / "r").string(),
       "none.sqlite"},
      {"history report --db " + db + " --aggregate mean --out " + (dir / "r").string(),
       "--aggregate"},
  };
  const std::string before = contentOf(db);
  for (const auto& [arguments, named] : cases) {
    const SplitResult r = runTessbenchSplit(arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.out << r.err;
    EXPECT_EQ(testing::lineCount(r.err), 1u) << arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << arguments << "\n" << r.err;
    EXPECT_EQ(r.out, "") << arguments;
  }
  EXPECT_EQ(readFile(text_file), "not a database\n");
  EXPECT_EQ(contentOf(db), before);
  EXPECT_FALSE(fs::exists(dir / "none.sqlite"));
}

}  // namespace
}  // namespace tb
