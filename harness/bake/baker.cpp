#include "harness/bake/baker.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/displacement/exr_io.h"
#include "core/mesh/input_error.h"
#include "reference/triangle_distance_field.h"
#include "reference/triangle_ray_caster.h"
#include "techniques/common/displaced_patches.h"

namespace tb::bake {
namespace {

// Clamps (u, v) into the patch domain: the unit square, or the triangle u, v >= 0,
// u + v <= 1 (scaled back onto the hypotenuse).
techniques::DomainCoord domainCoordOf(techniques::PatchDomain domain, TexelParameter t) {
  const double u = std::clamp(t.u, 0.0, 1.0), v = std::clamp(t.v, 0.0, 1.0);
  if (domain == techniques::PatchDomain::kQuad) return techniques::DomainCoord{u, v, 0};
  const double sum = u + v;
  if (sum <= 1) return techniques::DomainCoord{u, v, 1 - sum};
  return techniques::DomainCoord{u / sum, v / sum, 0};
}

struct Samplers {
  const ref::TriangleRayCaster* rays = nullptr;         // scalar bakes
  const ref::TriangleDistanceField* closest = nullptr;  // vector bakes
};

// One texel's channels; returns false when it missed the target. `direction`: the unit
// displacement direction at the point (scalar bakes).
bool bakeTexel(const techniques::SurfacePoint& point, const mesh::Vec3d& direction,
               const Samplers& samplers, uint32_t* hint, float* out) {
  if (samplers.closest != nullptr) {
    const ref::ClosestPoint hit = samplers.closest->closest(point.position, *hint);
    if (hit.triangle == ref::kNoTriangle) return false;
    *hint = hit.triangle;
    const mesh::Vec3d d = hit.point - point.position;
    for (int c = 0; c < 3; ++c) out[c] = float(d[c]);
    return true;
  }
  if (!(length(direction) > 0)) return false;
  const auto up = samplers.rays->nearestHit(point.position, direction);
  const auto down = samplers.rays->nearestHit(point.position, -1.0 * direction);
  if (!up && !down) return false;
  // The nearer hit; a tie goes to +n.
  if (up && (!down || up->distance <= down->distance)) {
    out[0] = float(up->distance);
  } else {
    out[0] = float(-down->distance);
  }
  return true;
}

}  // namespace

TexelParameter texelParameter(uint32_t x, uint32_t y, const BakeSettings& settings) {
  const double tile_size = double(settings.resolution + 2 * settings.border);
  const double step = double(settings.resolution - 1), border = double(settings.border);
  return {(double(x) - border) / step, (tile_size - 1 - double(y) - border) / step};
}

BakeResult bakeDisplacement(const techniques::SurfacePatches& patches,
                            const ref::TriangleMeshRef& target, const BakeSettings& settings,
                            const std::string& target_source) {
  if (settings.resolution < 2 || settings.resolution > kMaxBakeResolution) {
    throw mesh::InputError(
        "--resolution", std::to_string(settings.resolution),
        "texels per patch side must be 2 to " + std::to_string(kMaxBakeResolution));
  }
  if (settings.layout == displacement::DisplacementLayout::kUv) {
    throw mesh::InputError("--layout", "uv", "the uv layout is not built yet (use tiles)");
  }
  const size_t patch_count = patches.patchCount();
  if (patch_count == 0)
    throw mesh::InputError(patches.controlMesh().source, "", "no patches to bake");
  const uint32_t tile_size = settings.resolution + 2 * settings.border;
  const auto per_row = uint32_t(std::ceil(std::sqrt(double(patch_count))));
  const auto rows = uint32_t((patch_count + per_row - 1) / per_row);
  if (uint64_t(per_row) * tile_size > displacement::kMaxDisplacementSide ||
      uint64_t(rows) * tile_size > displacement::kMaxDisplacementSide) {
    throw mesh::InputError("--resolution", std::to_string(settings.resolution),
                           "the atlas of " + std::to_string(patch_count) + " tiles would exceed " +
                               std::to_string(displacement::kMaxDisplacementSide) +
                               " texels a side");
  }

  BakeResult result;
  displacement::DisplacementMap& map = result.map;
  map.kind = settings.kind;
  map.pixel_type = settings.pixel_type;
  map.layout = displacement::DisplacementLayout::kTiles;
  map.tiles = {tile_size, settings.border, per_row, uint32_t(patch_count)};
  map.width = per_row * tile_size;
  map.height = rows * tile_size;
  const uint32_t channels = displacement::channelCount(settings.kind);
  map.texels.assign(size_t(map.width) * map.height * channels, 0.0f);
  // 1: baked, 0: outside the patch's domain (triangle tiles' upper-right half).
  std::vector<uint8_t> baked(size_t(map.width) * map.height, 0);

  std::optional<ref::TriangleRayCaster> rays;
  std::optional<ref::TriangleDistanceField> closest;
  Samplers samplers;
  if (settings.kind == displacement::DisplacementKind::kScalar) {
    rays.emplace(target.positions, target.triangles, target_source);
    samplers.rays = &*rays;
  } else {
    closest.emplace(target.positions, target.triangles, target_source);
    samplers.closest = &*closest;
  }

  const techniques::DisplacementFrame frame(patches);
  std::vector<size_t> misses(patch_count, 0);
  const double slack = double(settings.border) / double(settings.resolution - 1);
  tbb::parallel_for(size_t(0), patch_count, [&](size_t p) {
    const techniques::PatchDomain domain = patches.patchDomain(p);
    const uint32_t x0 = uint32_t(p % per_row) * tile_size, y0 = uint32_t(p / per_row) * tile_size;
    uint32_t hint = ref::kNoTriangle;
    for (uint32_t y = 0; y < tile_size; ++y) {
      for (uint32_t x = 0; x < tile_size; ++x) {
        const TexelParameter t = texelParameter(x, y, settings);
        if (domain == techniques::PatchDomain::kTriangle && t.u + t.v > 1 + slack) continue;
        const size_t texel = size_t(y0 + y) * map.width + (x0 + x);
        baked[texel] = 1;
        const techniques::DomainCoord coord = domainCoordOf(domain, t);
        const techniques::SurfacePoint point = patches.evaluate(p, coord);
        const mesh::Vec3d direction = samplers.rays ? frame.direction(p, coord) : mesh::Vec3d{};
        if (!bakeTexel(point, direction, samplers, &hint, &map.texels[texel * channels])) {
          ++misses[p];
        }
      }
    }
  });

  for (size_t m : misses) result.rays_missed += m;
  if (settings.pixel_type == displacement::DisplacementPixelType::kHalf)
    displacement::roundTexelsToHalf(map);
  bool first = true;
  for (size_t texel = 0; texel < baked.size(); ++texel) {
    if (!baked[texel]) continue;
    ++result.texels_baked;
    double squared = 0;
    for (uint32_t c = 0; c < channels; ++c) {
      const double value = map.texels[texel * channels + c];
      result.value_min[c] = first ? value : std::min(result.value_min[c], value);
      result.value_max[c] = first ? value : std::max(result.value_max[c], value);
      squared += value * value;
    }
    result.length_max = std::max(result.length_max, std::sqrt(squared));
    first = false;
  }
  return result;
}

}  // namespace tb::bake
