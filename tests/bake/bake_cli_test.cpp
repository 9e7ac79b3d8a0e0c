// `tessbench bake` end to end: a small analytic bake writes the map, its sidecar and the
// target OBJ; every bad input is one line, exit 2, and nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::CommandResult;
using testing::runTessbench;

TEST(BakeCli, AnalyticBakeWritesMapSidecarAndTarget) {
  const auto dir = testing::scratchDirectory("bake_cli_ok");
  const std::string out = (dir / "torus.exr").string(), obj = (dir / "target.obj").string();
  const CommandResult first = runTessbench(
      "bake --technique acc --asset opensubdiv/catmark_torus --analytic --resolution 4 "
      "--target-rate 8 --out " +
      out + " --write-target " + obj);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  ASSERT_TRUE(std::filesystem::exists(out));
  ASSERT_TRUE(std::filesystem::exists(obj));
  std::ifstream file(out + ".json");
  const nlohmann::json sidecar = nlohmann::json::parse(file);
  EXPECT_EQ(sidecar["technique"], "acc");
  EXPECT_EQ(sidecar["kind"], "scalar");
  EXPECT_EQ(sidecar["layout"], "tiles");
  EXPECT_EQ(sidecar["resolution"], 4);
  EXPECT_EQ(sidecar["tiles"]["tile_size"], 6);
  EXPECT_EQ(sidecar["rays_missed"], 0);
  EXPECT_NE(sidecar["target"].get<std::string>().find("analytic: h(p) = "), std::string::npos);
  EXPECT_LT(sidecar["displacement"]["min"][0].get<double>(), 0);
  EXPECT_GT(sidecar["displacement"]["max"][0].get<double>(), 0);

  // The written target, baked as an OBJ target, gives the same kind of map.
  const std::string vector_out = (dir / "vector.exr").string();
  const CommandResult second = runTessbench(
      "bake --technique acc --asset opensubdiv/catmark_torus --kind vector --resolution 4 "
      "--target " +
      obj + " --out " + vector_out);
  ASSERT_EQ(second.exit_code, 0) << second.output;
  std::ifstream vector_file(vector_out + ".json");
  const nlohmann::json vector_sidecar = nlohmann::json::parse(vector_file);
  EXPECT_EQ(vector_sidecar["kind"], "vector");
  EXPECT_EQ(vector_sidecar["target"], obj);
  EXPECT_EQ(vector_sidecar["displacement"]["min"].size(), 3u);
  std::filesystem::remove_all(dir);
}

struct BadCase {
  const char* name;
  std::string arguments;  // after `bake ... --out OUT`
};

TEST(BakeCli, BadInputIsOneLineExitTwoAndWritesNothing) {
  const auto dir = testing::scratchDirectory("bake_cli_bad");
  const std::string bad_obj = testing::writeTextFile(dir / "bad.obj", "v 0 0 0\nf 1 2 3\n");
  const std::string ok = "--technique acc --asset opensubdiv/catmark_torus ";
  const BadCase cases[] = {
      {"unknown technique", "--technique nope --asset opensubdiv/catmark_torus --analytic"},
      {"unknown variant", ok + "--variant nope --analytic"},
      {"unknown asset", "--technique acc --asset no_such_asset --analytic"},
      {"neither target", ok},
      {"both targets", ok + "--analytic --target " + bad_obj},
      {"bad target obj", ok + "--target " + bad_obj},
      {"missing target obj", ok + "--target " + (dir / "missing.obj").string()},
      {"resolution 0", ok + "--analytic --resolution 0"},
      {"resolution absurd", ok + "--analytic --resolution 5000"},
      {"unknown kind", ok + "--analytic --kind normal"},
      {"uv layout", ok + "--analytic --layout uv"},
      {"write-target without analytic", ok + "--target " + bad_obj + " --write-target x.obj"},
      {"technique refuses asset", "--technique acc --asset tessbench/tri_torus --analytic"},
  };
  for (const BadCase& c : cases) {
    const std::string out = (dir / "out.exr").string();
    const CommandResult result = runTessbench("bake " + c.arguments + " --out " + out);
    EXPECT_EQ(result.exit_code, 2) << c.name << ": " << result.output;
    EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1)
        << c.name << ": " << result.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
    EXPECT_FALSE(std::filesystem::exists(out + ".json")) << c.name;
  }
  std::filesystem::remove_all(dir);
}

TEST(BakeCli, NeverOverwritesAnExistingOut) {
  const auto dir = testing::scratchDirectory("bake_cli_exists");
  const std::string out = testing::writeTextFile(dir / "taken.exr", "keep me");
  const CommandResult result = runTessbench(
      "bake --technique acc --asset opensubdiv/catmark_torus --analytic --resolution 2 --out " +
      out);
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("exists already"), std::string::npos) << result.output;
  std::ifstream file(out);
  std::string text;
  std::getline(file, text);
  EXPECT_EQ(text, "keep me");
  EXPECT_FALSE(std::filesystem::exists(out + ".json"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tb
