#include "harness/suite/suite.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "harness/results/results_json.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

TEST(Suite, PhongMemoryOnOneAssetGivesOneRecordPerMeasuredVariant) {
  suite::SuiteSelection selection;
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.measures = {measures::MeasureRegistry::instance().find("memory")};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  ASSERT_EQ(results.assets.size(), 1u);
  EXPECT_EQ(results.assets[0].name, "opensubdiv/catmark_cube");
  std::vector<std::string> phong_variants;
  for (const results::Record& record : results.records) {
    if (record.technique != "phong") continue;
    phong_variants.push_back(record.variant);
    ASSERT_EQ(record.measures.size(), 1u);
    EXPECT_EQ(record.measures[0].rows.size(), 8u);  // 4 levels x path tessellator | compute
    EXPECT_EQ(record.parameters.at("alpha"), "0.75");
  }
  // memory does not depend on α: the α variants share the default's patch data and are
  // not measured again; `edge` adds per-edge normals, so it gets its own record.
  EXPECT_EQ(phong_variants, (std::vector<std::string>{"alpha0.75", "edge"}));
}

// Memory follows the patch data: gregory_acc/quads_only refines the pyramid's triangles
// into quads (16 patches instead of 4 triangles + 1 quad) and is measured; the evaluation
// orders share the default's patch data and are not (quads_only: a --suite full variant).
TEST(Suite, VariantsWithTheirOwnPatchDataGetTheirOwnMemoryRecord) {
  suite::SuiteSelection selection;
  selection.suite = measures::SuiteMode::kFull;
  selection.techniques = {techniques::TechniqueRegistry::instance().find("gregory_acc")};
  selection.assets = {suite::resolveAsset("catmark_pyramid")};
  selection.measures = {measures::MeasureRegistry::instance().find("memory")};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  std::map<std::string, double> patches_by_variant;
  for (const results::Record& record : results.records) {
    ASSERT_EQ(record.measures.size(), 1u);
    ASSERT_FALSE(record.measures[0].rows.empty());
    for (const results::Metric& m : record.measures[0].rows[0].metrics) {
      if (m.name == "patches") patches_by_variant[record.variant] = m.value;
    }
  }
  EXPECT_EQ(patches_by_variant,
            (std::map<std::string, double>{{"edge_symmetric", 5}, {"quads_only", 16}}));
}

TEST(Suite, UnknownAssetIsAnInputError) {
  EXPECT_THROW(suite::resolveAsset("definitely_not_an_asset"), std::exception);
  EXPECT_EQ(suite::resolveAsset("opensubdiv/loop_cube").name, "opensubdiv/loop_cube");
}

TEST(Suite, BundledAssetsAreSortedAndComplete) {
  const auto assets = suite::bundledAssets();
  EXPECT_GE(assets.size(), 27u);  // the 27 OpenSubdiv shapes, plus any added later
  EXPECT_TRUE(std::any_of(assets.begin(), assets.end(), [](const suite::AssetRef& a) {
    return a.name == "opensubdiv/catmark_cube";
  }));
  for (size_t i = 1; i < assets.size(); ++i) EXPECT_LT(assets[i - 1].name, assets[i].name);
}

// The default suite leaves the full-suite folder out (assets/full_suite/README.md); the full
// suite and a named asset reach it.
TEST(Suite, FullSuiteAssetsRunOnlyInTheFullSuiteOrWhenNamed) {
  auto names = [](const std::vector<suite::AssetRef>& assets) {
    std::vector<std::string> out;
    for (const suite::AssetRef& asset : assets) out.push_back(asset.name);
    return out;
  };
  std::vector<std::string> all = names(suite::bundledAssets());
  for (const std::string& name : names(suite::productionAssets())) all.push_back(name);
  const std::vector<std::string> full = names(suite::suiteAssets(true));
  const std::vector<std::string> fast = names(suite::suiteAssets(false));
  EXPECT_EQ(full, all);
  ASSERT_NE(std::find(all.begin(), all.end(), "full_suite/pole64"), all.end());
  EXPECT_EQ(std::find(fast.begin(), fast.end(), "full_suite/pole64"), fast.end());
  const auto in_full_folder = std::count_if(all.begin(), all.end(), [](const std::string& name) {
    return name.rfind("full_suite/", 0) == 0;
  });
  // pole64, the glTF seams pair and the character's cage (assets/full_suite/README.md)
  EXPECT_EQ(in_full_folder, 4);
  EXPECT_EQ(fast.size() + size_t(in_full_folder) + suite::productionAssets().size(), all.size());
  EXPECT_EQ(suite::resolveAsset("pole64").name, "full_suite/pole64");
}

