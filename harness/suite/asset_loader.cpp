// loadAsset (asset_catalog.h): apart from the catalogue, so the fuzz build's catalogue needs
// no OpenSubdiv.
#include "core/mesh/gltf_loader.h"
#include "core/mesh/normals.h"
#include "core/mesh/obj_loader.h"
#include "core/osd/uniform_refinement.h"
#include "harness/suite/asset_catalog.h"

namespace tb::suite {

mesh::Mesh loadAsset(const AssetRef& asset) {
  mesh::Mesh mesh =
      mesh::isGltfPath(asset.path) ? mesh::loadGltfFile(asset.path) : mesh::loadObjFile(asset.path);
  if (asset.refine == 0) return mesh;
  const bool triangles = mesh.allFacesOfSize(3);
  mesh::Mesh refined = osd::refineUniform(
      mesh, triangles ? osd::Scheme::kLoop : osd::Scheme::kCatmullClark, asset.refine);
  refined.source = asset.shownPath();
  // As the loader gives a file without normals (the refined mesh has none; the input's
  // would not fit its new vertices).
  mesh::assignAngleWeightedNormals(&refined);
  return refined;
}

}  // namespace tb::suite
