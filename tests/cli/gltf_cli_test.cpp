// Issue 60 end to end: the bundled glTF asset is listed, runs, is advised on and tabled, and
// gives the figures of its OBJ twin in every measure of every triangle technique.
// Oracle: the twin's results (the same mesh written as OBJ `f v/vt/vn`,
// assets/full_suite/gltf/README.md), row for row; the crack rows' edge_kind keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::runTessbenchSplit;
using testing::SplitResult;

constexpr const char* kSeamGlb = "full_suite/gltf/tri_torus_seams";
constexpr const char* kSeamTwin = "full_suite/gltf/tri_torus_seams_twin";

TEST(GltfCli, ListAssetsShowsTheBundledGltfAsset) {
  const SplitResult r = runTessbenchSplit("list assets");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(kSeamGlb), std::string::npos) << r.out;
}

// The one run the tests below read: both assets, the triangle techniques, default measures.
const std::filesystem::path& twinRun() {
  static const std::filesystem::path folder = [] {
    const auto dir = testing::scratchDirectory("gltf_twin_run");
    const SplitResult r = runTessbenchSplit(
        "run --quiet --no-pictures --out " + dir.string() + " --run-id twins --asset " + kSeamGlb +
        " --asset " + kSeamTwin + " --technique pn_triangles --technique phong");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir / "twins";
  }();
  return folder;
}

TEST(GltfCli, TheGlbAndItsObjTwinGiveEqualFiguresInEveryMeasure) {
  const nlohmann::json results =
      nlohmann::json::parse(testing::readFile(twinRun() / "results.json"));
  std::map<std::string, nlohmann::json> glb, twin;  // technique/variant -> measures
  for (const auto& record : results["records"]) {
    const std::string key =
        record["technique"].get<std::string>() + "/" + record["variant"].get<std::string>();
    // isa runs once per technique × variant, on its first input (the glb): not compared.
    nlohmann::json measures = nlohmann::json::array();
    for (const auto& measure : record["measures"]) {
      if (measure["measure"] != "isa") measures.push_back(measure);
    }
    if (record["asset"] == kSeamGlb) glb[key] = measures;
    if (record["asset"] == kSeamTwin) twin[key] = measures;
  }
  ASSERT_GE(glb.size(), 7u) << "pn_triangles' and phong's default variants";
  ASSERT_EQ(glb.size(), twin.size());
  size_t seam_rows = 0;
  for (const auto& [key, measures] : glb) {
    ASSERT_TRUE(twin.count(key)) << key;
    ASSERT_EQ(measures.size(), twin[key].size()) << key;
    for (size_t m = 0; m < measures.size(); ++m) {
      EXPECT_EQ(measures[m].dump(), twin[key][m].dump()) << key << " " << measures[m]["measure"];
      if (measures[m]["measure"] == "cracks") {
        for (const auto& row : testing::rowObjects(measures[m])) {
          seam_rows += row["keys"].value("edge_kind", "") == "seam" ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GT(seam_rows, 0u) << "the crack rows at seams appear";
}

TEST(GltfCli, AdviseAndTableTakeTheGltfAsset) {
  const SplitResult advice =
      runTessbenchSplit("advise " + testing::assetPath("full_suite/gltf/tri_torus_seams.glb") +
                        " --technique pn_triangles --json");
  ASSERT_EQ(advice.exit_code, 0) << advice.err;
  EXPECT_NE(advice.out.find("pn_triangles"), std::string::npos);
  const SplitResult table = runTessbenchSplit("table " + twinRun().string() +
                                              " --measure cracks --format csv --per-asset");
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("tri_torus_seams"), std::string::npos) << table.out;
}

}  // namespace
}  // namespace tb
