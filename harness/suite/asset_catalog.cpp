#include "harness/suite/asset_catalog.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/mesh/input_error.h"

#ifndef TB_DEFAULT_ASSETS_DIR
#error "TB_DEFAULT_ASSETS_DIR must be defined by the build"
#endif

namespace tb::suite {

namespace fs = std::filesystem;

// An installed tessbench (`cmake --install`) finds its assets beside its own binary,
// <prefix>/bin/tessbench -> <prefix>/share/tessbench/assets, wherever the prefix was moved.
std::string installedAssetsDirectory() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const fs::path dir = exe.parent_path().parent_path() / "share" / "tessbench" / "assets";
  return fs::is_directory(dir, error) ? dir.string() : std::string();
}

std::string assetsDirectory() {
  if (const char* dir = std::getenv("TB_ASSETS_DIR"); dir != nullptr && *dir != '\0') return dir;
  static const std::string installed = installedAssetsDirectory();
  if (!installed.empty()) return installed;
  return TB_DEFAULT_ASSETS_DIR;  // the build tree's: the source checkout's assets/
}

std::vector<AssetRef> bundledAssets() {
  std::vector<AssetRef> assets;
  const fs::path root = assetsDirectory();
  std::error_code error;
  for (fs::recursive_directory_iterator it(root, error), end; !error && it != end;
       it.increment(error)) {
    if (!it->is_regular_file() || it->path().extension() != ".obj") continue;
    fs::path relative = fs::relative(it->path(), root);
    const std::string label = "assets/" + relative.generic_string();
    relative.replace_extension();
    assets.push_back({relative.generic_string(), it->path().string(), label});
  }
  std::sort(assets.begin(), assets.end(),
            [](const AssetRef& a, const AssetRef& b) { return a.name < b.name; });
  return assets;
}

std::vector<AssetRef> suiteAssets(bool full_suite) {
  std::vector<AssetRef> assets = bundledAssets();
  if (!full_suite) {
    std::erase_if(assets, [](const AssetRef& asset) {
      return asset.name.rfind(kFullSuiteAssetFolder, 0) == 0;
    });
  }
  return assets;
}

AssetRef resolveAsset(const std::string& name_or_path) {
  for (const AssetRef& asset : bundledAssets()) {
    const std::string stem = fs::path(asset.name).filename().string();
    if (asset.name == name_or_path || stem == name_or_path) return asset;
  }
  if (fs::is_regular_file(name_or_path)) return {name_or_path, name_or_path, ""};
  throw mesh::InputError(name_or_path, "",
                         "no such file, and not a bundled asset (see `tessbench list assets`)");
}

}  // namespace tb::suite
