// A figure's device is part of its identity (harness/results/device_identity.h): results.json
// and timings.json name the device and driver, and `compare` refuses two runs measured on
// different devices with one line and exit 2. The control: the same run compared with its
// own copy passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::runTessbenchSplit;
using testing::SplitResult;

TEST(DeviceIdentity, CompareNeverJoinsTheFiguresOfTwoDevices) {
  const fs::path dir = testing::scratchDirectory("device_identity");
  const fs::path run = dir / "out" / "lavapipe";
  ASSERT_EQ(runTessbenchSplit("run --quiet --no-pictures --technique phong --asset catmark_cube "
                              "--measure cracks --out " +
                              (dir / "out").string() + " --run-id lavapipe")
                .exit_code,
            0);
  const auto device =
      nlohmann::json::parse(std::ifstream(run / "results.json"))["context"]["vulkan_device"]
          .get<std::string>();
  const auto timings = nlohmann::json::parse(std::ifstream(run / "timings.json"));
  EXPECT_EQ(timings["device"].get<std::string>(), device) << "timings.json names the device";

  const fs::path copy = dir / "out" / "copy", other = dir / "out" / "other_device";
  fs::copy(run, copy, fs::copy_options::recursive);
  fs::copy(run, other, fs::copy_options::recursive);
  nlohmann::json relabelled = nlohmann::json::parse(std::ifstream(other / "results.json"));
  relabelled["context"]["vulkan_device"] = "NVIDIA H100 (NVIDIA 550.54.15, Vulkan 1.3.277)";
  std::ofstream(other / "results.json") << relabelled.dump(1) << "\n";

  const SplitResult same = runTessbenchSplit("compare " + run.string() + " " + copy.string());
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  const SplitResult joined = runTessbenchSplit("compare " + run.string() + " " + other.string());
  EXPECT_EQ(joined.exit_code, 2) << joined.out << joined.err;
  EXPECT_NE(joined.err.find("never compared"), std::string::npos) << joined.err;
  EXPECT_NE(joined.err.find("NVIDIA H100"), std::string::npos) << joined.err;
}

// `list devices` names the devices by the identity results.json uses; the default one is the
// run's. Without a driver it says so in one line and exits 0 (the control).
TEST(DeviceIdentity, ListDevicesNamesTheRunsDeviceFirst) {
  const SplitResult listed = runTessbenchSplit("list devices --json");
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  const nlohmann::json devices = nlohmann::json::parse(listed.out);
  ASSERT_FALSE(devices.empty()) << "lavapipe at least";
  EXPECT_TRUE(devices[0]["default"].get<bool>());
  const fs::path dir = testing::scratchDirectory("device_identity_list");
  ASSERT_EQ(runTessbenchSplit("run --quiet --no-pictures --technique phong --asset catmark_cube "
                              "--measure instructions --out " +
                              dir.string() + " --run-id r")
                .exit_code,
            0);
  const auto context = nlohmann::json::parse(std::ifstream(dir / "r" / "results.json"))["context"];
  EXPECT_EQ(devices[0]["identity"], context["vulkan_device"]);
  const SplitResult none = runTessbenchSplit(
      "list devices",
      "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
  EXPECT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(none.out.rfind("no Vulkan device: ", 0), 0u) << none.out;
}

}  // namespace
}  // namespace tb
