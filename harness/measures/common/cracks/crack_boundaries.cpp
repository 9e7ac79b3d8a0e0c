#include "harness/measures/common/cracks/crack_boundaries.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <map>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace tb::measures {
namespace {

uint32_t cornerCount(techniques::PatchDomain domain) {
  return domain == techniques::PatchDomain::kQuad ? 4 : 3;
}

tess::Domain tessDomain(techniques::PatchDomain domain) {
  return domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle;
}

// The boundary points of `tessellation` in BoundaryTessellation order (points,
// edge_begin, edge_t).
void fillBoundary(techniques::PatchDomain domain, const tess::Tessellation& tessellation,
                  BoundaryTessellation* b) {
  const uint32_t corners = cornerCount(domain);
  b->points.assign(corners, tess::DomainPoint{});
  b->edge_t.assign(corners, 0);
  std::vector<bool> seen(corners, false);
  std::vector<std::vector<std::pair<int64_t, tess::DomainPoint>>> edge_points(corners);
  for (const tess::DomainPoint& p : tessellation.points) {
    for (uint32_t c = 0; c < corners; ++c) {
      if (isDomainCorner(domain, c, p)) {
        b->points[c] = p;
        seen[c] = true;
      }
    }
    for (uint32_t e = 0; e < corners; ++e) {
      const int64_t t = domainEdgeParameter(domain, e, p);
      if (t > 0 && t < kEdgeParameterOne) edge_points[e].emplace_back(t, p);
    }
  }
  if (std::find(seen.begin(), seen.end(), false) != seen.end()) {
    throw std::logic_error("cracks: the tessellation lacks a patch corner");
  }
  b->edge_begin.assign(1, corners);
  for (uint32_t e = 0; e < corners; ++e) {
    auto& points = edge_points[e];
    // Tessellation points are distinct, so no two share an edge parameter.
    std::sort(points.begin(), points.end(),
              [](const auto& a, const auto& c) { return a.first < c.first; });
    for (const auto& [t, p] : points) {
      b->points.push_back(p);
      b->edge_t.push_back(t);
    }
    b->edge_begin.push_back(uint32_t(b->points.size()));
  }
}

bool sameBoundary(const BoundaryTessellation& a, const BoundaryTessellation& b) {
  return a.edge_begin == b.edge_begin && a.points.size() == b.points.size() &&
         std::memcmp(a.points.data(), b.points.data(),
                     a.points.size() * sizeof(tess::DomainPoint)) == 0;
}

// The largest inner level kept for the capture: a ring well inside the outer one.
float captureInnerCap(tess::Spacing spacing) {
  switch (spacing) {
    case tess::Spacing::kFractionalOdd:
      return 3.0f;
    case tess::Spacing::kFractionalEven:
      return 2.0f;
    default:
      return 1.0f;
  }
}

BoundaryTessellation computeBoundary(techniques::PatchDomain domain, tess::Spacing spacing,
                                     const tess::Levels& levels) {
  BoundaryTessellation b;
  const tess::Tessellation full = tess::tessellate(tessDomain(domain), spacing, levels);
  b.culled = full.culled;
  b.tessellated_points = full.points.size();
  b.capture_levels = levels;
  b.capture_points = full.points.size();
  if (full.culled) return b;
  fillBoundary(domain, full, &b);

  tess::Levels lowered = levels;
  const float cap = captureInnerCap(spacing);
  for (float& inner : lowered.inner) inner = inner > cap ? cap : inner;
  if (tess::levelsBits(lowered) == tess::levelsBits(levels)) return b;
  const tess::Tessellation smaller = tess::tessellate(tessDomain(domain), spacing, lowered);
  if (smaller.culled) return b;
  BoundaryTessellation check;
  fillBoundary(domain, smaller, &check);
  if (sameBoundary(b, check)) {
    b.capture_levels = lowered;
    b.capture_points = smaller.points.size();
  }
  return b;
}

struct CacheKey {
  techniques::PatchDomain domain;
  tess::Spacing spacing;
  tess::LevelsBits bits;
  bool operator<(const CacheKey& o) const {
    return std::tie(domain, spacing, bits) < std::tie(o.domain, o.spacing, o.bits);
  }
};

// Entries stay alive while a PatchBoundaries holds them, so clearing is always safe; the
// bound only matters for callers that feed the measure ever new levels.
constexpr size_t kMaxCachedTessellations = 1 << 14;

}  // namespace

