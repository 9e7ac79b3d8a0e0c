// Helpers shared by the gregory_acc test files: the bundled assets the technique accepts,
// and the twin of every directed patch edge (for shared-edge checks).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "harness/mesh/obj_loader.h"
#include "techniques/gregory_acc/gregory_acc.h"
#include "tests/test_support.h"

namespace tb::gregory_acc::testing {

// Every bundled OBJ ("opensubdiv/catmark_cube.obj", ...) that checkSupport accepts, sorted.
inline std::vector<std::string> supportedBundledAssets() {
  std::vector<std::string> names;
  GregoryAccTechnique technique;
  for (const char* folder : {"opensubdiv", "tessbench"}) {
    for (const auto& entry :
         std::filesystem::directory_iterator(tb::testing::assetPath(folder))) {
      if (entry.path().extension() != ".obj") continue;
      const std::string name = std::string(folder) + "/" + entry.path().filename().string();
      if (technique.checkSupport(loadObjFile(tb::testing::assetPath(name))).empty()) {
        names.push_back(name);
      }
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct EdgeTwin {
  int64_t face = -1;  // -1: boundary edge
  int corner = 0;     // the twin is (corner, corner + 1) of `face`, running the other way
};

// twins[f * 4 + c]: the patch edge sharing edge (c, c + 1) of quad patch f.
inline std::vector<EdgeTwin> edgeTwins(const Mesh& quads) {
  std::unordered_map<uint64_t, EdgeTwin> by_directed;
  for (size_t f = 0; f < quads.faceCount(); ++f) {
    const auto fv = quads.facePositions(f);
    for (int c = 0; c < 4; ++c) {
      by_directed[(uint64_t(fv[c]) << 32) | fv[(c + 1) % 4]] = {int64_t(f), c};
    }
  }
  std::vector<EdgeTwin> twins(4 * quads.faceCount());
  for (size_t f = 0; f < quads.faceCount(); ++f) {
    const auto fv = quads.facePositions(f);
    for (int c = 0; c < 4; ++c) {
      const auto it = by_directed.find((uint64_t(fv[(c + 1) % 4]) << 32) | fv[c]);
      if (it != by_directed.end()) twins[f * 4 + c] = it->second;
    }
  }
  return twins;
}

}  // namespace tb::gregory_acc::testing
