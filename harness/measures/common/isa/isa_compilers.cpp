#include "harness/measures/common/isa/isa_compilers.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <utility>

extern char** environ;

namespace tb::measures::isa {
namespace {

namespace fs = std::filesystem;

constexpr Family kFamilies[] = {
    {"polaris10", "GCN4"}, {"vega10", "GCN5"},    {"navi10", "RDNA1"},         {"navi21", "RDNA2"},
    {"gfx1100", "RDNA3"},  {"raven", "GCN5 APU"}, {"gfx1103_r1", "RDNA3 APU"},
};
constexpr size_t kDefaultFamilyCount = 5;

// The variables the loader and RADV read to choose a driver: the worker gets its own.
bool choosesDriver(std::string_view entry) {
  for (std::string_view name :
       {"VK_ICD_FILENAMES=", "VK_DRIVER_FILES=", "VK_ADD_DRIVER_FILES=", "RADV_FORCE_FAMILY=",
        "VK_INSTANCE_LAYERS=", "VK_LOADER_LAYERS_ENABLE="}) {
    if (entry.starts_with(name)) return true;
  }
  return false;
}

// One worker process, talking over a socket (send with MSG_NOSIGNAL: a worker that died
// is an error, never a SIGPIPE in the run).
class Worker {
 public:
  ~Worker() { stop(); }

  // Starts the worker if it is not running; false with `why` when it cannot.
  bool start(const std::string& executable, const std::string& icd, std::string_view family,
             std::string* why) {
    if (pid_ > 0) return true;
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      *why = std::string("socketpair: ") + std::strerror(errno);
      return false;
    }
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
      if (!choosesDriver(*e)) env.emplace_back(*e);
    }
    env.push_back("VK_ICD_FILENAMES=" + icd);
    env.push_back("RADV_FORCE_FAMILY=" + std::string(family));
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 0);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::string program = executable;
    char* argv[] = {program.data(), nullptr};
    const int spawned =
        posix_spawn(&pid_, executable.c_str(), &actions, nullptr, argv, envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    if (spawned != 0) {
      close(fds[0]);
      pid_ = -1;
      *why = "cannot start " + executable + ": " + std::strerror(spawned);
      return false;
    }
    socket_ = fds[0];
    std::string line;
    if (!readLine(&line)) {
      *why = exitReason(family);
      return false;
    }
    hello_ = helloFromLine(line);
    if (!hello_.error.empty()) {
      *why = hello_.error;
      stop();
      return false;
    }
    return true;
  }

