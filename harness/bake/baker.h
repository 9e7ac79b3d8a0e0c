// The displacement baker (docs/derivations/displacement.md): a map for one technique's surface
// against a detailed target mesh. Scalar texels are the signed distance along the
// displacement direction (DisplacementFrame, techniques/common/displaced_patches.h: the
// technique's normals at the patch corners, interpolated, so that a displaced surface moves
// each point along the very ray it was baked on) to the target's nearest hit (Embree rays
// both ways); vector texels are
// the closest point of the target minus the surface point (Embree point queries).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/displacement/displacement_map.h"
#include "reference/triangle_mesh_ref.h"
#include "techniques/technique.h"

namespace tb::bake {

inline constexpr std::uint32_t kMaxBakeResolution = 1024;

struct BakeSettings {
  displacement::DisplacementKind kind = displacement::DisplacementKind::kScalar;
  // Texels per patch side, both edges included (2..kMaxBakeResolution): the first and last
  // lie on the patch's edges, so a patch's edges and corners sit on texel centres and
  // bilinear sampling is second order up to them; each tile adds `border` texels on every
  // side (copies of the edge, for filtering that reaches past it).
  std::uint32_t resolution = 16;
  displacement::DisplacementLayout layout =
      displacement::DisplacementLayout::kTiles;  // kUv is refused (not built yet)
  std::uint32_t border = 1;
  displacement::DisplacementPixelType pixel_type = displacement::DisplacementPixelType::kFloat;
};

struct BakeResult {
  displacement::DisplacementMap map;
  // Scalar: texels whose rays along +n and -n both missed the target (texel 0), plus texels
  // where the direction is zero. Vector: texels with a zero normal never count; 0 unless
  // the target is empty. Best 0, worst every baked texel.
  std::size_t rays_missed = 0;
  std::size_t texels_baked = 0;  // texels inside a patch's domain (the rest of a tile is 0)
  // Per channel, over the baked texels, world units (scalar: one channel).
  std::array<double, 3> value_min{0, 0, 0};
  std::array<double, 3> value_max{0, 0, 0};
  double length_max = 0;  // largest |texel| (vector length), world units
};

// The parameter of texel (x, y) of a tile (0 <= x, y < resolution + 2 border; y counts rows
// from the top of the tile): the texel centre u = (x - border) / (resolution - 1),
// v = (tile_size - 1 - y - border) / (resolution - 1), so v grows upwards, the interior
// texels span [0, 1] edge to edge, and a triangle patch (barycentric weights u, v, 1 - u - v
// of corners 0, 1, 2) owns the lower-left half u + v <= 1. Border texels lie one texel
// outside the domain (clamped back onto the edge when baked).
struct TexelParameter {
  double u = 0, v = 0;
};
TexelParameter texelParameter(std::uint32_t x, std::uint32_t y, const BakeSettings& settings);

// Bakes every patch of `patches` into a tile atlas (tiles_per_row = ceil(sqrt(patches))).
// Each texel centre of a tile, border included, is clamped into the patch's domain (a
// triangle's: u, v >= 0, u + v <= 1, by scaling) and evaluated in double; triangle tiles
// bake the texels whose centre has u + v <= 1 + border / (resolution - 1) and leave the rest 0.
// Patches run in parallel (TBB) into their own tiles, so the map does not depend on the
// thread count. Throws InputError for a resolution outside 2..kMaxBakeResolution, the uv
// layout ("not built yet"), an atlas wider or taller than kMaxDisplacementSide, and a target
// with bad indices or coordinates (named `target_source`).
BakeResult bakeDisplacement(const techniques::SurfacePatches& patches,
                            const ref::TriangleMeshRef& target, const BakeSettings& settings,
                            const std::string& target_source = "target mesh");

}  // namespace tb::bake
