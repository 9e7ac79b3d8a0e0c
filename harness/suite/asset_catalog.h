// Bundled assets (assets/**/*.obj) and how a name or path on the command line
// resolves to one.
#pragma once

#include <string>
#include <vector>

namespace tb {

struct AssetRef {
  std::string name;  // "opensubdiv/catmark_cube" for bundled assets, the path otherwise
  std::string path;  // file to load
};

// The assets folder: $TB_ASSETS_DIR when set, else the source tree's assets/.
std::string assetsDirectory();

// Every bundled .obj, sorted by name.
std::vector<AssetRef> bundledAssets();

// A bundled name ("catmark_cube" or "opensubdiv/catmark_cube") or a path to an
// .obj. Throws InputError naming the argument when it is neither.
AssetRef resolveAsset(const std::string& name_or_path);

}  // namespace tb
