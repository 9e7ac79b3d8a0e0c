#include "techniques/common/displaced_patches.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <utility>

#include "core/mesh/input_error.h"
#include "core/mesh/topology.h"

namespace tb::techniques {
namespace {

uint32_t cornerCountOf(PatchDomain domain) { return domain == PatchDomain::kQuad ? 4 : 3; }

// Domain coordinates of local corner k, as the tessellator emits them.
DomainCoord cornerCoord(PatchDomain domain, uint32_t corner) {
  if (domain == PatchDomain::kTriangle) {
    DomainCoord c{0, 0, 0};
    c[corner] = 1;
    return c;
  }
  static constexpr double kQuad[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return {kQuad[corner][0], kQuad[corner][1], 0};
}

template <class T>
std::array<T, 3> coordArray(const DomainCoord& c) {
  return {T(c[0]), T(c[1]), T(c[2])};
}

}  // namespace

const char* samplingName(DisplacementSampling sampling) {
  return sampling == DisplacementSampling::kNaive ? "naive" : "watertight";
}

TileGeometry tileGeometryOf(const displacement::DisplacementMap& map) {
  return {map.tiles.tile_size - 2 * map.tiles.border, map.tiles.border, map.tiles.tile_size,
          map.tiles.tiles_per_row};
}

std::vector<BoundaryOwners> boundaryOwners(const SurfacePatches& patches) {
  const size_t count = patches.patchCount();
  std::vector<BoundaryOwners> owners(count);
  // Positions with identical coordinates are one vertex (as the crack measure pairs them).
  const mesh::Welding welding = mesh::weldByPosition(patches.controlMesh());
  std::map<uint32_t, BoundaryOwners::Corner> corner_owner;  // position -> lowest patch
  // (lower position, higher position) -> the lowest patch's edge and its direction.
  struct EdgeOwner {
    uint32_t patch, edge, from;
  };
  std::map<std::pair<uint32_t, uint32_t>, EdgeOwner> edge_owner;
  for (size_t p = 0; p < count; ++p) {
    std::array<uint32_t, 4> c = patches.patchCorners(p);
    const uint32_t n = cornerCountOf(patches.patchDomain(p));
    for (uint32_t k = 0; k < n; ++k) c[k] = welding.canonical[c[k]];
    for (uint32_t k = 0; k < n; ++k) {
      const auto [it, first] =
          corner_owner.try_emplace(c[k], BoundaryOwners::Corner{uint32_t(p), k});
      owners[p].corners[k] = it->second;
      const uint32_t a = c[k], b = c[(k + 1) % n];
      const auto [edge, new_edge] =
          edge_owner.try_emplace({std::min(a, b), std::max(a, b)}, EdgeOwner{uint32_t(p), k, a});
      owners[p].edges[k] = {edge->second.patch, edge->second.edge, edge->second.from != a};
    }
  }
  return owners;
}

DisplacedPatches::DisplacedPatches(const SurfacePatches& inner,
                                   std::shared_ptr<const displacement::DisplacementMap> map,
                                   DisplacementSampling sampling, std::string map_name)
    : inner_(inner),
      map_(std::move(map)),
      sampling_(sampling),
      frame_(inner),
      warnings_(inner.warnings()) {
  if (map_->layout != displacement::DisplacementLayout::kTiles) {
    throw mesh::InputError(map_name, "", "a uv-layout map cannot displace patches (tiles only)");
  }
  if (map_->tiles.tile_count != inner.patchCount()) {
    throw mesh::InputError(map_name, "",
                           "the map has " + std::to_string(map_->tiles.tile_count) +
                               " tiles but the surface has " + std::to_string(inner.patchCount()) +
                               " patches (baked for another technique or asset?)");
  }
  if (map_->tiles.tile_size < 2 * map_->tiles.border + 1 || map_->tiles.tile_size < 2) {
    throw mesh::InputError(
        map_name, "",
        "tiles of " + std::to_string(map_->tiles.tile_size) + " texels are too small to sample");
  }
  geometry_ = tileGeometryOf(*map_);
  const uint32_t channels = displacement::channelCount(map_->kind);
  for (size_t i = 0; i < map_->texels.size(); i += channels) {
    double squared = 0;
    for (uint32_t c = 0; c < channels; ++c)
      squared += double(map_->texels[i + c]) * map_->texels[i + c];
    max_displacement_ = std::max(max_displacement_, std::sqrt(squared));
  }
  // Watertight sampling reads corners and edges from other tiles, so a patch's bound takes
  // the largest texel of its own tile and of every tile it reads.
  std::vector<double> own_max(map_->tiles.tile_count, 0);
  for (uint32_t tile = 0; tile < map_->tiles.tile_count; ++tile) {
    const uint32_t x0 = (tile % geometry_.tiles_per_row) * geometry_.tile_size;
    const uint32_t y0 = (tile / geometry_.tiles_per_row) * geometry_.tile_size;
    for (uint32_t y = 0; y < geometry_.tile_size; ++y) {
      for (uint32_t x = 0; x < geometry_.tile_size; ++x) {
        for (uint32_t c = 0; c < channels; ++c) {
          own_max[tile] = std::max(own_max[tile], double(std::abs(map_->at(x0 + x, y0 + y, c))));
        }
      }
    }
  }
  tile_max_.resize(inner.patchCount());
  for (size_t p = 0; p < inner.patchCount(); ++p) {
    double largest = own_max[p];
    for (const BoundaryOwners::Corner& corner : frame_.owners(p).corners) {
      largest = std::max(largest, own_max[corner.patch]);
    }
    for (const BoundaryOwners::Edge& edge : frame_.owners(p).edges) {
      largest = std::max(largest, own_max[edge.patch]);
    }
    tile_max_[p] = largest;
  }
  warnings_.push_back("displaced by " + map_name + " (" +
                      std::string(displacement::kindName(map_->kind)) + ", " +
                      samplingName(sampling) + " sampling)");
}

DisplacementFrame::DisplacementFrame(const SurfacePatches& patches)
    : patches_(patches), owners_(boundaryOwners(patches)) {
  const size_t count = patches.patchCount();
  const mesh::Welding welding = mesh::weldByPosition(patches.controlMesh());
  std::map<uint32_t, mesh::Vec3d> position_dir;
  corner_dirs_.resize(count);
  corner_dirs_float_.resize(count);
  for (size_t p = 0; p < count; ++p) {
    const PatchDomain domain = patches.patchDomain(p);
    const std::array<uint32_t, 4> c = patches.patchCorners(p);
    for (uint32_t k = 0; k < cornerCountOf(domain); ++k) {
      const uint32_t vertex = welding.canonical[c[k]];
      auto it = position_dir.find(vertex);
      if (it == position_dir.end()) {
        it = position_dir.emplace(vertex, patches.evaluate(p, cornerCoord(domain, k)).normal).first;
      }
      corner_dirs_[p][k] = it->second;
      corner_dirs_float_[p][k] = vecCast<float>(it->second);
    }
  }
}

mesh::Vec3d DisplacementFrame::direction(size_t patch, const DomainCoord& coord) const {
  return displacementDirection(patches_.patchDomain(patch), owners_[patch], corner_dirs_[patch],
                               coordArray<double>(coord));
}

SurfacePoint DisplacedPatches::evaluate(size_t patch, const DomainCoord& coord) const {
  SurfacePoint point = inner_.evaluate(patch, coord);
  const PatchDomain domain = inner_.patchDomain(patch);
  const auto c = coordArray<double>(coord);
  const TileCoord<double> at = lookupCoord(uint32_t(patch), domain, frame_.owners(patch), sampling_,
                                           c, [this](uint32_t q) { return inner_.patchDomain(q); });
  double h[3] = {0, 0, 0};
  sampleTile(*map_, geometry_, at.tile, at.u, at.v, displacement::channelCount(map_->kind), h);
  if (map_->kind == displacement::DisplacementKind::kScalar) {
    point.position = point.position + frame_.direction(patch, coord) * h[0];
  } else {
    point.position = point.position + mesh::Vec3d{h[0], h[1], h[2]};
  }
  return point;
}

SurfacePointF DisplacedPatches::evaluateFloat(size_t patch, const tess::DomainPoint& coord) const {
  SurfacePointF point = inner_.evaluateFloat(patch, coord);
  const PatchDomain domain = inner_.patchDomain(patch);
  const std::array<float, 3> c{coord[0], coord[1], coord[2]};
  const TileCoord<float> at = lookupCoord(uint32_t(patch), domain, frame_.owners(patch), sampling_,
                                          c, [this](uint32_t q) { return inner_.patchDomain(q); });
  float h[3] = {0, 0, 0};
  sampleTile(*map_, geometry_, at.tile, at.u, at.v, displacement::channelCount(map_->kind), h);
  if (map_->kind == displacement::DisplacementKind::kScalar) {
    const mesh::Vec3f dir =
        displacementDirection(domain, frame_.owners(patch), frame_.cornerDirectionsFloat(patch), c);
    point.position = point.position + dir * h[0];
  } else {
    point.position = point.position + mesh::Vec3f{h[0], h[1], h[2]};
  }
  return point;
}

std::optional<PatchCullBounds> DisplacedPatches::cullBounds(size_t patch) const {
  std::optional<PatchCullBounds> inner = inner_.cullBounds(patch);
  if (!inner) return std::nullopt;
  const double r = tile_max_[patch];
  PatchCullBounds grown;
  for (const mesh::Vec3d& point : inner->hull) {
    for (int corner = 0; corner < 8; ++corner) {
      grown.hull.push_back(
          point + mesh::Vec3d{corner & 1 ? r : -r, corner & 2 ? r : -r, corner & 4 ? r : -r});
    }
  }
  return grown;
}

DataFootprint DisplacedPatches::footprint() const {
  DataFootprint footprint = inner_.footprint();
  footprint.displacement_map_bytes = displacement::gpuResidentBytes(*map_);
  // The per-patch owner and direction words the displaced TES reads.
  footprint.patch_data_bytes += uint64_t(patchCount()) * kDisplacePatchWords * 4;
  return footprint;
}

std::vector<gpu::GpuPatchProgram> DisplacedPatches::gpuPrograms() const {
  std::vector<gpu::GpuPatchProgram> programs = inner_.gpuPrograms();
  if (programs.empty()) return programs;
  auto texels = std::make_shared<const std::vector<std::byte>>(displacement::gpuTexelBytes(*map_));
  for (gpu::GpuPatchProgram& program : programs) {
    auto displacement = std::make_shared<gpu::GpuDisplacement>();
    displacement->width = map_->width;
    displacement->height = map_->height;
    displacement->channels = map_->kind == displacement::DisplacementKind::kScalar ? 1 : 4;
    displacement->bytes_per_channel =
        map_->pixel_type == displacement::DisplacementPixelType::kHalf ? 2 : 4;
    displacement->texels = texels;
    displacement->kind = map_->kind == displacement::DisplacementKind::kScalar ? 1 : 2;
    displacement->sampling = sampling_ == DisplacementSampling::kNaive ? 0 : 1;
    std::vector<uint32_t>& words = displacement->patch_words;
    gpu::layout::appendWords(
        words, gpu::layout::TbDisplaceHeader{geometry_.resolution, geometry_.border,
                                             geometry_.tile_size, geometry_.tiles_per_row});
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      const uint32_t p = program.patch_ids.empty() ? i : program.patch_ids[i];
      const BoundaryOwners& owners = frame_.owners(p);
      auto triangleBit = [this](uint32_t q) {
        return inner_.patchDomain(q) == PatchDomain::kTriangle ? 1u << 8 : 0u;
      };
      gpu::layout::TbDisplacePatch record{};
      record.tile = p;
      for (size_t c = 0; c < 4; ++c) {
        const BoundaryOwners::Corner& corner = owners.corners[c];
        record.corner[c][0] = corner.patch;
        record.corner[c][1] = corner.corner | triangleBit(corner.patch);
      }
      for (size_t e = 0; e < 4; ++e) {
        const BoundaryOwners::Edge& edge = owners.edges[e];
        record.edge[e][0] = edge.patch;
        record.edge[e][1] = edge.edge | triangleBit(edge.patch);
        record.edge[e][2] = edge.reversed ? 1u : 0u;
      }
      for (size_t c = 0; c < 4; ++c) {
        const mesh::Vec3f& dir = frame_.cornerDirectionsFloat(p)[c];
        for (int k = 0; k < 3; ++k) record.direction_bits[c][k] = std::bit_cast<uint32_t>(dir[k]);
      }
      gpu::layout::appendWords(words, record);
    }
    program.evaluation_shader += "#displaced";
    program.displacement = std::move(displacement);
  }
  return programs;
}

}  // namespace tb::techniques
