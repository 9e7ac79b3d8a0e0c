// Acceptance tests of `tessbench compare` on real run folders: it flags an injected
// regression (the `regress` plug-in built broken, tests/cli/regress_plugin.cpp, against the
// same source built as it is) with exit 1, passes two identical runs, never flags timings
// of single samples, and flags timings only when repeated samples differ clearly (the U
// test; the samples are written into timings.json, so no test depends on this machine's
// speed). Runs have no Vulkan device (the plug-in has no GPU program): the GPU rows are
// skipped on both sides and the CPU figures are compared.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "harness/results/results_json.h"
#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::readFile;
using testing::runTessbenchSplit;
using testing::SplitResult;

using testing::kNoVulkanDevice;

// Runs `regress` (from `plugin`) on the Loop cube with the error and cracks measures into
// `<dir>/out/<run_id>`; returns the folder.
std::string runRegress(const fs::path& dir, const char* plugin, const std::string& run_id,
                       int repetitions = 1) {
  const SplitResult r = runTessbenchSplit(
      std::string("--plugin ") + plugin +
          " run --quiet --technique regress --asset loop_cube --measure error --measure cracks "
          "--repetitions " +
          std::to_string(repetitions) + " --out " + (dir / "out").string() + " --run-id " + run_id,
      kNoVulkanDevice);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  return (dir / "out" / run_id).string();
}

SplitResult compare(const std::string& base, const std::string& current,
                    const std::string& options = "") {
  return runTessbenchSplit("compare " + options + " " + base + " " + current);
}

// Rewrites every entry's samples of a run's timings.json (seconds: the first).
void writeSamples(const std::string& run, const std::vector<double>& samples) {
  const fs::path path = fs::path(run) / "timings.json";
  nlohmann::ordered_json timings = nlohmann::ordered_json::parse(readFile(path));
  for (auto& entry : timings.at("measures")) {
    entry["samples"] = samples;
    entry["seconds"] = samples.front();
  }
  fs::remove(path);
  std::ofstream(path) << timings.dump(1) << "\n";
}

TEST(CompareAcceptance, ABrokenTechniqueAgainstTheBaselineFails) {
  const fs::path dir = testing::scratchDirectory("compare_broken");
  const std::string good = runRegress(dir, testing::regressGood(), "good");
  const std::string broken = runRegress(dir, testing::regressBroken(), "broken");
  const SplitResult r = compare(good, broken, "--limit 1000");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("FAIL"), std::string::npos) << r.out;
  // Lower is better for both: the broken build opens cracks on the CPU and leaves the limit.
  EXPECT_NE(r.out.find("| regression | regress/default opensubdiv/loop_cube | cracks | "
                       "backend=cpu_float"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| points_not_equal | 0 |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| regression | regress/default opensubdiv/loop_cube | error | "),
            std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

TEST(CompareAcceptance, TwoIdenticalRunsPass) {
  const fs::path dir = testing::scratchDirectory("compare_identical");
  const std::string first = runRegress(dir, testing::regressGood(), "first");
  const std::string second = runRegress(dir, testing::regressGood(), "second");
  const SplitResult r = compare(first, second);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("0 missing, 0 regressions, 0 changed (no direction), 0 improvements, 0 "
                       "added. PASS."),
            std::string::npos)
      << r.out;
  fs::remove_all(dir);
}

// One sample a side: however far apart, the timings are not tested, and the output says so.
TEST(CompareAcceptance, SingleSampleTimingsAreNeverFlagged) {
  const fs::path dir = testing::scratchDirectory("compare_single");
  const std::string base = runRegress(dir, testing::regressGood(), "base");
  const std::string slow = runRegress(dir, testing::regressGood(), "slow");
  writeSamples(base, {0.01});
  writeSamples(slow, {100.0});
  const SplitResult r = compare(base, slow);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("timings: 2 not tested (fewer than 2 samples per side; run --repetitions "
                       "≥ 2)"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("seconds"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

// Five samples a side (run --repetitions 5, each repeat checked against the first): clearly
// slower samples are a `seconds` regression, exit 1 (p = 2/252 < 0.05, median +100%);
// overlapping ones are not flagged; --no-timings leaves timings out.
TEST(CompareAcceptance, RepeatedTimingsAreFlaggedOnlyWhenClearlySlower) {
  const fs::path dir = testing::scratchDirectory("compare_repeated");
  const std::string base = runRegress(dir, testing::regressGood(), "base", 5);
  const std::string slower = runRegress(dir, testing::regressGood(), "slower", 5);
  const std::string similar = runRegress(dir, testing::regressGood(), "similar", 5);
  const nlohmann::json timings = nlohmann::json::parse(readFile(fs::path(base) / "timings.json"));
  EXPECT_EQ(timings.at("repetitions"), 5);
  EXPECT_EQ(timings.at("measures").at(0).at("samples").size(), 5u);
  for (const results::Record& record : results::readResultsFile(base + "/results.json").records) {
    EXPECT_TRUE(record.warnings.empty()) << record.warnings.front();
  }
  writeSamples(base, {1.0, 1.1, 1.2, 1.3, 1.4});
  writeSamples(slower, {2.0, 2.2, 2.4, 2.6, 2.8});
  writeSamples(similar, {1.05, 1.15, 1.25, 1.35, 1.45});
  const SplitResult flagged = compare(base, slower);
  EXPECT_EQ(flagged.exit_code, 1) << flagged.out << flagged.err;
  EXPECT_NE(flagged.out.find("| regression | regress/default opensubdiv/loop_cube | error | "
                             "timing, 5 vs 5 samples | seconds | 1.2 | 2.4 | +100% | 0.00794 |"),
            std::string::npos)
      << flagged.out;
  const SplitResult overlapping = compare(base, similar);
  EXPECT_EQ(overlapping.exit_code, 0) << overlapping.out << overlapping.err;
  EXPECT_NE(overlapping.out.find("timings: 2 tested"), std::string::npos) << overlapping.out;
  EXPECT_EQ(overlapping.out.find("seconds"), std::string::npos) << overlapping.out;
  const SplitResult off = compare(base, slower, "--no-timings");
  EXPECT_EQ(off.exit_code, 0) << off.out << off.err;
  EXPECT_NE(off.out.find("timings: not compared (--no-timings)"), std::string::npos) << off.out;
  fs::remove_all(dir);
}

// A measure whose repeats differ keeps its first figures and the record says so; the run
// still succeeds (a warning, not a failure).
TEST(Repetitions, ARepeatThatDiffersIsARecordWarning) {
  const fs::path dir = testing::scratchDirectory("repetitions_flaky");
  const std::string run_arguments =
      std::string("--plugin ") + testing::regressGood() +
      " run --quiet --technique regress_flaky --technique regress --asset loop_cube --measure "
      "error --repetitions 2 --out " +
      (dir / "out").string() + " --run-id r";
  const SplitResult r = runTessbenchSplit(run_arguments, kNoVulkanDevice);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const results::Results results =
      results::readResultsFile((dir / "out" / "r" / "results.json").string());
  std::map<std::string, std::vector<std::string>> warnings;
  for (const results::Record& record : results.records)
    warnings[record.technique] = record.warnings;
  EXPECT_EQ(warnings["regress_flaky"],
            std::vector<std::string>{"measure error is not deterministic across repetitions"});
  EXPECT_TRUE(warnings["regress"].empty());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tb