int64_t domainEdgeParameter(techniques::PatchDomain domain, uint32_t edge,
                            const tess::DomainPoint& p) {
  assert(edge < (domain == techniques::PatchDomain::kQuad ? 4u : 3u));
  double t = -1;
  if (domain == techniques::PatchDomain::kQuad) {
    const float u = p[0], v = p[1];
    switch (edge) {
      case 0:
        if (v == 0) t = u;
        break;
      case 1:
        if (u == 1) t = v;
        break;
      case 2:
        if (v == 1) t = 1.0 - u;
        break;
      default:
        if (u == 0) t = 1.0 - v;
        break;
    }
  } else if (p[(edge + 2) % 3] == 0) {
    t = p[(edge + 1) % 3];
  }
  return t < 0 ? -1 : int64_t(std::llround(t * double(kEdgeParameterOne)));
}

bool isDomainCorner(techniques::PatchDomain domain, uint32_t corner, const tess::DomainPoint& p) {
  assert(corner < (domain == techniques::PatchDomain::kQuad ? 4u : 3u));
  if (domain == techniques::PatchDomain::kTriangle) return p[corner] == 1;
  static constexpr float kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return p[0] == kCorner[corner][0] && p[1] == kCorner[corner][1];
}

int64_t BoundaryTessellation::edgePoint(uint32_t edge, int64_t t) const {
  assert(size_t(edge) + 1 < edge_begin.size());
  const auto first = edge_t.begin() + edge_begin[edge];
  const auto last = edge_t.begin() + edge_begin[edge + 1];
  const auto it = std::lower_bound(first, last, t);
  return it != last && *it == t ? int64_t(it - edge_t.begin()) : -1;
}

int64_t BoundaryTessellation::indexOf(techniques::PatchDomain domain,
                                      const tess::DomainPoint& p) const {
  const uint32_t count = corners();
  for (uint32_t c = 0; c < count; ++c) {
    if (isDomainCorner(domain, c, p)) {
      return std::memcmp(&points[c], &p, sizeof(p)) == 0 ? int64_t(c) : -1;
    }
  }
  for (uint32_t e = 0; e < count; ++e) {
    const int64_t t = domainEdgeParameter(domain, e, p);
    if (t <= 0 || t >= kEdgeParameterOne) continue;
    const int64_t k = edgePoint(e, t);
    return k >= 0 && std::memcmp(&points[size_t(k)], &p, sizeof(p)) == 0 ? k : -1;
  }
  return -1;
}

std::shared_ptr<const BoundaryTessellation> boundaryTessellation(techniques::PatchDomain domain,
                                                                 tess::Spacing spacing,
                                                                 const tess::Levels& levels) {
  static std::mutex mutex;
  static std::map<CacheKey, std::shared_ptr<const BoundaryTessellation>> cache;
  const CacheKey key{domain, spacing, tess::levelsBits(levels)};
  {
    const std::lock_guard lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  // Computed outside the lock; when two threads race, the first stored wins (both equal).
  auto computed =
      std::make_shared<const BoundaryTessellation>(computeBoundary(domain, spacing, levels));
  const std::lock_guard lock(mutex);
  if (cache.size() >= kMaxCachedTessellations) cache.clear();
  return cache.emplace(key, std::move(computed)).first->second;
}

PatchBoundaries patchBoundaries(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                                std::span<const tess::Levels> patch_levels) {
  assert(patch_levels.size() == patches.patchCount());
  PatchBoundaries b;
  const size_t count = patches.patchCount();
  b.tessellation.resize(count);
  b.domain.resize(count);
  b.offset.assign(count + 1, 0);
  std::map<std::pair<techniques::PatchDomain, tess::LevelsBits>, uint32_t> seen;
  for (size_t p = 0; p < count; ++p) {
    const techniques::PatchDomain domain = patches.patchDomain(p);
    b.domain[p] = domain;
    const auto key = std::make_pair(domain, tess::levelsBits(patch_levels[p]));
    auto found = seen.find(key);
    if (found == seen.end()) {
      b.tessellations.push_back(boundaryTessellation(domain, spacing, patch_levels[p]));
      found = seen.emplace(key, uint32_t(b.tessellations.size() - 1)).first;
    }
    b.tessellation[p] = found->second;
    const BoundaryTessellation& t = *b.tessellations[found->second];
    if (t.culled) ++b.culled_patches;
    b.offset[p + 1] = b.offset[p] + t.points.size();
  }
  return b;
}

}  // namespace tb::measures
