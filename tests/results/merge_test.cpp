// mergeShards on hand-made shard results. Oracle: the order the suite writes records in
// (technique, variant, asset as context.selection lists them; measures in selection order),
// written out by hand below.
#include "harness/results/merge.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "harness/results/results_json.h"

namespace tb {
namespace {

// Two techniques (not in id order), two assets, two measures (not in id order).
results::RunSelection selection() {
  return {{{"zeta", {"v0", "v1"}}, {"alpha", {"only"}}}, {"cube", "ball"}, {"memory", "error"}};
}

results::MeasureResult measure(const std::string& id, double value) {
  results::MeasureResult result;
  result.measure = id;
  result.rows.push_back({{{"level", "8"}}, {{"x", value, "ratio"}}});
  return result;
}

results::Record record(const std::string& technique, const std::string& variant,
                       const std::string& asset, std::vector<results::MeasureResult> measures) {
  return {technique, variant, asset, {{"alpha", "0.5"}}, {"a warning"}, std::move(measures)};
}

results::ShardRun shard(size_t index, size_t count, std::vector<results::Record> records,
                        std::vector<results::Skip> skips) {
  results::ShardRun run;
  run.folder = "results/s" + std::to_string(index);
  results::Results& r = run.results;
  r.context.run_id = "s" + std::to_string(index);
  r.context.git_sha = "abc";
  r.context.host = index == 0 ? "node-a" : "node-b";
  r.context.vulkan_device = "llvmpipe";
  r.context.selection = selection();
  r.context.shard = {index, count};
  r.assets = {{"cube", "cube.obj", 6, 8, "quads", false},
              {"ball", "ball.obj", 20, 12, "triangles", true}};
  r.measures = {{"error", "Error", "", {}, {}, {}}, {"memory", "Memory", "", {}, {}, {}}};
  r.records = std::move(records);
  r.skipped = std::move(skips);
  return run;
}

// What the unsharded run would hold, in its order.
std::vector<results::Record> unshardedRecords() {
  return {record("zeta", "v0", "cube", {measure("memory", 1), measure("error", 2)}),
          record("zeta", "v0", "ball", {measure("memory", 3)}),
          record("zeta", "v1", "cube", {measure("error", 4)}),
          record("alpha", "only", "cube", {measure("memory", 5), measure("error", 6)})};
}

std::vector<results::ShardRun> threeShards() {
  return {shard(1, 3,
                {record("zeta", "v1", "cube", {measure("error", 4)}),
                 record("zeta", "v0", "cube", {measure("error", 2)})},
                {{"alpha", "ball", "alpha: no triangles"}}),
          shard(0, 3,
                {record("zeta", "v0", "cube", {measure("memory", 1)}),
                 record("alpha", "only", "cube", {measure("error", 6)})},
                {}),
          shard(2, 3,
                {record("zeta", "v0", "ball", {measure("memory", 3)}),
                 record("alpha", "only", "cube", {measure("memory", 5)})},
                {})};
}

std::string recordsJson(const std::vector<results::Record>& records) {
  results::Results results;
  results.records = records;
  return results::toJson(results)["records"].dump(2);
}

TEST(Merge, RecordsAndMeasuresComeBackInTheUnshardedOrder) {
  const results::Results merged = results::mergeShards(threeShards());
  EXPECT_EQ(recordsJson(merged.records), recordsJson(unshardedRecords()));
  ASSERT_EQ(merged.skipped.size(), 1u);
  EXPECT_EQ(merged.skipped[0].technique, "alpha");
  EXPECT_EQ(merged.assets.size(), 2u);
  EXPECT_EQ(merged.measures.size(), 2u);
  EXPECT_EQ(merged.context.shard.count, 0u);
  ASSERT_EQ(merged.context.merged_from.size(), 3u);
  EXPECT_EQ(merged.context.merged_from[2].run_id, "s2");
  EXPECT_EQ(merged.context.host, "node-a; node-b");
  EXPECT_TRUE(merged.context.date.empty());
}

void expectRefusal(const std::vector<results::ShardRun>& shards, const std::string& rule) {
  try {
    results::mergeShards(shards);
    FAIL() << "merged; expected a refusal: " << rule;
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(rule), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(Merge, RefusesShardsThatDoNotFitTogether) {
  std::vector<results::ShardRun> shards = threeShards();
  expectRefusal({shards[0], shards[1]}, "missing shard 2/3");
  expectRefusal({shards[0], shards[1], shards[2], shards[1]}, "given twice");

  std::vector<results::ShardRun> other_n = threeShards();
  other_n[2].results.context.shard = {2, 4};
  expectRefusal(other_n, "same N");

  std::vector<results::ShardRun> other_build = threeShards();
  other_build[1].results.context.git_sha = "def";
  expectRefusal(other_build, "git sha");

  std::vector<results::ShardRun> other_device = threeShards();
  other_device[1].results.context.vulkan_device = "NVIDIA";
  expectRefusal(other_device, "Vulkan device");

  std::vector<results::ShardRun> other_selection = threeShards();
  other_selection[1].results.context.selection.measures = {"error", "memory"};
  expectRefusal(other_selection, "selection differs");

  std::vector<results::ShardRun> other_suite = threeShards();
  other_suite[2].results.context.selection.suite = "full";
  expectRefusal(other_suite, "selection differs");

  std::vector<results::ShardRun> other_cameras = threeShards();
  other_cameras[1].results.context.selection.camera_paths = {"assets/cameras/dolly.json"};
  expectRefusal(other_cameras, "selection differs");

  std::vector<results::ShardRun> other_assets = threeShards();
  other_assets[1].results.assets[0].faces = 7;
  expectRefusal(other_assets, "assets differ");

  std::vector<results::ShardRun> unsharded = threeShards();
  unsharded[0].results.context.shard = {};
  expectRefusal(unsharded, "not a shard run");
}

TEST(Merge, RefusesRecordsThatDisagree) {
  std::vector<results::ShardRun> twice = threeShards();
  twice[1].results.records.push_back(record("zeta", "v1", "cube", {measure("error", 4)}));
  expectRefusal(twice, "was also measured in results/s0");

  std::vector<results::ShardRun> warnings = threeShards();
  warnings[1].results.records[0].warnings.clear();
  expectRefusal(warnings, "parameters or warnings");

  std::vector<results::ShardRun> skipped_twice = threeShards();
  skipped_twice[2].results.skipped.push_back({"alpha", "ball", "alpha: no triangles"});
  expectRefusal(skipped_twice, "also recorded in");

  std::vector<results::ShardRun> unknown = threeShards();
  unknown[2].results.records.push_back(record("zeta", "v9", "cube", {measure("error", 4)}));
  expectRefusal(unknown, "not in the run's selection");
}

TEST(Merge, ContextRoundTripsThroughResultsJson) {
  const results::Results merged = results::mergeShards(threeShards());
  const results::Results parsed = results::resultsFromJson(results::toJson(merged));
  EXPECT_EQ(parsed.context.selection, selection());
  ASSERT_EQ(parsed.context.merged_from.size(), 3u);
  EXPECT_EQ(parsed.context.merged_from[1].shard, (results::ShardId{1, 3}));
  EXPECT_EQ(results::serializeResults(parsed), results::serializeResults(merged));
  // The suite mode and --camera files round-trip; results written before them read as
  // the default suite with the suite's own paths.
  results::Results full = merged;
  full.context.selection.suite = "full";
  full.context.selection.camera_paths = {"assets/cameras/orbit.json", "my/path.json"};
  EXPECT_EQ(results::resultsFromJson(results::toJson(full)).context.selection,
            full.context.selection);
  auto before_suite = results::toJson(merged);
  before_suite["context"]["selection"].erase("suite");
  EXPECT_EQ(results::resultsFromJson(before_suite).context.selection.suite, "default");
  EXPECT_FALSE(results::toJson(merged)["context"]["selection"].contains("camera_paths"));
  // Results written before sharding (no selection, shard or merged_from) still read.
  auto old = results::toJson(merged);
  old["context"].erase("selection");
  old["context"].erase("merged_from");
  EXPECT_NO_THROW(results::resultsFromJson(old));
}

}  // namespace
}  // namespace tb
