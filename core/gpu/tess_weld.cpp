#include "core/gpu/tess_weld.h"

#include <bit>
#include <unordered_map>

#include "core/gpu/gpu_error.h"

namespace tb::gpu {
namespace {

struct CoordBitsHash {
  size_t operator()(const CoordBits& c) const {
    uint64_t h = c[0];
    h = h * 0x9E3779B97F4A7C15ull ^ c[1];
    h = h * 0x9E3779B97F4A7C15ull ^ c[2];
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

}  // namespace

tess::Tessellation weldCapture(std::span<const CoordBits> vertices,
                               uint32_t vertices_per_primitive) {
  if (vertices_per_primitive < 1 || vertices_per_primitive > 3 ||
      vertices.size() % vertices_per_primitive != 0) {
    throw GpuError("captured vertex count is not a whole number of primitives");
  }
  tess::Tessellation result;
  std::unordered_map<CoordBits, uint32_t, CoordBitsHash> index_of;
  index_of.reserve(vertices.size());
  std::vector<uint32_t> indices;
  indices.reserve(vertices.size());
  for (const CoordBits& bits : vertices) {
    const auto [it, inserted] =
        index_of.try_emplace(bits, static_cast<uint32_t>(result.points.size()));
    if (inserted) {
      result.points.push_back({std::bit_cast<float>(bits[0]), std::bit_cast<float>(bits[1]),
                               std::bit_cast<float>(bits[2])});
    }
    indices.push_back(it->second);
  }
  if (vertices_per_primitive == 3) {
    for (size_t i = 0; i < indices.size(); i += 3) {
      result.triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
    }
  } else if (vertices_per_primitive == 2) {
    for (size_t i = 0; i < indices.size(); i += 2) {
      result.lines.push_back({indices[i], indices[i + 1]});
    }
  }
  return result;
}

}  // namespace tb::gpu
