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

#include <nlohmann/json.hpp>

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
