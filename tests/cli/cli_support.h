// Running the built `tessbench` executable from the CLI tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace tb::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline CommandResult runTessbench(const std::string& arguments) {
  const std::string command = std::string(TB_TESSBENCH_BIN) + " " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

struct SplitResult {
  int exit_code = -1;
  std::string out, err;  // stdout, stderr
};

// Runs `tessbench arguments` with stdout and stderr kept apart; `environment` is a prefix
// of VAR=value words for the shell (e.g. "VK_ICD_FILENAMES=/nonexistent").
inline SplitResult runTessbenchSplit(const std::string& arguments,
                                     const std::string& environment = "") {
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() /
      ("tessbench_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string command = environment + " " + std::string(TB_TESSBENCH_BIN) + " " +
                              arguments + " 2>" + err_file.string();
  SplitResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  result.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
  std::filesystem::remove(err_file);
  return result;
}

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

inline size_t lineCount(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n');
}

}  // namespace tb::testing
