// Helpers shared by the test suites: bundled asset paths and scratch files.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "tests/test_paths.h"

namespace tb::testing {

inline std::string assetPath(const std::string& name) {
  return std::string(TB_SOURCE_DIR) + "/assets/" + name;
}

// A fresh, empty scratch directory under the system temp dir, unique per test.
inline std::filesystem::path scratchDirectory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("tessbench_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string writeTextFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace tb::testing
