// `run --technique ID/VARIANT`: one variant of a technique measured as the whole technique's
// run measures it. Oracle: the same run with every variant (`--technique acc`).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.h"

namespace tb {
namespace {

using testing::CommandResult;
using testing::readFile;
using testing::runTessbench;

// Per variant, its measures' JSON (results.json's records of one technique and asset).
std::map<std::string, nlohmann::json> measuresByVariant(const std::filesystem::path& run) {
  const auto json = nlohmann::json::parse(readFile(run / "results.json"));
  std::map<std::string, nlohmann::json> out;
  for (const auto& record : json["records"]) {
    out[record["variant"].get<std::string>()] = record["measures"];
  }
  return out;
}

constexpr const char* kRun =
    "run --quiet --no-pictures --asset opensubdiv/catmark_cube --measure cracks memory error ";

TEST(VariantSelection, OneVariantGetsTheMeasuresAndFiguresOfTheWholeRun) {
  const auto dir = testing::scratchDirectory("cli_variant_select");
  const CommandResult all =
      runTessbench(std::string(kRun) + "--technique acc --run-id all --out " + dir.string());
  ASSERT_EQ(all.exit_code, 0) << all.output;
  // no_tangent has its own patch data (error runs on it), asymmetric only another float order.
  const CommandResult some = runTessbench(std::string(kRun) +
                                          "--technique acc/no_tangent acc/asymmetric "
                                          "--run-id some --out " +
                                          dir.string());
  ASSERT_EQ(some.exit_code, 0) << some.output;
  const auto whole = measuresByVariant(dir / "all");
  const auto chosen = measuresByVariant(dir / "some");
  ASSERT_EQ(whole.size(), 6u);
  ASSERT_EQ(chosen.size(), 2u);
  for (const auto& [variant, measures] : chosen) {
    ASSERT_TRUE(whole.contains(variant)) << variant;
    EXPECT_EQ(measures, whole.at(variant)) << variant;
  }
  EXPECT_EQ(chosen.at("no_tangent").size(), 2u);  // cracks, error
  EXPECT_EQ(chosen.at("asymmetric").size(), 1u);  // cracks
}

TEST(VariantSelection, TheWholeTechniqueAndOneOfItsVariantsRunEveryVariant) {
  const auto dir = testing::scratchDirectory("cli_variant_whole");
  const CommandResult r = runTessbench(
      "run --quiet --no-pictures --asset opensubdiv/catmark_cube --measure cracks "
      "--technique acc/default acc --run-id w --out " +
      dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(measuresByVariant(dir / "w").size(), 6u);
}

TEST(VariantSelection, AnUnknownVariantIsOneLineNamingTheKnownOnes) {
  const CommandResult r = runTessbench("run --quiet --technique acc/nope --out /nonexistent");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find("acc/nope: unknown variant of acc (known: default,"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace tb
