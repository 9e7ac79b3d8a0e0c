// End-to-end tests of sharded runs (`run --shard I/N`) and `merge`. Oracle: the unsharded
// run of the same selection, whose assets, records, skipped and measures sections the
// merged results.json must repeat byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::CommandResult;
using testing::lineCount;
using testing::readFile;
using testing::runTessbench;
namespace fs = std::filesystem;

// results.json from its "assets" section to the end: assets, records, skipped and measures,
// as written (the context before them legitimately differs between runs).
std::string sectionsAfterContext(const fs::path& run) {
  const std::string text = readFile(run / "results.json");
  const size_t assets = text.find("\n  \"assets\": [");
  return assets == std::string::npos ? std::string() : text.substr(assets);
}

std::string runId(int shard) {
  std::string id = "s";
  id += std::to_string(shard);
  return id;
}

void runOk(const std::string& arguments) {
  const CommandResult r = runTessbench(arguments);
  ASSERT_EQ(r.exit_code, 0) << arguments << "\n" << r.output;
}

// A quad and a triangle asset (acc cannot take the triangles: a skip), three measures
// given out of id order (records list measures in selection order, declarations by id).
const char* kSelection =
    "--technique phong --technique acc --asset catmark_cube --asset loop_cube "
    "--measure memory --measure error --measure instructions";

