// Any surface technique's patches with a displacement map applied after evaluation
// (docs/derivations/displacement.md): position + direction * h for a scalar map,
// position + V for a vector map, sampled naively or watertight (displacement_sampling.h).
// The GPU side is the same technique's TES compiled with shaders/common/displace.glsl
// (embedded as "<tese>#displaced"), which its tbEmitVertex calls; evaluateFloat is its twin.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/displacement/displacement_map.h"
#include "shaders/common/layout/displace_layout.h"
#include "techniques/common/displacement_sampling.h"
#include "techniques/technique.h"

namespace tb::techniques {

// The GPU words of one program patch in TbDisplacePatches (shaders/common/displace.glsl),
// after a 4-word header (resolution, border, tile_size, tiles_per_row): own tile, 4 corners
// (owner tile, owner corner | owner is a triangle << 8), 4 edges (owner tile, owner edge |
// triangle << 8, reversed), 4 corner directions (x, y, z float bits).
// (shaders/common/layout/displace_layout.h TbDisplaceHeader, TbDisplacePatch.)
inline constexpr size_t kDisplaceHeaderWords = gpu::layout::kWordsOf<gpu::layout::TbDisplaceHeader>;
inline constexpr size_t kDisplacePatchWords = gpu::layout::kWordsOf<gpu::layout::TbDisplacePatch>;

// The owners of every shared corner and edge of a surface and its displacement directions:
// one unit direction per welded control-mesh position, the technique's normal there taken
// from the lowest patch at that corner, so every patch sees the same one; inside a patch
// they are interpolated (displacementDirection). The baker casts its rays along these, and
// DisplacedPatches moves scalar texels along them.
class DisplacementFrame {
 public:
  explicit DisplacementFrame(const SurfacePatches& patches);
  const BoundaryOwners& owners(size_t patch) const { return owners_[patch]; }
  const std::array<mesh::Vec3f, 4>& cornerDirectionsFloat(size_t patch) const {
    return corner_dirs_float_[patch];
  }
  // The unit direction of patch `patch` at `coord`, double.
  mesh::Vec3d direction(size_t patch, const DomainCoord& coord) const;

 private:
  const SurfacePatches& patches_;
  std::vector<BoundaryOwners> owners_;                         // per patch
  std::vector<std::array<mesh::Vec3d, 4>> corner_dirs_;        // per patch, unit, double
  std::vector<std::array<mesh::Vec3f, 4>> corner_dirs_float_;  // the same rounded to float
};

class DisplacedPatches final : public SurfacePatches {
 public:
  // Throws InputError (naming `map_name`) when the map is not a per-patch tile atlas with
  // one tile per patch of `inner`.
  DisplacedPatches(const SurfacePatches& inner,
                   std::shared_ptr<const displacement::DisplacementMap> map,
                   DisplacementSampling sampling, std::string map_name);

  PatchDomain patchDomain(size_t patch) const override { return inner_.patchDomain(patch); }
  LimitScheme approximates() const override { return inner_.approximates(); }
  size_t patchCount() const override { return inner_.patchCount(); }
  const mesh::Mesh& controlMesh() const override { return inner_.controlMesh(); }
  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    return inner_.patchCorners(patch);
  }
  uint32_t sourceFace(size_t patch) const override { return inner_.sourceFace(patch); }
  // The displaced position; the normal is the undisplaced surface's (the displaced
  // surface's own normal would come from the map's derivatives, not built).
  SurfacePoint evaluate(size_t patch, const DomainCoord& coord) const override;
  SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& coord) const override;
  // The technique's programs with "#displaced" evaluation shaders and the map attached.
  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override;
  // The undisplaced patch's hull grown by the largest displacement its tile holds (each hull
  // point replaced by the 8 corners of a cube of that half-size around it: the Minkowski sum
  // with the cube contains every displaced point, since |d h| <= the tile's largest |texel|
  // per axis); no normal generators (displacement turns the normals anywhere). The culling
  // measure's per-patch bound input. nullopt where the technique gives no bounds.
  std::optional<PatchCullBounds> cullBounds(size_t patch) const override;
  // None: the displacement (a bilinear blend of texels along the shading normal) changes the
  // second derivatives by terms no cheap bound of the map covers, so the error_bound policy
  // skips displaced surfaces (it must not read the undisplaced patch's net, which the
  // default would).
  std::optional<CurvatureBounds> curvatureBounds(size_t patch) const override {
    (void)patch;
    return std::nullopt;
  }
  // The technique's bytes plus the map's GPU-resident bytes and the owner words.
  DataFootprint footprint() const override;
  // The largest |texel| component in patch `patch`'s tile (world units): a bilinear blend
  // of the tile's texels never exceeds it.
  double tileMaxDisplacement(size_t patch) const { return tile_max_[patch]; }
  const std::vector<std::string>& warnings() const override { return warnings_; }

  const displacement::DisplacementMap& map() const { return *map_; }
  DisplacementSampling sampling() const { return sampling_; }
  const DisplacementFrame& frame() const { return frame_; }
  // The largest |displacement| the map holds (world units): a scalar map's largest |h|, a
  // vector map's longest V. Best 0.
  double maxDisplacement() const { return max_displacement_; }

 private:
  const SurfacePatches& inner_;
  std::shared_ptr<const displacement::DisplacementMap> map_;
  DisplacementSampling sampling_;
  DisplacementFrame frame_;
  TileGeometry geometry_;
  double max_displacement_ = 0;
  std::vector<double> tile_max_;  // per patch
  std::vector<std::string> warnings_;
};

// Builds the owner of every shared corner and edge of `patches` (BoundaryOwners).
std::vector<BoundaryOwners> boundaryOwners(const SurfacePatches& patches);

}  // namespace tb::techniques
