// Shared by the acc tests: bundled assets acc supports, and shared-edge bookkeeping.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "techniques/acc/acc.h"
#include "techniques/technique.h"
#include "tests/test_support.h"

namespace tb::acc::testing {

struct Asset {
  std::string name;
  mesh::Mesh mesh;
};

// Every bundled Catmull-Clark asset acc accepts (checkSupport empty), by file name.
inline std::vector<Asset> supportedAssets(std::vector<std::string>* rejected = nullptr) {
  std::vector<std::string> files;
  for (const char* folder : {"opensubdiv", "tessbench"}) {
    for (const auto& entry : std::filesystem::directory_iterator(tb::testing::assetPath(folder))) {
      if (entry.path().extension() == ".obj") files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<Asset> assets;
  AccTechnique technique;
  for (const std::string& file : files) {
    const std::string name = std::filesystem::path(file).filename().string();
    if (name.rfind("loop_", 0) == 0) continue;
    mesh::Mesh mesh = mesh::loadObjFile(file);
    const std::string reason = technique.checkSupport(mesh);
    if (reason.empty()) {
      assets.push_back({name, std::move(mesh)});
    } else if (rejected != nullptr) {
      rejected->push_back(name + ": " + reason);
    }
  }
  return assets;
}

inline techniques::VariantInfo variantNamed(const std::string& name) {
  for (const techniques::VariantInfo& v : AccTechnique().variants()) {
    if (v.name == name) return v;
  }
  return {};
}

// (u,v) of the point at fraction s along patch edge k, from corner k to corner k+1.
inline std::array<double, 2> edgeUv(int k, double s) {
  static constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto& a = kCorner[k];
  const auto& b = kCorner[(k + 1) % 4];
  return {a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s};
}

// The edges a domain point lies on, as (lower vertex, higher vertex, parameter from
// the lower vertex); exact for tessellator coordinates (multiples of 2^-16).
using EdgeKey = std::tuple<uint32_t, uint32_t, double>;
inline std::vector<EdgeKey> edgeKeys(const std::array<uint32_t, 4>& corners, double u, double v) {
  std::vector<EdgeKey> keys;
  const double s_of_edge[4] = {u, v, 1 - u, 1 - v};
  const bool on_edge[4] = {v == 0, u == 1, v == 1, u == 0};
  for (int k = 0; k < 4; ++k) {
    if (!on_edge[k]) continue;
    const uint32_t a = corners[k], b = corners[(k + 1) % 4];
    const double s = s_of_edge[k];
    keys.emplace_back(std::min(a, b), std::max(a, b), a < b ? s : 1 - s);
  }
  return keys;
}

}  // namespace tb::acc::testing
