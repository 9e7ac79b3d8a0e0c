// End-to-end tests of `run --camera` and `run --suite`: bad values are one line and exit 2
// with no run folder; good ones are recorded in results.json's context.selection, where
// `merge` holds shards to them.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::CommandResult;
using testing::lineCount;
using testing::readFile;
using testing::runTessbench;
namespace fs = std::filesystem;

// A cheap selection: one technique, one asset, the memory measure.
const std::string kCheap = "--quiet --technique phong --asset catmark_cube --measure memory";

TEST(CameraCli, ABadCameraFileIsOneLineNamingTheFileAndTheFieldWithNoRunFolder) {
  const fs::path dir = testing::scratchDirectory("camera_cli_bad");
  const std::string path = testing::writeTextFile(
      dir / "bad.json",
      R"({"fov_y_deg": 45, "frames": 4, "space": "bounds", "near": 0.01, "far": 10,
          "keyframes": [{"eye": [2, 0, 0], "target": [0, 0, 0], "up": [0, 0, 0]}]})");
  const CommandResult r =
      runTessbench("run " + kCheap + " --camera " + path + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(path + ": keyframes[0].up: zero-length vector"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "out")) << "a failed run must leave no folder";

  const CommandResult unknown =
      runTessbench("run " + kCheap + " --camera no_such_path --out " + (dir / "out").string());
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(lineCount(unknown.output), 1u) << unknown.output;
  EXPECT_NE(unknown.output.find("no_such_path: no such file, and not a bundled camera path"),
            std::string::npos)
      << unknown.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CameraCli, AnUnknownSuiteIsOneLineAndExit2) {
  const fs::path dir = testing::scratchDirectory("camera_cli_suite");
  const CommandResult r =
      runTessbench("run " + kCheap + " --suite bogus --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("--suite: bogus: unknown suite (known: default, full)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CameraCli, TheSuiteAndTheCameraFilesAreRecordedAndShardsMustAgreeOnThem) {
  const fs::path dir = testing::scratchDirectory("camera_cli_selection");
  const std::string out = " --out " + dir.string();
  CommandResult r = runTessbench("run " + kCheap + " --run-id plain" + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto selection =
      nlohmann::json::parse(readFile(dir / "plain" / "results.json"))["context"]["selection"];
  EXPECT_EQ(selection["suite"], "default");
  EXPECT_FALSE(selection.contains("camera_paths"));

  const std::string file = testing::assetPath("cameras/flyby.json");
  r = runTessbench("run " + kCheap + " --suite full --camera dolly --camera " + file +
                   " --run-id chosen" + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  selection =
      nlohmann::json::parse(readFile(dir / "chosen" / "results.json"))["context"]["selection"];
  EXPECT_EQ(selection["suite"], "full");
  EXPECT_EQ(selection["camera_paths"], nlohmann::json({"assets/cameras/dolly.json", file}));

  // Two shards of one selection but different suites do not merge.
  r = runTessbench("run " + kCheap + " --shard 0/2 --run-id s0" + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = runTessbench("run " + kCheap + " --shard 1/2 --suite full --run-id s1" + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = runTessbench("merge " + (dir / "s0").string() + " " + (dir / "s1").string() + " --out " +
                   (dir / "merged").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("selection differs"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "merged"));
}

}  // namespace
}  // namespace tb