TEST(ShardCli, ThreeShardsMergeIntoTheUnshardedRunByteForByte) {
  const fs::path dir = testing::scratchDirectory("shard_three");
  const std::string out = " --quiet --out " + dir.string();
  runOk(std::string("run ") + kSelection + out + " --run-id full");
  for (int i = 0; i < 3; ++i) {
    runOk(std::string("run ") + kSelection + " --shard " + std::to_string(i) + "/3" + out +
          " --run-id " + runId(i));
  }
  // The shards partition the measures: none holds them all, together they hold each once,
  // and some record is split over several shards.
  const auto full = nlohmann::json::parse(readFile(dir / "full" / "results.json"));
  size_t full_measures = 0;
  for (const auto& record : full["records"]) full_measures += record["measures"].size();
  size_t shard_measures = 0, shard_skips = 0;
  std::map<std::string, std::set<int>> shards_of_record;
  for (int i = 0; i < 3; ++i) {
    const auto shard = nlohmann::json::parse(readFile(dir / runId(i) / "results.json"));
    EXPECT_EQ(shard["context"]["shard"]["index"], i);
    EXPECT_EQ(shard["context"]["shard"]["count"], 3);
    size_t measures = 0;
    for (const auto& record : shard["records"]) {
      measures += record["measures"].size();
      shards_of_record[record["technique"].get<std::string>() + "/" +
                       record["variant"].get<std::string>() + " " +
                       record["asset"].get<std::string>()]
          .insert(i);
    }
    EXPECT_LT(measures, full_measures) << "shard " << i << " ran everything";
    shard_measures += measures;
    shard_skips += shard["skipped"].size();
  }
  EXPECT_EQ(shard_measures, full_measures);
  ASSERT_EQ(full["skipped"].size(), 1u);  // acc on loop_cube
  EXPECT_EQ(shard_skips, 1u);
  size_t split = 0;
  for (const auto& [record, shards] : shards_of_record) split += shards.size() > 1;
  EXPECT_GT(split, 0u) << "no record was split; the test would not exercise re-assembly";

  // Shards given in any order.
  const CommandResult merged =
      runTessbench("merge " + (dir / "s2").string() + " " + (dir / "s0").string() + " " +
                   (dir / "s1").string() + " --out " + (dir / "merged").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.output;
  const std::string expected = sectionsAfterContext(dir / "full");
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(sectionsAfterContext(dir / "merged"), expected);

  const auto context = nlohmann::json::parse(readFile(dir / "merged" / "results.json"))["context"];
  EXPECT_FALSE(context.contains("shard"));
  ASSERT_EQ(context["merged_from"].size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(context["merged_from"][i]["run_id"].get<std::string>(), runId(i));
  }
  EXPECT_EQ(context["run_id"], "merged");
  EXPECT_EQ(context["selection"], full["context"]["selection"]);
  const std::string report = readFile(dir / "merged" / "report.md");
  EXPECT_NE(report.find("merged from shard 2/3"), std::string::npos);
  EXPECT_NE(report.find("### error\n"), std::string::npos);
  // The merged run's detail and charts: every row as CSV, and report.html.
  EXPECT_TRUE(fs::exists(dir / "merged" / "tables" / "error.csv"));
  EXPECT_NE(readFile(dir / "merged" / "report.html").find("<canvas"), std::string::npos);
}

TEST(ShardCli, OneShardMergesIntoTheUnshardedRun) {
  const fs::path dir = testing::scratchDirectory("shard_one");
  const std::string selection =
      "--technique phong --asset catmark_cube --measure instructions --measure memory";
  const std::string out = " --quiet --out " + dir.string();
  runOk("run " + selection + out + " --run-id full");
  runOk("run " + selection + " --shard 0/1" + out + " --run-id s0");
  EXPECT_EQ(sectionsAfterContext(dir / "s0"), sectionsAfterContext(dir / "full"));
  runOk("merge --quiet " + (dir / "s0").string() + " --out " + (dir / "merged").string());
  EXPECT_EQ(sectionsAfterContext(dir / "merged"), sectionsAfterContext(dir / "full"));
}

TEST(ShardCli, BadShardValuesAreOneLineErrors) {
  const fs::path dir = testing::scratchDirectory("shard_bad");
  for (const char* value : {"3/3", "4/3", "0/0", "1", "x/3", "-1/3", "1/3x", "1/-3", "/3"}) {
    const CommandResult r = runTessbench(
        "run --quiet --technique phong --asset catmark_cube --measure memory "
        "--shard " +
        std::string(value) + " --out " + (dir / "out").string());
    EXPECT_NE(r.exit_code, 0) << value;
    EXPECT_EQ(lineCount(r.output), 1u) << r.output;
    EXPECT_NE(r.output.find("--shard"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out")) << value;
  }
}

// Each refusal is one line naming the rule, a non-zero exit, and no merged folder.
void expectRefused(const std::string& folders, const fs::path& out, const std::string& rule) {
  const CommandResult r = runTessbench("merge " + folders + " --out " + out.string());
  EXPECT_NE(r.exit_code, 0) << folders;
  EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(rule), std::string::npos) << r.output;
}

TEST(ShardCli, MergeRefusesShardsThatDoNotFitTogether) {
  const fs::path dir = testing::scratchDirectory("shard_refuse");
  const std::string memory = "run --quiet --technique phong --asset catmark_cube --measure memory";
  const std::string out = " --out " + dir.string();
  runOk(memory + " --shard 0/2" + out + " --run-id a0");
  runOk(memory + " --shard 1/2" + out + " --run-id a1");
  runOk(memory + " --shard 0/3" + out + " --run-id b0");
  runOk(memory + out + " --run-id whole");
  runOk("run --quiet --technique phong --asset catmark_cube --measure instructions --shard 1/2" +
        out + " --run-id other1");
  // a1 as if built from another commit.
  fs::create_directories(dir / "sha1");
  auto json = nlohmann::ordered_json::parse(readFile(dir / "a1" / "results.json"));
  json["context"]["git_sha"] = "0000000000000000000000000000000000000000";
  testing::writeTextFile(dir / "sha1" / "results.json", json.dump(2) + "\n");
  fs::create_directories(dir / "empty");

  const std::string a0 = (dir / "a0").string(), a1 = (dir / "a1").string();
  const fs::path merged = dir / "merged";
  expectRefused(a0, merged, "missing shard 1/2");
  expectRefused(a0 + " " + a0 + " " + a1, merged, "given twice");
  expectRefused(a0 + " " + a1 + " " + (dir / "b0").string(), merged, "same N");
  expectRefused(a0 + " " + (dir / "other1").string(), merged, "selection differs");
  expectRefused(a0 + " " + (dir / "sha1").string(), merged, "git sha");
  expectRefused(a0 + " " + (dir / "empty").string(), merged, "no results.json");
  expectRefused((dir / "whole").string(), merged, "not a shard run");
  EXPECT_FALSE(fs::exists(merged)) << "a refused merge must leave no folder";

  // An existing folder is never overwritten, as with `run --run-id`.
  runOk("merge --quiet " + a0 + " " + a1 + " --out " + merged.string());
  const std::string first = readFile(merged / "results.json");
  expectRefused(a1 + " " + a0, merged, "already exists");
  EXPECT_EQ(readFile(merged / "results.json"), first);
}

}  // namespace
}  // namespace tb
