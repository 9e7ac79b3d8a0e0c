// Helpers shared by the libFuzzer targets in this folder (README.md): checks of the
// properties a target's code documents, and a scratch file for readers that take a path.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace tb::fuzz {

// A documented property that does not hold is a finding: print it and abort, which
// libFuzzer reports as a crash and saves the input for.
inline void require(bool holds, const char* property) {
  if (holds) return;
  std::fprintf(stderr, "tessbench fuzz: property broken: %s\n", property);
  std::abort();
}

// One file per process, rewritten for every input and removed at exit; in /dev/shm when
// it exists (memory, not disk: a fuzzer writes it thousands of times a second).
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& extension) {
    namespace fs = std::filesystem;
    const fs::path folder =
        fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    path_ = (folder / ("tessbench_fuzz_" + std::to_string(::getpid()) + extension)).string();
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  // Replaces the file's contents with the bytes; returns its path.
  const std::string& write(const uint8_t* data, size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    out.close();
    require(bool(out), "the scratch file could be written");
    return path_;
  }

 private:
  std::string path_;
};

}  // namespace tb::fuzz
