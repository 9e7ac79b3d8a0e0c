#include "harness/results/run_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace tb::results {
namespace {

namespace fs = std::filesystem;

std::string formatUtc(const char* format) {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[64];
  std::strftime(text, sizeof(text), format, &utc);
  return text;
}

std::string errnoText() { return std::strerror(errno); }

// "out/" and "out" name the same folder.
std::string normalised(const std::string& path) {
  fs::path folder = fs::path(path).lexically_normal();
  if (folder.filename().empty() && folder.has_parent_path()) folder = folder.parent_path();
  return folder.string();
}

bool pathExists(const std::string& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0;
}

// Creates `folder` and its missing parents; returns the folders it created, deepest first
// (none when `folder` existed). One line naming the folder when it cannot be made.
std::vector<std::string> makeParents(const std::string& folder) {
  if (folder.empty()) return {};
  std::vector<std::string> created;
  for (fs::path p = fs::path(folder); !p.empty(); p = p.parent_path()) {
    if (pathExists(p.string())) break;
    created.push_back(p.string());
    if (p == p.parent_path()) break;
  }
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) {
    throw std::runtime_error(folder + ": cannot create results folder (" + error.message() + ")");
  }
  if (!fs::is_directory(folder)) {
    throw std::runtime_error(folder + ": cannot create results folder (not a directory)");
  }
  return created;
}

// mkdir is atomic: of two runs racing for one name, exactly one wins. false: it exists.
bool makeDirectory(const std::string& path) {
  if (::mkdir(path.c_str(), 0755) == 0) return true;
  if (errno == EEXIST) return false;
  throw std::runtime_error(path + ": cannot create run folder (" + errnoText() + ")");
}

void writeAll(int fd, const std::string& path, const std::string& contents) {
  size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw std::runtime_error(path + ": write failed (" +
                               (n < 0 ? errnoText() : std::string("nothing written")) + ")");
    }
    written += size_t(n);
  }
}

size_t countLines(const std::string& path) {
  std::ifstream file(path);
  size_t lines = 0;
  for (std::string line; std::getline(file, line);) lines += line.empty() ? 0 : 1;
  return lines;
}

constexpr const char* kMarkerText =
    "This run did not finish. tessbench writes a run here while it measures and renames the\n"
    "folder (dropping .incomplete) only once results.json and report.md are complete; a run\n"
    "that was killed or failed leaves this folder. records.jsonl holds the records measured\n"
    "before it stopped. `tessbench report` and `tessbench merge` refuse it.\n";

}  // namespace

std::string utcTimestampIso8601() { return formatUtc("%Y-%m-%dT%H:%M:%SZ"); }

PendingRunFolder PendingRunFolder::forRun(const std::string& root, const std::string& run_id) {
  PendingRunFolder folder;
  const std::string base = normalised(root);
  folder.created_folders_ = makeParents(base);
  auto claim = [&](const std::string& name) {
    const std::string final_path = base + "/" + name;
    if (pathExists(final_path)) return false;
    if (!makeDirectory(final_path + kIncompleteSuffix)) return false;
    folder.run_id_ = name;
    folder.final_path_ = final_path;
    folder.pending_path_ = final_path + kIncompleteSuffix;
    return true;
  };
  try {
    if (!run_id.empty()) {
      if (!claim(run_id)) {
        throw std::runtime_error(base + "/" + run_id +
                                 ": run folder already exists (finished or not); choose another "
                                 "--run-id (earlier results are never overwritten)");
      }
    } else {
      const std::string stamp = formatUtc("%Y%m%d-%H%M%S");
      for (int suffix = 1; suffix < 1000 && folder.run_id_.empty(); ++suffix) {
        claim(suffix == 1 ? stamp : stamp + "-" + std::to_string(suffix));
      }
      if (folder.run_id_.empty()) {
        throw std::runtime_error(base + ": too many runs with the same timestamp");
      }
    }
    folder.writeFile(kIncompleteMarker, kMarkerText);
    const std::string journal_path = folder.pending_path_ + "/" + kRecordJournal;
    folder.journal_fd_ = ::open(journal_path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND, 0644);
    if (folder.journal_fd_ < 0) {
      throw std::runtime_error(journal_path + ": cannot create (" + errnoText() + ")");
    }
  } catch (...) {
    folder.abandon();  // removes what was made so far
    throw;
  }
  return folder;
}