// A variant marked full_suite_only (osd_adaptive's iso4_gregory) runs in --suite full only.
TEST(Suite, FullSuiteOnlyVariantsRunOnlyInTheFullSuite) {
  const auto variants_run = [](measures::SuiteMode mode) {
    suite::SuiteSelection selection;
    selection.techniques = {techniques::TechniqueRegistry::instance().find("osd_adaptive")};
    selection.assets = {suite::resolveAsset("catmark_cube")};
    selection.measures = {measures::MeasureRegistry::instance().find("memory")};
    selection.suite = mode;
    results::Results results;
    suite::runSuite(selection, nullptr, &results);
    std::set<std::string> names;
    for (const results::Record& record : results.records) names.insert(record.variant);
    return names;
  };
  const std::set<std::string> fast = variants_run(measures::SuiteMode::kDefault);
  const std::set<std::string> full = variants_run(measures::SuiteMode::kFull);
  EXPECT_EQ(fast, (std::set<std::string>{"iso2_gregory"}));
  EXPECT_TRUE(full.count("iso2_gregory") && full.count("iso4_gregory") &&
              full.count("iso2_bspline"))
      << full.size();
}

// Oracle: the same run from a copy of the assets in another folder. Results name bundled
// assets relative to the assets folder (skip reasons and warnings included), so two
// checkouts, or two shards on two machines, give the same JSON.
TEST(Suite, ResultsDoNotDependOnWhereTheAssetsFolderIs) {
  const auto run = [] {
    suite::SuiteSelection selection;
    // catmark_smoothtris0 is skipped by gregory_acc with a reason that names the file.
    selection.assets = {suite::resolveAsset("catmark_smoothtris0"),
                        suite::resolveAsset("catmark_cube")};
    selection.measures = {measures::MeasureRegistry::instance().find("memory")};
    results::Results results;
    suite::runSuite(selection, nullptr, &results);
    return results::serializeResults(results);
  };
  const std::string here = run();
  const std::filesystem::path copy = testing::scratchDirectory("assets_copy");
  std::filesystem::create_directories(copy / "opensubdiv");
  for (const char* name : {"catmark_smoothtris0.obj", "catmark_cube.obj"}) {
    std::filesystem::copy_file(testing::assetPath(std::string("opensubdiv/") + name),
                               copy / "opensubdiv" / name);
  }
  // The bundled scenarios too: simulation techniques run on them by default (the
  // mass_spring ones with the bundled pawn as their skin).
  std::filesystem::copy(testing::assetPath("scenarios"), copy / "scenarios");
  std::filesystem::copy_file(testing::assetPath("opensubdiv/catmark_pawn.obj"),
                             copy / "opensubdiv" / "catmark_pawn.obj");
  ::setenv("TB_ASSETS_DIR", copy.c_str(), 1);
  const std::string there = run();
  ::unsetenv("TB_ASSETS_DIR");
  std::filesystem::remove_all(copy);
  EXPECT_NE(here.find("assets/opensubdiv/catmark_smoothtris0.obj"), std::string::npos);
  EXPECT_EQ(here.find(TB_SOURCE_DIR), std::string::npos);
  EXPECT_TRUE(here == there) << "results depend on the assets folder's location";
}

}  // namespace
}  // namespace tb
