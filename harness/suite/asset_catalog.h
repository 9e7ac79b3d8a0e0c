// Bundled assets (assets/**/*.obj, *.gltf, *.glb) and how a name or path on the command line
// resolves to one.
#pragma once

#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::suite {

struct AssetRef {
  std::string name;  // "opensubdiv/catmark_cube" for bundled assets, the path otherwise
  std::string path;  // file to load
  // How results and messages name the file: "assets/opensubdiv/catmark_cube.obj" for a
  // bundled asset, whatever folder the checkout is in (so results do not depend on it);
  // empty for a path given by the user, which is shown as given.
  std::string label;
  // Uniform refinement steps applied at load (loadAsset): 0 for a file as it is. A refined
  // asset is refined by OpenSubdiv with its creases, corners, holes and boundary rule
  // (osd::refineUniform), Loop for an all-triangle mesh and Catmull-Clark otherwise, so it
  // has the same limit surface with 4^refine times the faces.
  int refine = 0;
  const std::string& shownPath() const { return label.empty() ? path : label; }
};

// The mesh of an asset: the OBJ or glTF at `path`, refined `refine` times. Throws InputError as
// loadObjFile and loadGltfFile do. Deterministic: the same file and count give the same mesh.
mesh::Mesh loadAsset(const AssetRef& asset);

// The most refinement steps `--refine` and the production list accept: each step multiplies
// the faces by 4 (a 100-face mesh at 6 steps is 410k faces).
inline constexpr int kMaxRefine = 6;

// `asset` refined `levels` more times: named "<name>@refine<total>", its label saying so.
// Throws InputError for a count outside 1..kMaxRefine (in all).
AssetRef refinedAsset(AssetRef asset, int levels);

// The assets folder: $TB_ASSETS_DIR when set, else the source tree's assets/.
std::string assetsDirectory();

// Every bundled .obj, .gltf and .glb, sorted by name.
std::vector<AssetRef> bundledAssets();

// The folder of bundled assets too costly for the default suite (assets/full_suite/README.md):
// `run --suite full` runs them, the default suite leaves them out unless named.
inline constexpr const char* kFullSuiteAssetFolder = "full_suite/";
// The production-size assets (assets/production/assets.json): bundled shapes refined at load
// to 5k-40k faces with their creases, named "production/<name>". The full suite runs them;
// `--asset production/<name>` runs one. Throws InputError naming the file, entry and field
// of a malformed list.
std::vector<AssetRef> productionAssets();

// The bundled assets a suite runs when none is named: every one (and the production assets)
// for the full suite, all but the full-suite folder's for the default suite.
std::vector<AssetRef> suiteAssets(bool full_suite);

// A bundled name ("catmark_cube" or "opensubdiv/catmark_cube"), a production asset's
// ("production/catmark_pawn_r2") or a path to an .obj. Throws InputError naming the argument
// when it is none of them (a folder is named as a folder).
AssetRef resolveAsset(const std::string& name_or_path);

}  // namespace tb::suite
