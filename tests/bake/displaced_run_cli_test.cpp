// `tessbench run --displacement` end to end (issue 17, acceptances 3 and 4): a bundled map
// adds its displaced asset to cracks, error and memory, rows keyed displacement and
// sampling; watertight sampling is bitwise watertight on the CPU twin and on lavapipe where
// naive sampling opens gaps (tri_torus: a triangle tile's hypotenuse crosses texels, so
// each side blends texels of its own tile); the bundled maps equal a fresh bake.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::readFile;
using testing::rowObjects;
using testing::runTessbench;

nlohmann::json onlyResults(const fs::path& out) {
  for (const auto& entry : fs::directory_iterator(out)) {
    std::ifstream file(entry.path() / "results.json");
    return nlohmann::json::parse(file);
  }
  ADD_FAILURE() << "no run folder in " << out;
  return {};
}

TEST(DisplacedRun, BundledMapRunsCracksErrorAndMemoryWithSamplingKeys) {
  const fs::path dir = testing::scratchDirectory("displaced_run");
  const std::string map = testing::assetPath("displacement/pn_triangles_tri_torus.exr");
  const auto r = runTessbench(
      "run --quiet --no-pictures --technique pn_triangles --asset "
      "tessbench/tri_torus --measure cracks error memory --displacement " +
      map + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json results = onlyResults(dir / "out");
  const nlohmann::json* displaced = nullptr;
  for (const nlohmann::json& record : results["records"]) {
    if (record["asset"] == "tessbench/tri_torus+pn_triangles_tri_torus") displaced = &record;
  }
  ASSERT_NE(displaced, nullptr) << "no displaced record";
  EXPECT_EQ((*displaced)["variant"], "pn");
  EXPECT_EQ((*displaced)["parameters"]["displacement"], "pn_triangles_tri_torus.exr");
  size_t naive_gaps = 0, watertight_rows = 0, gpu_rows = 0;
  for (const nlohmann::json& measure : (*displaced)["measures"]) {
    for (const nlohmann::json& row : rowObjects(measure)) {
      ASSERT_EQ(row["keys"]["displacement"], "pn_triangles_tri_torus.exr");
      const std::string sampling = row["keys"]["sampling"];
      ASSERT_TRUE(sampling == "naive" || sampling == "watertight") << sampling;
      if (measure["measure"] == "cracks" && !row.contains("status")) {
        const double not_equal = row["metrics"]["points_not_equal"];
        if (sampling == "watertight") {
          ++watertight_rows;
          EXPECT_EQ(not_equal, 0) << row.dump();
          if (row["keys"]["backend"] == "gpu") {
            ++gpu_rows;
            EXPECT_EQ(row["metrics"]["vs_cpu_float_points_differing"], 0) << row.dump();
          }
        } else if (not_equal > 0) {
          ++naive_gaps;
        }
      }
      if (measure["measure"] == "error") {
        EXPECT_EQ(row["keys"]["reference"], "baked_target");
        EXPECT_GT(row["metrics"]["hausdorff"], 0.0);
        EXPECT_LT(row["metrics"]["hausdorff"], 0.01) << "within 1% of the diagonal";
      }
      if (measure["measure"] == "memory" && row.contains("status")) {
        // The compute path does not displace yet: its rows say so.
        EXPECT_EQ(row["keys"]["path"], "compute") << row.dump();
        EXPECT_EQ(row["status"], "skipped") << row.dump();
      } else if (measure["measure"] == "memory") {
        EXPECT_EQ(row["metrics"]["map_file_bytes"], double(fs::file_size(map)));
        EXPECT_EQ(row["metrics"]["displacement_bytes"], 144.0 * 144 * 2) << "R16 texels";
      }
    }
  }
  EXPECT_GT(watertight_rows, 0u);
  EXPECT_GT(naive_gaps, 0u) << "naive sampling should open gaps on tri_torus";
  std::printf("watertight crack rows %zu (gpu %zu), naive rows with gaps %zu\n", watertight_rows,
              gpu_rows, naive_gaps);
}

TEST(BundledMaps, EqualAFreshBake) {
  // scripts/bake_default_maps.sh's list: bake each again and compare bytes.
  const fs::path dir = testing::scratchDirectory("bundled_maps");
  const char* maps[][3] = {
      {"acc_catmark_torus", "acc", "opensubdiv/catmark_torus"},
      {"gregory_acc_catmark_toroidal_tet", "gregory_acc", "opensubdiv/catmark_toroidal_tet"},
      {"pn_triangles_tri_torus", "pn_triangles", "tessbench/tri_torus"},
      {"phong_tri_torus", "phong", "tessbench/tri_torus"},
  };
  size_t bundled = 0;
  for (const auto& entry : fs::directory_iterator(testing::assetPath("displacement"))) {
    bundled += entry.path().extension() == ".exr";
  }
  EXPECT_EQ(bundled, std::size(maps)) << "scripts/bake_default_maps.sh and this list differ";
  for (const auto& [name, technique, asset] : maps) {
    const std::string out = (dir / (std::string(name) + ".exr")).string();
    const auto r = runTessbench(std::string("bake --technique ") + technique + " --asset " + asset +
                                " --analytic --resolution 16 --pixel-type half --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string bundled_exr =
        testing::assetPath(std::string("displacement/") + name + ".exr");
    EXPECT_EQ(readFile(out), readFile(bundled_exr)) << name << ": run scripts/bake_default_maps.sh";
    EXPECT_EQ(readFile(out + ".json"), readFile(bundled_exr + ".json")) << name;
  }
}

}  // namespace
}  // namespace tb
