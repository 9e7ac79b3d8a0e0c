// Helpers shared by the test suites: bundled assets and their meshes, the registered
// techniques, scratch files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "core/mesh/bounds.h"
#include "core/mesh/gltf_loader.h"
#include "core/mesh/obj_loader.h"
#include "techniques/registry.h"
#include "tests/test_paths.h"

namespace tb::testing {

inline std::string assetPath(const std::string& name) {
  return std::string(TB_SOURCE_DIR) + "/assets/" + name;
}

inline mesh::Mesh loadAsset(const std::string& name) {
  return mesh::isGltfPath(name) ? mesh::loadGltfFile(assetPath(name))
                                : mesh::loadObjFile(assetPath(name));
}

// The diagonal of the mesh's bounding box (mesh::boundsOf), world units.
inline double diagonalOf(const mesh::Mesh& mesh) { return mesh::diagonalOf(mesh::boundsOf(mesh)); }

// The registered surface techniques, sorted by id.
inline std::vector<const techniques::Technique*> surfaceTechniques() {
  std::vector<const techniques::Technique*> result;
  for (const techniques::Technique* t : techniques::TechniqueRegistry::instance().all()) {
    if (t->info().family == techniques::TechniqueFamily::kSurface) result.push_back(t);
  }
  return result;
}

// The registered technique `id`; throws std::logic_error when there is none.
inline const techniques::Technique& technique(const std::string& id) {
  const techniques::Technique* t = techniques::TechniqueRegistry::instance().find(id);
  if (t == nullptr) throw std::logic_error("no technique " + id);
  return *t;
}

// The technique's variant `name`; a test failure and {} when it has none.
inline techniques::VariantInfo variantOf(const techniques::Technique& technique,
                                         const std::string& name) {
  for (const techniques::VariantInfo& v : technique.variants()) {
    if (v.name == name) return v;
  }
  ADD_FAILURE() << technique.info().id << " has no variant " << name;
  return {};
}

// The bundled meshes (assets/opensubdiv, assets/tessbench), relative to assets/, sorted.
inline std::vector<std::string> bundledObjs() {
  std::vector<std::string> objs;
  for (const char* folder : {"opensubdiv", "tessbench"}) {
    for (const auto& entry : std::filesystem::directory_iterator(assetPath(folder))) {
      if (entry.path().extension() == ".obj") {
        objs.push_back(std::string(folder) + "/" + entry.path().filename().string());
      }
    }
  }
  std::sort(objs.begin(), objs.end());
  return objs;
}

// The scratch directories a test program made: removed when the program exits with every
// test passed, kept for a look when one failed (the failure messages name them).
class ScratchDirectories {
 public:
  static ScratchDirectories& instance() {
    static ScratchDirectories directories;  // after gtest's UnitTest, so destroyed before it
    return directories;
  }
  void add(const std::filesystem::path& dir) {
    const std::lock_guard lock(mutex_);
    dirs_.push_back(dir);
  }
  ~ScratchDirectories() {
    if (::testing::UnitTest::GetInstance()->Failed()) return;
    std::error_code ignored;
    for (const auto& dir : dirs_) std::filesystem::remove_all(dir, ignored);
  }

 private:
  ScratchDirectories() = default;
  std::mutex mutex_;
  std::vector<std::filesystem::path> dirs_;
};

// A fresh, empty scratch directory under the system temp dir, unique per test program.
inline std::filesystem::path scratchDirectory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("tessbench_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ScratchDirectories::instance().add(dir);
  return dir;
}

// Whether this test program runs under AddressSanitizer (the asan-ubsan preset). The few
// end-to-end tests that repeat a whole run over every bundled asset (minutes under ASan, where
// CI's 30-minute budget goes) thin their inputs under it: the sanitizer still sees every code
// path on a subset, and the Release run keeps the whole sweep.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif
#else
inline constexpr bool kUnderSanitizer = false;
#endif

// 1 in Release; `stride` under a sanitizer: take every stride-th item of a sweep.
inline size_t sweepStride(size_t stride) { return kUnderSanitizer ? stride : 1; }

inline std::string writeTextFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace tb::testing
