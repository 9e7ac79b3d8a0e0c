// `tessbench compare` for the runs people make: a run of one technique on two assets
// against the committed default baseline (results/baseline/). Oracle: the baseline's own
// figures; an injected regression is a figure of the new run made worse by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::runTessbenchSplit;
using testing::SplitResult;

std::string baseline() { return std::string(TB_SOURCE_DIR) + "/results/baseline"; }

// phong on two assets, the error and memory measures (CPU only).
std::string runPhong(const fs::path& dir, const std::string& run_id) {
  const SplitResult r = runTessbenchSplit(
      "run --quiet --no-pictures --technique phong --asset catmark_cube --asset loop_cube "
      "--measure error --measure memory --out " +
      dir.string() + " --run-id " + run_id);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  return (dir / run_id).string();
}

// Doubles phong/alpha0.75's first hausdorff figure on the Loop cube (lower is better).
void injectRegression(const std::string& run) {
  const std::string file = run + "/results.json";
  results::Results results = results::readResultsFile(file);
  bool done = false;
  for (results::Record& record : results.records) {
    if (done || record.variant != "alpha0.75" || record.asset != "opensubdiv/loop_cube") continue;
    for (results::MeasureResult& measure : record.measures) {
      for (results::MetricRow& row : measure.rows) {
        for (results::Metric& metric : row.metrics) {
          if (!done && metric.name == "hausdorff") {
            metric.value *= 2;
            done = true;
          }
        }
      }
    }
  }
  ASSERT_TRUE(done);
  fs::remove(file);
  results::writeNewFile(file, results::serializeResults(results));
}

TEST(CompareFilters, OneTechniqueOnTwoAssetsAgainstTheBaseline) {
  const fs::path dir = testing::scratchDirectory("compare_filters");
  const std::string mine = runPhong(dir, "mine");
  // Every other record of the baseline is missing: listed, not failed under --only-common.
  const SplitResult common = runTessbenchSplit("compare --only-common " + baseline() + " " + mine);
  EXPECT_EQ(common.exit_code, 0) << common.out << common.err;
  EXPECT_NE(common.out.find("0 regressions"), std::string::npos) << common.out;
  EXPECT_NE(common.out.find("PASS (--only-common"), std::string::npos) << common.out;
  EXPECT_NE(common.out.find("| missing | acc/default"), std::string::npos) << common.out;
  const SplitResult typo = runTessbenchSplit("compare --technique phogn " + mine + " " + mine);
  EXPECT_EQ(typo.exit_code, 2) << typo.out << typo.err;
  EXPECT_NE(typo.err.find("--technique phogn"), std::string::npos) << typo.err;

  const std::string clean = (dir / "clean").string();
  fs::copy(mine, clean, fs::copy_options::recursive);
  injectRegression(mine);
  const SplitResult regressed =
      runTessbenchSplit("compare --only-common --json " + baseline() + " " + mine);
  EXPECT_EQ(regressed.exit_code, 1) << regressed.out << regressed.err;
  const nlohmann::json document = nlohmann::json::parse(regressed.out);
  EXPECT_TRUE(document.at("failed").get<bool>());
  EXPECT_TRUE(document.at("only_common").get<bool>());
  EXPECT_EQ(document.at("counts").at("regression"), 1);
  EXPECT_GT(document.at("counts").at("missing").get<int>(), 400);
  nlohmann::json worst;  // the first regression: missing figures come first, worst first
  for (const auto& change : document.at("changes")) {
    if (change.at("kind") == "regression" && worst.is_null()) worst = change;
  }
  ASSERT_FALSE(worst.is_null()) << regressed.out;
  EXPECT_EQ(worst.at("kind"), "regression");
  EXPECT_EQ(worst.at("record"), "phong/alpha0.75 opensubdiv/loop_cube");
  EXPECT_EQ(worst.at("metric"), "hausdorff");
  EXPECT_DOUBLE_EQ(worst.at("new").get<double>(), 2 * worst.at("base").get<double>());
  EXPECT_NEAR(worst.at("relative_change").get<double>(), 0.5, 1e-12);
  EXPECT_TRUE(worst.at("p_value").is_null());
  // The filters keep one asset's error figures: the regression, nothing missing.
  const SplitResult filtered = runTessbenchSplit(
      "compare --technique phong --asset loop_cube --measure error " + clean + " " + mine);
  EXPECT_EQ(filtered.exit_code, 1) << filtered.out << filtered.err;
  EXPECT_NE(filtered.out.find(" 0 missing, 1 regressions"), std::string::npos) << filtered.out;
  EXPECT_EQ(filtered.out.find("catmark_cube"), std::string::npos) << filtered.out;
  EXPECT_EQ(filtered.out.find("| memory |"), std::string::npos) << filtered.out;
  fs::remove_all(dir);
}

// --all-timings lists every timing tested, flagged or not, with both medians and p.
TEST(CompareFilters, EveryTimingIsListedOnRequest) {
  const fs::path dir = testing::scratchDirectory("compare_all_timings");
  const SplitResult run = runTessbenchSplit(
      "run --quiet --no-pictures --technique phong --asset catmark_cube --measure memory "
      "--repetitions 3 --out " +
      dir.string() + " --run-id t");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string t = (dir / "t").string();
  const SplitResult r = runTessbenchSplit("compare --all-timings " + t + " " + t);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("## Timings"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| same | phong/alpha0.75 opensubdiv/catmark_cube | memory | 3 vs 3 |"),
            std::string::npos)
      << r.out;
  const nlohmann::json json =
      nlohmann::json::parse(runTessbenchSplit("compare --json " + t + " " + t).out);
  EXPECT_EQ(json.at("timings").size(), json.at("timings_tested").get<size_t>());
  EXPECT_EQ(json.at("timings").at(0).at("p_value"), 1.0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tb
