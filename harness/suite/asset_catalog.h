// Bundled assets (assets/**/*.obj) and how a name or path on the command line
// resolves to one.
#pragma once

#include <string>
#include <vector>

namespace tb::suite {

struct AssetRef {
  std::string name;  // "opensubdiv/catmark_cube" for bundled assets, the path otherwise
  std::string path;  // file to load
  // How results and messages name the file: "assets/opensubdiv/catmark_cube.obj" for a
  // bundled asset, whatever folder the checkout is in (so results do not depend on it);
  // empty for a path given by the user, which is shown as given.
  std::string label;
  const std::string& shownPath() const { return label.empty() ? path : label; }
};

// The assets folder: $TB_ASSETS_DIR when set, else the source tree's assets/.
std::string assetsDirectory();

// Every bundled .obj, sorted by name.
std::vector<AssetRef> bundledAssets();

// The folder of bundled assets too costly for the default suite (assets/full_suite/README.md):
// `run --suite full` runs them, the default suite leaves them out unless named.
inline constexpr const char* kFullSuiteAssetFolder = "full_suite/";
// The bundled assets a suite runs when none is named: every one for the full suite, all but
// the full-suite folder's for the default suite.
std::vector<AssetRef> suiteAssets(bool full_suite);

// A bundled name ("catmark_cube" or "opensubdiv/catmark_cube") or a path to an
// .obj. Throws InputError naming the argument when it is neither.
AssetRef resolveAsset(const std::string& name_or_path);

}  // namespace tb::suite
