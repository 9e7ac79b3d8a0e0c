// Running the built `tessbench` executable from the CLI tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace tb::testing {

// A measure's rows from results.json (schema 4: "keys" and "metrics" name the columns,
// each row is [[key values], [metric values]] plus status and reason when not ok) as
// objects: {"keys": {name: value}, "metrics": {name: value}, "status", "reason"}; absent
// keys and metrics are left out, ok rows have no status.
inline nlohmann::json rowObjects(const nlohmann::json& measure) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& line : measure["rows"]) {
    nlohmann::json row{{"keys", nlohmann::json::object()}, {"metrics", nlohmann::json::object()}};
    for (size_t k = 0; k < measure["keys"].size(); ++k) {
      if (!line[0][k].is_null()) row["keys"][measure["keys"][k].get<std::string>()] = line[0][k];
    }
    for (size_t m = 0; m < measure["metrics"].size(); ++m) {
      if (!line[1][m].is_null()) {
        row["metrics"][measure["metrics"][m].get<std::string>()] = line[1][m];
      }
    }
    if (line.size() == 4) {
      row["status"] = line[2];
      row["reason"] = line[3];
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

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

// Runs `program arguments` with stdout and stderr kept apart; `environment` is a prefix
// of VAR=value words for the shell (e.g. "VK_ICD_FILENAMES=/nonexistent").
inline SplitResult runSplit(const std::string& program, const std::string& arguments,
                            const std::string& environment = "") {
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() /
      ("tessbench_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string command =
      environment + " " + program + " " + arguments + " 2>" + err_file.string();
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

inline SplitResult runTessbenchSplit(const std::string& arguments,
                                     const std::string& environment = "") {
  return runSplit(TB_TESSBENCH_BIN, arguments, environment);
}

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream file(path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

inline size_t lineCount(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n');
}

// The environment prefix of a run without a Vulkan device (the loader finds no driver).
inline constexpr const char* kNoVulkanDevice =
    "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";

inline size_t occurrences(const std::string& text, const std::string& what) {
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

// The text after the first `open` up to the next `close`; empty when there is none.
inline std::string between(const std::string& text, const std::string& open,
                           const std::string& close) {
  const size_t start = text.find(open);
  if (start == std::string::npos) return {};
  const size_t from = start + open.size();
  const size_t end = text.find(close, from);
  return end == std::string::npos ? std::string() : text.substr(from, end - from);
}

// The pages' browser checks: Debian's chromium, headless (scripts/install_deps.sh installs it).
inline bool chromiumOnPath() { return std::system("command -v chromium >/dev/null 2>&1") == 0; }

// Runs chromium headless on `page` with extra arguments; stdout goes to `out`, stderr (its
// log noise) is dropped. Returns the exit status.
inline int runChromium(const std::filesystem::path& profile, const std::string& arguments,
                       const std::filesystem::path& page, const std::filesystem::path& out) {
  const std::string command =
      "timeout 120 chromium --headless=new --no-sandbox --disable-gpu "
      "--no-first-run --user-data-dir=" +
      profile.string() + " --virtual-time-budget=5000 " + arguments + " file://" + page.string() +
      " >" + out.string() + " 2>/dev/null";
  return std::system(command.c_str());
}

// The names in `folder`, sorted; none when it does not exist.
inline std::vector<std::string> folderEntries(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  if (!std::filesystem::exists(folder)) return names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace tb::testing
