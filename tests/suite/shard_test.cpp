// The slicing rule of sharded runs (harness/suite/shard.h).
#include "harness/suite/shard.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/mesh/fnv1a.h"
#include "core/mesh/input_error.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"

namespace tb {
namespace {

// Oracle: the published FNV-1a 64-bit test vectors (Fowler, Noll, Vo).
TEST(Shard, HashIsFnv1a64) {
  EXPECT_EQ(mesh::fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(mesh::fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(mesh::fnv1a64("foobar"), 0x85944171f73967e8ull);
  // A word's low bytes, least significant first, hash as those bytes do.
  EXPECT_EQ(mesh::fnv1aWord(mesh::kFnv1aOffsetBasis, 0x7261626f6f66ull, 6),
            mesh::fnv1a64("foobar"));
}

TEST(Shard, ParsesIndexOfCountFromZero) {
  const suite::ShardSpec shard = suite::parseShard("2/3");
  EXPECT_EQ(shard.index, 2u);
  EXPECT_EQ(shard.count, 3u);
  EXPECT_TRUE(shard.sharded());
  EXPECT_FALSE(suite::parseShard("0/1").sharded());
  for (const char* bad : {"3/3", "0/0", "", "3", "/3", "1/", "a/3", "-1/3", " 1/3", "1/3 ", "1/+3",
                          "1//3", "99999999999999999999999/3"}) {
    EXPECT_THROW(suite::parseShard(bad), mesh::InputError) << bad;
  }
}

// Every work item of the default suite (every registered technique × variant × bundled
// asset × measure, and every technique × asset skip) belongs to exactly one shard.
TEST(Shard, ShardsPartitionTheDefaultWorkList) {
  std::vector<std::vector<std::string>> measure_items;
  std::vector<std::vector<std::string>> skip_items;
  for (const techniques::Technique* technique : techniques::TechniqueRegistry::instance().all()) {
    for (const suite::AssetRef& asset : suite::bundledAssets()) {
      skip_items.push_back({technique->info().id, asset.name});
      for (const techniques::VariantInfo& variant : technique->variants()) {
        for (const measures::Measure* measure : measures::MeasureRegistry::instance().all()) {
          measure_items.push_back(
              {technique->info().id, variant.name, asset.name, measure->info().id});
        }
      }
    }
  }
  ASSERT_GT(measure_items.size(), 1000u);
  for (const size_t count : {size_t(1), size_t(2), size_t(3), size_t(8)}) {
    std::vector<size_t> per_shard(count, 0);
    for (const auto& item : measure_items) {
      size_t owners = 0;
      for (size_t i = 0; i < count; ++i) {
        if (suite::ownsMeasure({i, count}, item[0], item[1], item[2], item[3])) {
          ++owners;
          ++per_shard[i];
        }
      }
      ASSERT_EQ(owners, 1u) << item[0] << "/" << item[1] << "/" << item[2] << "/" << item[3];
    }
    for (const auto& item : skip_items) {
      size_t owners = 0;
      for (size_t i = 0; i < count; ++i) owners += suite::ownsSkip({i, count}, item[0], item[1]);
      ASSERT_EQ(owners, 1u) << item[0] << " " << item[1];
    }
    // Evenly spread by count: every shard within a quarter of the mean (a hash, not a
    // guarantee; thousands of items make a worse spread vanishingly unlikely).
    const double mean = double(measure_items.size()) / double(count);
    for (size_t i = 0; i < count; ++i) {
      EXPECT_NEAR(double(per_shard[i]), mean, 0.25 * mean) << "shard " << i << "/" << count;
    }
  }
}

TEST(Shard, SelectionIsDescribedInRunOrder) {
  suite::SuiteSelection selection;
  selection.techniques = {techniques::TechniqueRegistry::instance().find("phong")};
  selection.measures = {measures::MeasureRegistry::instance().find("memory"),
                        measures::MeasureRegistry::instance().find("error")};
  results::Results results;
  results.assets.push_back({"opensubdiv/catmark_cube", "", 6, 8, "quads", false});
  const results::RunSelection described = suite::describeSelection(selection, results);
  ASSERT_EQ(described.techniques.size(), 1u);
  EXPECT_EQ(described.techniques[0].technique, "phong");
  std::vector<std::string> variants;
  for (const techniques::VariantInfo& v : selection.techniques[0]->variants())
    if (!v.full_suite_only) variants.push_back(v.name);  // the default suite's
  EXPECT_EQ(described.techniques[0].variants, variants);
  EXPECT_EQ(described.assets, (std::vector<std::string>{"opensubdiv/catmark_cube"}));
  EXPECT_EQ(described.measures, (std::vector<std::string>{"memory", "error"}));
  // No techniques or measures named: all of them, in registry order.
  const results::RunSelection all = suite::describeSelection(suite::SuiteSelection{}, results);
  EXPECT_EQ(all.techniques.size(), techniques::TechniqueRegistry::instance().all().size());
  EXPECT_EQ(all.measures.size(), measures::MeasureRegistry::instance().all().size());
}

}  // namespace
}  // namespace tb