  // The request's outcome; an error outcome when the worker dies on it.
  CompileOutcome call(const std::string& request, std::string_view family) {
    const std::string line = request + '\n';
    size_t sent = 0;
    while (sent < line.size()) {
      const ssize_t n = send(socket_, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;
      sent += size_t(n);
    }
    std::string answer;
    if (sent < line.size() || !readLine(&answer)) return {{}, exitReason(family)};
    return outcomeFromLine(answer);
  }

  const WorkerHello& hello() const { return hello_; }

 private:
  bool readLine(std::string* line) {
    for (;;) {
      if (const size_t end = buffer_.find('\n'); end != std::string::npos) {
        *line = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        return true;
      }
      std::array<char, 65536> chunk;
      const ssize_t n = read(socket_, chunk.data(), chunk.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      buffer_.append(chunk.data(), size_t(n));
    }
  }

  // Why the worker stopped answering (it is reaped here, and restarts at the next call).
  std::string exitReason(std::string_view family) {
    int status = 0;
    const pid_t pid = pid_;
    stop(&status);
    std::string what =
        "the " + std::string(family) + " compiler worker (pid " + std::to_string(pid) + ") ended";
    if (WIFSIGNALED(status)) return what + " on signal " + std::to_string(WTERMSIG(status));
    return what + " with status " + std::to_string(WEXITSTATUS(status));
  }

  void stop(int* status = nullptr) {
    if (socket_ >= 0) close(socket_);
    socket_ = -1;
    buffer_.clear();
    if (pid_ > 0) {
      int ignored = 0;
      waitpid(pid_, status != nullptr ? status : &ignored, 0);
    }
    pid_ = -1;
  }

  pid_t pid_ = -1;
  int socket_ = -1;
  std::string buffer_;
  WorkerHello hello_;
};

struct FamilyCompilers {
  std::mutex mutex;
  Worker worker;
  std::string unavailable;  // a start that failed for good (no ICD, no worker, no device)
  std::map<std::string, std::shared_ptr<const CompileOutcome>> cache;  // by request line
};

class Compilers {
 public:
  static Compilers& instance() {
    static Compilers compilers;
    return compilers;
  }
  FamilyCompilers& of(std::string_view family) {
    const std::lock_guard lock(mutex_);
    std::unique_ptr<FamilyCompilers>& entry = families_[std::string(family)];
    if (!entry) entry = std::make_unique<FamilyCompilers>();
    return *entry;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::unique_ptr<FamilyCompilers>> families_;
};

}  // namespace

std::span<const Family> defaultFamilies() { return {kFamilies, kDefaultFamilyCount}; }
std::span<const Family> fullSuiteFamilies() { return kFamilies; }

std::string radeonIcd(std::string* why) {
  for (const char* variable : {"VK_ICD_FILENAMES", "VK_DRIVER_FILES"}) {
    const char* value = std::getenv(variable);
    if (value == nullptr || *value == '\0') continue;
    std::string list = value;
    for (size_t start = 0; start <= list.size();) {
      const size_t end = std::min(list.find(':', start), list.size());
      const std::string entry = list.substr(start, end - start);
      if (fs::path(entry).filename().string().starts_with("radeon_icd") && fs::exists(entry)) {
        return entry;
      }
      start = end + 1;
    }
    *why = std::string(variable) + " names no radeon ICD (radeon_icd*.json): " + list;
    return {};
  }
  for (const char* folder :
       {"/usr/share/vulkan/icd.d", "/usr/local/share/vulkan/icd.d", "/etc/vulkan/icd.d"}) {
    std::error_code error;
    std::vector<fs::path> found;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, error)) {
      if (e.path().filename().string().starts_with("radeon_icd")) found.push_back(e.path());
    }
    std::sort(found.begin(), found.end());
    if (!found.empty()) return found.front().string();
  }
  *why = "the radeon ICD (radeon_icd*.json, Debian's mesa-vulkan-drivers) is not installed";
  return {};
}

std::string workerExecutable(std::string* why) {
  if (const char* path = std::getenv("TB_ISA_WORKER"); path != nullptr && *path != '\0') {
    if (fs::exists(path)) return path;
    *why = std::string("TB_ISA_WORKER names no file: ") + path;
    return {};
  }
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  if (!error && fs::exists(self.parent_path() / "tessbench-isa-worker")) {
    return (self.parent_path() / "tessbench-isa-worker").string();
  }
#ifdef TB_ISA_WORKER_BUILD_PATH
  if (fs::exists(TB_ISA_WORKER_BUILD_PATH)) return TB_ISA_WORKER_BUILD_PATH;
#endif
  *why = "the ISA compiler worker (tessbench-isa-worker) is not built beside " + self.string();
  return {};
}

FamilyCompile compileOn(std::string_view family, const PipelineRequest& request) {
  FamilyCompile result;
  // Asked at every call, never cached: the environment says which drivers a run may use.
  std::string why;
  const std::string icd = radeonIcd(&why);
  if (icd.empty()) {
    result.unavailable = why;
    return result;
  }
  FamilyCompilers& compilers = Compilers::instance().of(family);
  const std::lock_guard lock(compilers.mutex);
  if (!compilers.unavailable.empty()) {
    result.unavailable = compilers.unavailable;
    return result;
  }
  const std::string executable = workerExecutable(&why);
  if (executable.empty() || !compilers.worker.start(executable, icd, family, &why)) {
    compilers.unavailable = why;
    result.unavailable = why;
    return result;
  }
  result.driver = compilers.worker.hello().driver;
  const std::string line = toLine(request);
  std::shared_ptr<const CompileOutcome>& cached = compilers.cache[line];
  if (!cached) {
    cached = std::make_shared<const CompileOutcome>(compilers.worker.call(line, family));
  }
  result.outcome = cached;
  return result;
}

}  // namespace tb::measures::isa
