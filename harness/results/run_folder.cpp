#include "harness/results/run_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <stdexcept>

namespace tb {
namespace {

std::string formatUtc(const char* format) {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[64];
  std::strftime(text, sizeof(text), format, &utc);
  return text;
}

// mkdir is atomic: of two runs racing for one name, exactly one wins.
bool makeDirectory(const std::string& path) {
  if (::mkdir(path.c_str(), 0755) == 0) return true;
  if (errno == EEXIST) return false;
  throw std::runtime_error(path + ": cannot create run folder: " + std::strerror(errno));
}

}  // namespace

std::string utcTimestampIso8601() { return formatUtc("%Y-%m-%dT%H:%M:%SZ"); }

std::string createRunFolder(const std::string& root, const std::string& run_id,
                            std::string* chosen_run_id) {
  std::error_code error;
  std::filesystem::create_directories(root, error);
  if (error) throw std::runtime_error(root + ": cannot create results folder: " + error.message());
  if (!run_id.empty()) {
    const std::string path = root + "/" + run_id;
    if (!makeDirectory(path)) {
      throw std::runtime_error(path + ": run folder already exists; choose another --run-id "
                               "(earlier results are never overwritten)");
    }
    *chosen_run_id = run_id;
    return path;
  }
  const std::string base = formatUtc("%Y%m%d-%H%M%S");
  for (int suffix = 1; suffix < 1000; ++suffix) {
    const std::string name = suffix == 1 ? base : base + "-" + std::to_string(suffix);
    const std::string path = root + "/" + name;
    if (makeDirectory(path)) {
      *chosen_run_id = name;
      return path;
    }
  }
  throw std::runtime_error(root + ": too many runs with the same timestamp");
}

void createNewRunFolder(const std::string& path) {
  std::filesystem::path folder = std::filesystem::path(path).lexically_normal();
  if (folder.filename().empty()) folder = folder.parent_path();  // "out/" is "out"
  const std::filesystem::path parent = folder.parent_path();
  std::error_code error;
  if (!parent.empty()) std::filesystem::create_directories(parent, error);
  if (error) {
    throw std::runtime_error(parent.string() +
                             ": cannot create results folder: " + error.message());
  }
  if (!makeDirectory(folder.string())) {
    throw std::runtime_error(path +
                             ": run folder already exists; choose another --out "
                             "(earlier results are never overwritten)");
  }
}

void writeNewFile(const std::string& path, const std::string& contents) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0) {
    throw std::runtime_error(path + ": cannot create (" + std::strerror(errno) +
                             "); existing results are never overwritten");
  }
  size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n <= 0) {
      ::close(fd);
      throw std::runtime_error(path + ": write failed");
    }
    written += size_t(n);
  }
  ::close(fd);
}

}  // namespace tb
