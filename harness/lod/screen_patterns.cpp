#include "harness/lod/screen_patterns.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "core/tess/factor_helpers.h"

namespace tb::lod {
namespace {

tess::Domain tessDomain(techniques::PatchDomain domain) {
  return domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle;
}

void tessellatePattern(ScreenPattern* pattern) {
  const ScreenPatternKey& key = pattern->key;
  tess::Levels levels;
  for (int i = 0; i < 4; ++i) levels.outer[i] = std::bit_cast<float>(key.levels[i]);
  for (int i = 0; i < 2; ++i) levels.inner[i] = std::bit_cast<float>(key.levels[4 + i]);
  const tess::Domain domain = tessDomain(key.domain);
  const tess::Tessellation t =
      key.spacing == tess::Spacing::kPow2
          ? tess::tessellate(domain, tess::Spacing::kInteger, tess::roundPow2Levels(domain, levels))
          : tess::tessellate(domain, key.spacing, levels);
  pattern->tessellated = true;
  pattern->culled = t.culled || t.points.empty() || t.triangles.empty();
  if (pattern->culled) return;
  pattern->triangles = t.triangles;
  pattern->vertex_coords.reserve(t.points.size());
  for (const tess::DomainPoint& p : t.points) {
    // gl_TessCoord as the technique takes it (batch_eval.h): quads (u, v, 0), triangles
    // the barycentric (u, v, w) of corners 0, 1, 2, as the crack measure passes it.
    pattern->vertex_coords.push_back(key.domain == techniques::PatchDomain::kQuad
                                         ? techniques::DomainCoord{p[0], p[1], 0}
                                         : techniques::DomainCoord{p[0], p[1], p[2]});
  }
}

// Sorted by (lower, higher) end: a counting sort on the lower end, then each vertex's few
// higher ends sorted and deduplicated in place.
void buildEdges(ScreenPattern* pattern) {
  const size_t vertices = pattern->vertexCount();
  std::vector<uint32_t> start(vertices + 1, 0);
  for (const auto& t : pattern->triangles) {
    for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  }
  for (size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> higher(start[vertices]);
  std::vector<uint32_t> next(start.begin(), start.end() - 1);
  for (const auto& t : pattern->triangles) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      higher[next[std::min(a, b)]++] = std::max(a, b);
    }
  }
  pattern->edges.clear();
  pattern->edges.reserve(higher.size() / 2 + vertices);
  for (uint32_t v = 0; v < vertices; ++v) {
    const auto first = higher.begin() + start[v], last = higher.begin() + start[v + 1];
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it == first || *it != *(it - 1)) pattern->edges.push_back({v, *it});
    }
  }
}

techniques::DomainCoord blendCoord(const std::vector<techniques::DomainCoord>& vertices,
                                   const VertexBlend& blend) {
  techniques::DomainCoord c{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) c[i] += blend.weight[k] * vertices[blend.index[k]][i];
  }
  return c;
}

void buildSamples(ScreenPattern* pattern) {
  pattern->samples.clear();
  pattern->samples.reserve(pattern->edges.size() + pattern->triangles.size());
  for (const auto& e : pattern->edges) {
    pattern->samples.push_back({{e[0], e[1], e[0]}, {0.5, 0.5, 0}});
  }
  for (const auto& t : pattern->triangles) {
    pattern->samples.push_back({{t[0], t[1], t[2]}, {1.0 / 3, 1.0 / 3, 1.0 / 3}});
  }
}

// The batch pattern of the vertices, followed by the samples when there are any.
void buildPoints(const techniques::SurfacePatches& patches, ScreenPattern* pattern,
                 bool technique_kernel) {
  static std::atomic<uint64_t> next_serial{1};
  pattern->points_serial = next_serial.fetch_add(1);
  std::vector<techniques::DomainCoord> coords;
  coords.reserve(pattern->vertexCount() + pattern->samples.size());
  coords.insert(coords.end(), pattern->vertex_coords.begin(), pattern->vertex_coords.end());
  for (const VertexBlend& s : pattern->samples) {
    coords.push_back(blendCoord(pattern->vertex_coords, s));
  }
  if (!technique_kernel) {
    pattern->points = std::make_unique<techniques::BatchPattern>(
        pattern->key.domain, std::move(coords), techniques::BatchOutput::kPositions);
    return;
  }
  pattern->points = patches.makeBatchPattern(pattern->key.domain, std::move(coords),
                                             techniques::BatchOutput::kPositions);
}

