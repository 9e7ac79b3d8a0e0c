// Runs of the `tessbench` executable cut short: a killed run leaves nothing that looks
// finished; an unwritable --out is one line before any measuring.
#include <fcntl.h>
#include <grp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::folderEntries;
using testing::readFile;
using testing::runTessbenchSplit;
using testing::SplitResult;
// Starts tessbench in the background; returns its pid.
pid_t spawnTessbench(const std::vector<std::string>& arguments, const fs::path& stderr_file) {
  std::vector<std::string> words{TB_TESSBENCH_BIN};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = -1;
  const int status = posix_spawn(&pid, TB_TESSBENCH_BIN, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return status == 0 ? pid : -1;
}

size_t journalLines(const fs::path& journal) {
  const std::string text = readFile(journal);
  return size_t(std::count(text.begin(), text.end(), '\n'));
}

// SIGKILL once the run has journaled its first record: what is left is only the
// `.incomplete` folder, which report and merge refuse in one line.
TEST(Interrupted, AKilledRunLeavesNoFolderThatLooksFinished) {
  const fs::path dir = testing::scratchDirectory("killed_run");
  const fs::path out = dir / "out";
  const fs::path pending = out / "killed.incomplete";
  // Enough records that the run is still going when the first is written (one thread).
  const pid_t pid =
      spawnTessbench({"run", "--quiet", "--threads", "1", "--technique", "gregory_acc", "--measure",
                      "error", "--measure", "memory", "--out", out.string(), "--run-id", "killed"},
                     dir / "stderr.txt");
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (journalLines(pending / "records.jsonl") == 0 &&
         std::chrono::steady_clock::now() < deadline && ::waitpid(pid, nullptr, WNOHANG) == 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(::kill(pid, SIGKILL), 0) << "the run ended before its first record was seen";
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  const size_t journaled = journalLines(pending / "records.jsonl");
  ASSERT_GE(journaled, 1u);

  EXPECT_EQ(folderEntries(out), std::vector<std::string>{"killed.incomplete"});
  EXPECT_TRUE(fs::exists(pending / "INCOMPLETE"));
  EXPECT_FALSE(fs::exists(out / "killed"));
  // Each journal line is a whole record.
  std::ifstream journal(pending / "records.jsonl");
  for (std::string line; std::getline(journal, line);) {
    const auto record = nlohmann::json::parse(line);
    EXPECT_EQ(record["technique"], "gregory_acc");
  }
  for (const std::string& command : {"report " + pending.string(),
                                     "merge " + pending.string() + " --out " + (dir / "m").string(),
                                     "compare " + pending.string() + " " + pending.string()}) {
    const SplitResult r = runTessbenchSplit(command);
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(pending.string() + ": unfinished run"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "m"));
  EXPECT_FALSE(fs::exists(dir / "m.incomplete"));
  // A new run beside it finishes normally and does not touch it.
  const SplitResult next = runTessbenchSplit(
      "run --quiet --technique phong --measure memory --asset catmark_cube --out " + out.string());
  ASSERT_EQ(next.exit_code, 0) << next.err;
  EXPECT_EQ(folderEntries(out).size(), 2u);
  EXPECT_EQ(journalLines(pending / "records.jsonl"), journaled);
}

// Runs tessbench as the unprivileged user `nobody` (root ignores mode bits); -1 when it
// cannot (not root, or nobody cannot reach the binary).
int runAsNobody(const fs::path& binary, const std::string& arguments, const fs::path& stderr_file) {
  if (::geteuid() != 0) return -1;
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int err = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (err >= 0) ::dup2(err, 2);
    if (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0) _exit(126);
    const std::string command = binary.string() + " " + arguments + " >/dev/null";
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A read-only --out: one line naming it before any measuring (no progress line, which a
// run that measured first would print), exit 2. Run as `nobody` on a mode-0555 folder
// when the test runs as root; directly otherwise.
TEST(ReadOnly, AReadOnlyOutputFolderIsOneLineBeforeMeasuring) {
  const fs::path dir = testing::scratchDirectory("read_only_out");
  fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                           fs::perms::others_read | fs::perms::others_exec);
  const fs::path locked = dir / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
  // nobody may not reach the build tree (a clone in a mode-0700 folder): the binary and the
  // asset are copied beside the locked folder, which nobody can reach.
  const fs::path binary = dir / "tessbench";
  fs::copy_file(TB_TESSBENCH_BIN, binary);
  const fs::path asset = dir / "cube.obj";
  fs::copy_file(testing::assetPath("opensubdiv/catmark_cube.obj"), asset);
  const std::string arguments = "run --technique phong --measure memory --asset " + asset.string() +
                                " --out " + (locked / "results").string();
  const fs::path stderr_file =
      fs::temp_directory_path() / ("tessbench_read_only_" + std::to_string(::getpid()) + ".txt");
  int exit_code;
  std::string err;
  if (::geteuid() == 0) {
    exit_code = runAsNobody(binary, arguments, stderr_file);
    err = readFile(stderr_file);
    fs::remove(stderr_file);
    if (exit_code == 126 || exit_code == 127) {
      GTEST_SKIP() << "cannot run as nobody here (" << exit_code << "); the path-through-a-file "
                   << "case of BadInputTable covers an unwritable --out";
    }
  } else {
    const SplitResult r = runTessbenchSplit(arguments);
    exit_code = r.exit_code;
    err = r.err;
  }
  EXPECT_EQ(exit_code, 2) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find((locked / "results").string() + ": cannot create results folder (Permission "
                                                     "denied)"),
            std::string::npos)
      << err;
  EXPECT_TRUE(folderEntries(locked).empty());
}

}  // namespace
}  // namespace tb
