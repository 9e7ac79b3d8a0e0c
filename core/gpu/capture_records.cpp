// The capture's 10-word records as CapturedVertex, and their canonical order: shared by the
// hardware path (patch_program.cpp) and the compute path (compute_path.cpp).
#include <algorithm>
#include <array>
#include <bit>
#include <string>

#include "core/gpu/gpu_error.h"
#include "core/gpu/patch_program.h"

namespace tb::gpu {
namespace {

using RecordCoordKey = std::array<uint32_t, 3>;
RecordCoordKey recordCoordKey(const CapturedVertex& v) {
  return {std::bit_cast<uint32_t>(v.coord[0]), std::bit_cast<uint32_t>(v.coord[1]),
          std::bit_cast<uint32_t>(v.coord[2])};
}

}  // namespace

void appendCaptureRecords(std::span<const uint32_t> words, std::span<const uint32_t> patch_ids,
                          std::vector<CapturedVertex>* vertices) {
  const size_t count = words.size() / kCaptureRecordWords;
  vertices->reserve(vertices->size() + count);
  for (size_t i = 0; i < count; ++i) {
    const uint32_t* w = &words[i * kCaptureRecordWords];
    CapturedVertex v;
    if (!patch_ids.empty() && w[0] >= patch_ids.size()) {
      throw GpuError("capture record of program patch " + std::to_string(w[0]) + ", beyond its " +
                     std::to_string(patch_ids.size()) + " patch ids");
    }
    v.patch = patch_ids.empty() ? w[0] : patch_ids[w[0]];
    for (int k = 0; k < 3; ++k) v.coord[k] = std::bit_cast<float>(w[1 + k]);
    v.position = {std::bit_cast<float>(w[4]), std::bit_cast<float>(w[5]),
                  std::bit_cast<float>(w[6])};
    v.normal = {std::bit_cast<float>(w[7]), std::bit_cast<float>(w[8]), std::bit_cast<float>(w[9])};
    vertices->push_back(v);
  }
}

// A counting sort by patch (a capture holds a contiguous range of patches), then each
// patch's vertices by coordinate bits.
void sortUniqueVertices(std::vector<CapturedVertex>* vertices) {
  if (vertices->empty()) return;
  const auto [lo, hi] = std::minmax_element(
      vertices->begin(), vertices->end(),
      [](const CapturedVertex& a, const CapturedVertex& b) { return a.patch < b.patch; });
  const uint32_t first = lo->patch;
  const size_t range = size_t(hi->patch) - first + 1;
  std::vector<size_t> start(range + 1, 0);
  for (const CapturedVertex& v : *vertices) ++start[v.patch - first + 1];
  for (size_t p = 0; p < range; ++p) start[p + 1] += start[p];
  std::vector<CapturedVertex> sorted(vertices->size());
  std::vector<size_t> next(start.begin(), start.end() - 1);
  for (const CapturedVertex& v : *vertices) sorted[next[v.patch - first]++] = v;
  auto by_coord = [](const CapturedVertex& a, const CapturedVertex& b) {
    return recordCoordKey(a) < recordCoordKey(b);
  };
  for (size_t p = 0; p < range; ++p) {
    std::sort(sorted.begin() + start[p], sorted.begin() + start[p + 1], by_coord);
  }
  sorted.erase(std::unique(sorted.begin(), sorted.end(),
                           [](const CapturedVertex& a, const CapturedVertex& b) {
                             return a.patch == b.patch && recordCoordKey(a) == recordCoordKey(b);
                           }),
               sorted.end());
  *vertices = std::move(sorted);
}

}  // namespace tb::gpu