// Each lattice point in the first triangle that contains it (barycentric weights >= -1e-9;
// domain coordinates are multiples of 2^-16 and the lattice's of 1/8, so the weights are
// nearly exact). Only lattice points inside a triangle's bounding box are tested.
void buildLattice(ScreenPattern* pattern) {
  const int n = kPopSampleSegments;
  const bool quad = pattern->key.domain == techniques::PatchDomain::kQuad;
  const std::vector<techniques::DomainCoord> lattice =
      techniques::latticeCoords(pattern->key.domain, n);
  // Index of lattice point (i, j), in latticeCoords' order (j-major rows).
  std::vector<int> row_start(n + 2, 0);
  for (int j = 0; j <= n; ++j) row_start[j + 1] = row_start[j] + (quad ? n + 1 : n - j + 1);
  std::vector<VertexBlend> located(lattice.size());
  std::vector<uint8_t> found(lattice.size(), 0);
  const std::vector<techniques::DomainCoord>& v = pattern->vertex_coords;
  constexpr double kSlack = 1e-9;
  for (const auto& t : pattern->triangles) {
    const double u0 = v[t[0]][0], v0 = v[t[0]][1];
    const double e1u = v[t[1]][0] - u0, e1v = v[t[1]][1] - v0;
    const double e2u = v[t[2]][0] - u0, e2v = v[t[2]][1] - v0;
    const double det = e1u * e2v - e1v * e2u;
    if (det == 0) continue;  // degenerate: its points belong to a neighbour
    double min_u = 1, max_u = 0, min_v = 1, max_v = 0;
    for (int k = 0; k < 3; ++k) {
      min_u = std::min(min_u, v[t[k]][0]), max_u = std::max(max_u, v[t[k]][0]);
      min_v = std::min(min_v, v[t[k]][1]), max_v = std::max(max_v, v[t[k]][1]);
    }
    const int i_lo = std::max(0, int(std::ceil(min_u * n - kSlack)));
    const int i_hi = std::min(n, int(std::floor(max_u * n + kSlack)));
    const int j_lo = std::max(0, int(std::ceil(min_v * n - kSlack)));
    const int j_hi = std::min(n, int(std::floor(max_v * n + kSlack)));
    for (int j = j_lo; j <= j_hi; ++j) {
      for (int i = i_lo; i <= i_hi && (quad || i + j <= n); ++i) {
        const int index = row_start[j] + i;
        if (found[index]) continue;
        const double qu = double(i) / n - u0, qv = double(j) / n - v0;
        const double l1 = (qu * e2v - qv * e2u) / det, l2 = (e1u * qv - e1v * qu) / det;
        const double l0 = 1 - l1 - l2;
        if (std::min({l0, l1, l2}) < -kSlack) continue;
        located[index] = {{t[0], t[1], t[2]}, {l0, l1, l2}};
        found[index] = 1;
      }
    }
  }
  if (std::find(found.begin(), found.end(), 0) != found.end()) {
    throw std::logic_error("screen metrics: a pop lattice point lies in no tessellated triangle");
  }
  pattern->lattice = std::move(located);
}

}  // namespace

ScreenPatternKey screenPatternKey(techniques::PatchDomain domain, tess::Spacing spacing,
                                  const tess::Levels& levels) {
  return {domain, spacing, tess::levelsBits(levels)};
}

void completeScreenPattern(const techniques::SurfacePatches& patches, unsigned parts,
                           ScreenPattern* pattern, bool technique_kernel) {
  if (!pattern->tessellated) tessellatePattern(pattern);
  if (!pattern->culled) {
    const unsigned missing = parts & ~pattern->parts;
    if ((missing & (kPatternEdges | kPatternSamples)) && !(pattern->parts & kPatternEdges)) {
      buildEdges(pattern);
      pattern->parts |= kPatternEdges;
    }
    if (missing & kPatternLattice) buildLattice(pattern);
    if (missing & kPatternSamples) buildSamples(pattern);
    // A pattern of the vertices alone is replaced by one with the samples appended.
    if (!pattern->points || (missing & kPatternSamples))
      buildPoints(patches, pattern, technique_kernel);
  }
  pattern->parts |= parts;
}

size_t estimateScreenPatternPoints(techniques::PatchDomain domain, const tess::Levels& levels) {
  const bool quad = domain == techniques::PatchDomain::kQuad;
  float largest = 1;
  auto take = [&](float level) {
    if (level > largest) largest = std::min(level, 64.0f);  // NaN and culling levels: 1
  };
  for (int i = 0; i < (quad ? 4 : 3); ++i) take(levels.outer[i]);
  for (int i = 0; i < (quad ? 2 : 1); ++i) take(levels.inner[i]);
  // Fractional spacings round up to the next odd or even segment count.
  const size_t n = size_t(std::ceil(largest)) + 2;
  // A quad at n segments: (n + 1)^2 vertices, 2 n^2 triangles, about 3 n^2 edges.
  return (quad ? 6 : 3) * (n + 1) * (n + 1);
}

ScreenPatternCache::ScreenPatternCache(const techniques::SurfacePatches& patches, size_t max_points)
    : patches_(patches), max_points_(max_points) {}

std::vector<const ScreenPattern*> ScreenPatternCache::acquire(
    std::span<const ScreenPatternKey> keys, unsigned parts, bool technique_kernels) {
  size_t held = 0;
  for (const auto& [key, pattern] : patterns_) held += pattern->patternPoints();
  if (held > max_points_) {
    const std::set<ScreenPatternKey> wanted(keys.begin(), keys.end());
    std::erase_if(patterns_, [&](const auto& entry) { return !wanted.contains(entry.first); });
  }
  std::vector<ScreenPattern*> found(keys.size());
  std::vector<size_t> to_build;
  for (size_t i = 0; i < keys.size(); ++i) {
    std::unique_ptr<ScreenPattern>& slot = patterns_[keys[i]];
    if (!slot) {
      slot = std::make_unique<ScreenPattern>();
      slot->key = keys[i];
    }
    found[i] = slot.get();
    if (!slot->tessellated || (parts & ~slot->parts) != 0) to_build.push_back(i);
  }
  // Distinct keys, so each task completes its own pattern.
  tbb::parallel_for(size_t(0), to_build.size(), [&](size_t k) {
    completeScreenPattern(patches_, parts, found[to_build[k]], technique_kernels);
  });
  return {found.begin(), found.end()};
}

}  // namespace tb::lod
