#include "harness/results/run_folder.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <functional>

#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// While it runs, a run lives in `<id>.incomplete` with its marker and journal; finish()
// leaves exactly the files written, under `<id>`.
TEST(RunFolder, PendingFolderIsRenamedIntoPlaceWhenFinished) {
  const auto root = testing::scratchDirectory("run_folder_finish");
  results::PendingRunFolder folder = results::PendingRunFolder::forRun(root.string(), "baseline");
  EXPECT_EQ(folder.runId(), "baseline");
  EXPECT_EQ(folder.pendingPath(), (root / "baseline.incomplete").string());
  EXPECT_TRUE(fs::is_regular_file(root / "baseline.incomplete" / results::kIncompleteMarker));
  EXPECT_FALSE(fs::exists(root / "baseline"));
  folder.journal(R"({"technique":"acc"})");
  folder.writeFile("results.json", "{}\n");
  EXPECT_EQ(folder.finish(), (root / "baseline").string());
  EXPECT_FALSE(fs::exists(root / "baseline.incomplete"));
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(root / "baseline")) {
    files.push_back(entry.path().filename().string());
  }
  EXPECT_EQ(files, std::vector<std::string>{"results.json"});
  EXPECT_NO_THROW(results::requireFinishedRunFolder((root / "baseline").string()));
}

TEST(RunFolder, ExplicitRunIdIsNeverReusedFinishedOrNot) {
  const auto root = testing::scratchDirectory("run_folder_explicit");
  results::PendingRunFolder::forRun(root.string(), "baseline").finish();
  EXPECT_NE(errorOf([&] {
              results::PendingRunFolder::forRun(root.string(), "baseline");
            }).find("run folder already exists"),
            std::string::npos);
  results::PendingRunFolder running = results::PendingRunFolder::forRun(root.string(), "running");
  EXPECT_THROW(results::PendingRunFolder::forRun(root.string(), "running"), std::runtime_error);
}

TEST(RunFolder, TimestampedRunsGetDistinctFolders) {
  const auto root = testing::scratchDirectory("run_folder_auto");
  results::PendingRunFolder a = results::PendingRunFolder::forRun(root.string(), "");
  results::PendingRunFolder b = results::PendingRunFolder::forRun(root.string(), "");
  EXPECT_NE(a.runId(), b.runId());
  EXPECT_NE(a.finish(), b.finish());
}

// A run that fails (bad input, an error) removes its folder, and the results root when it
// made it; an earlier run's folder is untouched.
TEST(RunFolder, AbandonedRunLeavesNothingBehind) {
  const auto root = testing::scratchDirectory("run_folder_abandon");
  {
    results::PendingRunFolder folder =
        results::PendingRunFolder::forRun((root / "new" / "results").string(), "r");
    folder.journal("{}");
  }
  EXPECT_TRUE(fs::is_empty(root)) << "the run's folder and the parents it made are gone";
  results::PendingRunFolder::forRun(root.string(), "kept").finish();
  { results::PendingRunFolder failed = results::PendingRunFolder::forRun(root.string(), "failed"); }
  EXPECT_TRUE(fs::is_directory(root / "kept"));
  EXPECT_FALSE(fs::exists(root / "failed.incomplete"));
}

// What a killed run leaves is refused by name or by marker, with the records it journaled.
TEST(RunFolder, UnfinishedFolderIsRefusedWithOneLine) {
  const auto root = testing::scratchDirectory("run_folder_unfinished");
  results::PendingRunFolder folder = results::PendingRunFolder::forRun(root.string(), "killed");
  folder.journal("{}");
  folder.journal("{}");
  const std::string message =
      errorOf([&] { results::requireFinishedRunFolder(folder.pendingPath()); });
  EXPECT_NE(message.find("killed.incomplete: unfinished run"), std::string::npos) << message;
  EXPECT_NE(message.find("2 records journaled"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  // Renamed by hand, the marker still says so.
  fs::rename(folder.pendingPath(), root / "renamed");
  EXPECT_THROW(results::requireFinishedRunFolder((root / "renamed").string()), std::runtime_error);
  EXPECT_NE(readFile(root / "renamed" / results::kIncompleteMarker).find("did not finish"),
            std::string::npos);
}

// A folder that appears under the final name while the run measures is never replaced.
TEST(RunFolder, FinishRefusesToReplaceAFolderThatAppeared) {
  const auto root = testing::scratchDirectory("run_folder_race");
  results::PendingRunFolder folder = results::PendingRunFolder::forRun(root.string(), "r");
  fs::create_directories(root / "r");
  testing::writeTextFile(root / "r" / "results.json", "other\n");
  folder.writeFile("results.json", "{}\n");
  EXPECT_THROW(folder.finish(), std::runtime_error);
  EXPECT_EQ(readFile(root / "r" / "results.json"), "other\n");
  EXPECT_EQ(readFile(root / "r.incomplete" / "results.json"), "{}\n");
}

// An --out that cannot hold a folder fails before any measuring, naming the path. (Mode
// bits do not stop root, so the unwritable place is a path through a regular file.)
TEST(RunFolder, UnwritableRootIsOneLineNamingIt) {
  const auto root = testing::scratchDirectory("run_folder_unwritable");
  const std::string file = testing::writeTextFile(root / "plain_file", "x");
  const std::string message =
      errorOf([&] { results::PendingRunFolder::forRun(file + "/results", ""); });
  EXPECT_NE(message.find(file + "/results: cannot create results folder"), std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_THROW(results::PendingRunFolder::at(file + "/merged"), std::runtime_error);
}

TEST(RunFolder, MergeFolderIsCreatedOnceWithItsParents) {
  const auto root = testing::scratchDirectory("run_folder_new");
  const std::string path = (root / "merged" / "all").string();
  results::PendingRunFolder folder = results::PendingRunFolder::at(path + "/");
  EXPECT_EQ(folder.runId(), "all");
  folder.finish();
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_THROW(results::PendingRunFolder::at(path), std::runtime_error);
  EXPECT_THROW(results::PendingRunFolder::at(path + "/"), std::runtime_error);
}

TEST(RunFolder, WriteNewFileRefusesToOverwrite) {
  const auto root = testing::scratchDirectory("run_folder_write");
  const std::string path = (root / "results.json").string();
  results::writeNewFile(path, "{}\n");
  EXPECT_THROW(results::writeNewFile(path, "other\n"), std::runtime_error);
  EXPECT_EQ(readFile(path), "{}\n");
}

// A file that cannot grow (a full disk; here a file-size limit, which fails write() the
// same way) is a one-line error naming the file and the cause, not a silent short file.
TEST(RunFolder, WriteFailureNamesTheFileAndTheCause) {
  const auto root = testing::scratchDirectory("run_folder_full");
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = saved;
  small.rlim_cur = 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string path = (root / "results.json").string();
  const std::string message = errorOf([&] { results::writeNewFile(path, std::string(4096, 'x')); });
  results::PendingRunFolder folder = results::PendingRunFolder::forRun(root.string(), "r");
  const std::string journal_message = errorOf([&] { folder.journal(std::string(4096, 'x')); });
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(message.find(path + ": write failed (File too large)"), std::string::npos) << message;
  EXPECT_NE(journal_message.find("records.jsonl: write failed"), std::string::npos)
      << journal_message;
}

}  // namespace
}  // namespace tb
