#include <gtest/gtest.h>

#include <filesystem>

#include "harness/results/run_folder.h"
#include "tests/test_support.h"

namespace tb {
namespace {

TEST(RunFolder, ExplicitRunIdIsNeverReused) {
  const auto root = testing::scratchDirectory("run_folder_explicit");
  std::string chosen;
  const std::string path = createRunFolder(root.string(), "baseline", &chosen);
  EXPECT_EQ(chosen, "baseline");
  EXPECT_TRUE(std::filesystem::is_directory(path));
  EXPECT_THROW(createRunFolder(root.string(), "baseline", &chosen), std::runtime_error);
}

TEST(RunFolder, TimestampedRunsGetDistinctFolders) {
  const auto root = testing::scratchDirectory("run_folder_auto");
  std::string first, second;
  const std::string a = createRunFolder(root.string(), "", &first);
  const std::string b = createRunFolder(root.string(), "", &second);
  EXPECT_NE(a, b);
  EXPECT_NE(first, second);
}

TEST(RunFolder, NewRunFolderIsCreatedOnceWithItsParents) {
  const auto root = testing::scratchDirectory("run_folder_new");
  const std::string path = (root / "merged" / "all").string();
  createNewRunFolder(path + "/");
  EXPECT_TRUE(std::filesystem::is_directory(path));
  EXPECT_THROW(createNewRunFolder(path), std::runtime_error);
  EXPECT_THROW(createNewRunFolder(path + "/"), std::runtime_error);
}

TEST(RunFolder, WriteNewFileRefusesToOverwrite) {
  const auto root = testing::scratchDirectory("run_folder_write");
  const std::string path = (root / "results.json").string();
  writeNewFile(path, "{}\n");
  EXPECT_THROW(writeNewFile(path, "other\n"), std::runtime_error);
  std::ifstream file(path);
  std::string contents((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(contents, "{}\n");
}

}  // namespace
}  // namespace tb
