#include <gtest/gtest.h>

#include <algorithm>

#include "harness/measures/suite.h"
#include "tests/test_support.h"

namespace tb {
namespace {

TEST(Suite, PhongMemoryOnOneAssetGivesOneRecordPerMeasuredVariant) {
  SuiteSelection selection;
  selection.assets = {resolveAsset("catmark_cube")};
  selection.measures = {MeasureRegistry::instance().find("memory")};
  Results results;
  runSuite(selection, nullptr, &results);
  ASSERT_EQ(results.assets.size(), 1u);
  EXPECT_EQ(results.assets[0].name, "opensubdiv/catmark_cube");
  size_t phong_records = 0;
  for (const Record& record : results.records) {
    if (record.technique != "phong") continue;
    ++phong_records;
    // memory does not depend on α: measured on the default variant only.
    EXPECT_EQ(record.variant, "alpha0.75");
    ASSERT_EQ(record.measures.size(), 1u);
    EXPECT_EQ(record.measures[0].rows.size(), 4u);
    EXPECT_EQ(record.parameters.at("alpha"), "0.75");
  }
  EXPECT_EQ(phong_records, 1u);
}

TEST(Suite, UnknownAssetIsAnInputError) {
  EXPECT_THROW(resolveAsset("definitely_not_an_asset"), std::exception);
  EXPECT_EQ(resolveAsset("opensubdiv/loop_cube").name, "opensubdiv/loop_cube");
}

TEST(Suite, BundledAssetsAreSortedAndComplete) {
  const auto assets = bundledAssets();
  EXPECT_GE(assets.size(), 27u);  // the 27 OpenSubdiv shapes, plus any added later
  EXPECT_TRUE(std::any_of(assets.begin(), assets.end(),
                          [](const AssetRef& a) { return a.name == "opensubdiv/catmark_cube"; }));
  for (size_t i = 1; i < assets.size(); ++i) EXPECT_LT(assets[i - 1].name, assets[i].name);
}

}  // namespace
}  // namespace tb
