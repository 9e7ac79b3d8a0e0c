#include "harness/suite/asset_catalog.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/mesh/gltf_loader.h"
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
    const bool mesh_file = it->path().extension() == ".obj" || mesh::isGltfPath(it->path());
    if (!it->is_regular_file() || !mesh_file) continue;
    fs::path relative = fs::relative(it->path(), root);
    const std::string label = "assets/" + relative.generic_string();
    relative.replace_extension();
    assets.push_back({relative.generic_string(), it->path().string(), label});
  }
  std::sort(assets.begin(), assets.end(),
            [](const AssetRef& a, const AssetRef& b) { return a.name < b.name; });
  return assets;
}

namespace {

constexpr const char* kProductionList = "production/assets.json";

// A bundled .obj by its name ("opensubdiv/catmark_pawn") or stem ("catmark_pawn").
const AssetRef* findBundled(const std::vector<AssetRef>& bundled, const std::string& name) {
  for (const AssetRef& asset : bundled) {
    const std::string stem = fs::path(asset.name).filename().string();
    if (asset.name == name || stem == name) return &asset;
  }
  return nullptr;
}

// One entry of the production list, `where` naming it for errors ("assets[2]").
AssetRef productionAsset(const nlohmann::json& entry, const std::vector<AssetRef>& bundled,
                         const std::string& file, const std::string& where) {
  auto field = [&](const char* name) -> const nlohmann::json& {
    if (!entry.is_object() || !entry.contains(name)) {
      throw mesh::InputError(file, where, std::string("needs the field \"") + name + "\"");
    }
    return entry.at(name);
  };
  const nlohmann::json& name = field("name");
  const nlohmann::json& source = field("source");
  const nlohmann::json& refine = field("refine");
  if (!name.is_string() || !source.is_string() || !refine.is_number_integer()) {
    throw mesh::InputError(file, where, "name and source are strings, refine an integer");
  }
  const AssetRef* base = findBundled(bundled, source.get<std::string>());
  if (base == nullptr) {
    throw mesh::InputError(file, where + ".source",
                           "\"" + source.get<std::string>() + "\" is not a bundled asset");
  }
  AssetRef asset = refinedAsset(*base, refine.get<int>());
  asset.name = "production/" + name.get<std::string>();
  return asset;
}

}  // namespace

AssetRef refinedAsset(AssetRef asset, int levels) {
  const int total = asset.refine + levels;
  if (levels < 1 || total > kMaxRefine) {
    throw mesh::InputError(asset.name, "refine " + std::to_string(levels),
                           "refinement steps must be 1.." + std::to_string(kMaxRefine) +
                               " in all (each multiplies the faces by 4)");
  }
  const std::string file = asset.label.empty() ? asset.path : asset.label;
  asset.name = (asset.refine == 0 ? asset.name : asset.name.substr(0, asset.name.rfind('@'))) +
               "@refine" + std::to_string(total);
  asset.label = file.substr(0, file.find(" (refined")) + " (refined " + std::to_string(total) +
                "x by OpenSubdiv)";
  asset.refine = total;
  return asset;
}

std::vector<AssetRef> productionAssets() {
  const fs::path path = fs::path(assetsDirectory()) / kProductionList;
  const std::string file = std::string("assets/") + kProductionList;
  std::ifstream in(path);
  if (!in) return {};
  nlohmann::json list;
  try {
    list = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& error) {
    throw mesh::InputError(file, "byte " + std::to_string(error.byte), "is not valid JSON");
  }
  if (!list.is_object() || !list.contains("assets") || !list["assets"].is_array()) {
    throw mesh::InputError(file, "assets", "needs an array \"assets\"");
  }
  const std::vector<AssetRef> bundled = bundledAssets();
  std::vector<AssetRef> assets;
  for (size_t i = 0; i < list["assets"].size(); ++i) {
    assets.push_back(
        productionAsset(list["assets"][i], bundled, file, "assets[" + std::to_string(i) + "]"));
  }
  return assets;
}

std::vector<AssetRef> suiteAssets(bool full_suite) {
  std::vector<AssetRef> assets = bundledAssets();
  if (!full_suite) {
    std::erase_if(assets, [](const AssetRef& asset) {
      return asset.name.rfind(kFullSuiteAssetFolder, 0) == 0;
    });
    return assets;
  }
  for (AssetRef& asset : productionAssets()) assets.push_back(std::move(asset));
  return assets;
}

AssetRef resolveAsset(const std::string& name_or_path) {
  const std::vector<AssetRef> bundled = bundledAssets();
  if (const AssetRef* asset = findBundled(bundled, name_or_path)) return *asset;
  if (name_or_path.rfind("production/", 0) == 0) {
    for (const AssetRef& asset : productionAssets()) {
      if (asset.name == name_or_path) return asset;
    }
  }
  std::error_code error;
  if (fs::is_regular_file(name_or_path, error)) return {name_or_path, name_or_path, ""};
  if (fs::is_directory(name_or_path, error)) {
    throw mesh::InputError(
        name_or_path, "",
        "is a folder; --asset takes one .obj, .gltf or .glb file (repeat --asset for more)");
  }
  throw mesh::InputError(name_or_path, "",
                         "no such file, and not a bundled asset (see `tessbench list assets`)");
}

}  // namespace tb::suite