PendingRunFolder PendingRunFolder::at(const std::string& final_path) {
  PendingRunFolder folder;
  const std::string path = normalised(final_path);
  const std::string parent = fs::path(path).parent_path().string();
  folder.created_folders_ = makeParents(parent);
  if (pathExists(path) || !makeDirectory(path + kIncompleteSuffix)) {
    throw std::runtime_error(final_path +
                             ": run folder already exists (finished or not); choose another "
                             "--out (earlier results are never overwritten)");
  }
  folder.run_id_ = fs::path(path).filename().string();
  folder.final_path_ = path;
  folder.pending_path_ = path + kIncompleteSuffix;
  try {
    folder.writeFile(kIncompleteMarker, kMarkerText);
  } catch (...) {
    folder.abandon();
    throw;
  }
  return folder;
}

PendingRunFolder::PendingRunFolder(PendingRunFolder&& other) noexcept
    : run_id_(std::move(other.run_id_)),
      final_path_(std::move(other.final_path_)),
      pending_path_(std::move(other.pending_path_)),
      created_folders_(std::move(other.created_folders_)),
      journal_fd_(other.journal_fd_),
      finished_(other.finished_) {
  other.journal_fd_ = -1;
  other.pending_path_.clear();
  other.created_folders_.clear();
  other.finished_ = true;
}

PendingRunFolder::~PendingRunFolder() { abandon(); }

void PendingRunFolder::abandon() noexcept {
  if (journal_fd_ >= 0) ::close(journal_fd_);
  journal_fd_ = -1;
  if (finished_) return;
  finished_ = true;
  std::error_code ignored;
  if (!pending_path_.empty()) fs::remove_all(pending_path_, ignored);
  // Only when empty: another run may have put its folder there meanwhile.
  for (const std::string& created : created_folders_) {
    if (!fs::remove(created, ignored)) break;
  }
}

void PendingRunFolder::journal(const std::string& line) {
  if (journal_fd_ < 0) throw std::logic_error("run folder journal is not open");
  writeAll(journal_fd_, pending_path_ + "/" + kRecordJournal, line + "\n");
}

void PendingRunFolder::writeFile(const std::string& name, const std::string& contents) {
  // A name with folders ("tables/cracks.csv") gets them made inside the run folder.
  const fs::path parent = fs::path(name).parent_path();
  if (!parent.empty()) {
    std::error_code error;
    fs::create_directories(fs::path(pending_path_) / parent, error);
    if (error) {
      throw std::runtime_error(pending_path_ + "/" + parent.string() + ": cannot create (" +
                               error.message() + ")");
    }
  }
  writeNewFile(pending_path_ + "/" + name, contents);
}

std::string PendingRunFolder::finish() {
  if (journal_fd_ >= 0) {
    ::close(journal_fd_);
    journal_fd_ = -1;
    ::unlink((pending_path_ + "/" + kRecordJournal).c_str());
  }
  ::unlink((pending_path_ + "/" + kIncompleteMarker).c_str());
  // RENAME_NOREPLACE: a folder that appeared under the final name meanwhile is never replaced.
  int status =
      ::renameat2(AT_FDCWD, pending_path_.c_str(), AT_FDCWD, final_path_.c_str(), RENAME_NOREPLACE);
  if (status != 0 && (errno == EINVAL || errno == ENOSYS)) {  // a file system without it
    errno = EEXIST;
    status = pathExists(final_path_) ? -1 : ::rename(pending_path_.c_str(), final_path_.c_str());
  }
  if (status != 0) {
    const std::string why = errnoText();
    finished_ = true;  // keep the results where they are
    throw std::runtime_error(pending_path_ + ": cannot rename to " + final_path_ + " (" + why +
                             "); the complete results stay in " + pending_path_);
  }
  finished_ = true;
  return final_path_;
}

void requireFinishedRunFolder(const std::string& folder) {
  const std::string path = normalised(folder);
  const bool marked = pathExists(path + "/" + kIncompleteMarker);
  if (!marked && !path.ends_with(kIncompleteSuffix)) return;
  const std::string journal = path + "/" + kRecordJournal;
  const std::string records = pathExists(journal)
                                  ? std::to_string(countLines(journal)) + " records journaled"
                                  : "no journal";
  throw std::runtime_error(folder + ": unfinished run (it stopped before completing; " + records +
                           "); only finished runs are read, so rerun it");
}

void writeNewFile(const std::string& path, const std::string& contents) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    throw std::runtime_error(path + ": cannot create (" + errnoText() +
                             "); existing results are never overwritten");
  }
  try {
    writeAll(fd, path, contents);
  } catch (...) {
    ::close(fd);
    throw;
  }
  // A full disk or a network file system may report the failure only here.
  if (::close(fd) != 0) throw std::runtime_error(path + ": write failed (" + errnoText() + ")");
}

}  // namespace tb::results
