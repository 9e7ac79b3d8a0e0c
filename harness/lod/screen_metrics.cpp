#include "harness/lod/screen_metrics.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "harness/lod/reference_scheme.h"
#include "reference/limit_face.h"

namespace tb::lod {
namespace {

// How patch p's parameter maps to its limit face p (as the error measure maps it).
enum ReferenceMap : uint8_t {
  kNoReference,  // no limit face, or a parameterisation the face does not share
  kQuadUv,       // quad patch on a Catmull-Clark face: (u, v) = (coord[0], coord[1])
  kLoopUv,       // triangle patch on a Loop face: Bfr's corners (0,0), (1,0), (0,1) weigh
                 // (1 - u - v, u, v), so (u, v) = (coord[1], coord[2])
};

// Sums of one set of screen distances, added in a fixed order.
struct ErrorSums {
  uint64_t samples = 0;
  double max_px = 0, squared_px2 = 0;
  void add(double distance_px) {
    ++samples;
    max_px = std::max(max_px, distance_px);
    squared_px2 += distance_px * distance_px;
  }
  void merge(const ErrorSums& other) {
    samples += other.samples;
    max_px = std::max(max_px, other.max_px);
    squared_px2 += other.squared_px2;
  }
  ScreenErrorFigures figures() const {
    if (samples == 0) return {};
    return {samples, max_px, std::sqrt(squared_px2 / double(samples))};
  }
};

bool inFront(const view::View& view, const view::ProjectedPoint& p) {
  return p.clip_w >= view.near_plane;
}
bool inside(const view::View& view, const view::ProjectedPoint& p) {
  return p.x_px >= 0 && p.x_px <= view.viewport_width_px && p.y_px >= 0 &&
         p.y_px <= view.viewport_height_px;
}
bool visible(const view::View& view, const view::ProjectedPoint& p) {
  return inFront(view, p) && inside(view, p);
}
double distancePx(const view::ProjectedPoint& a, const view::ProjectedPoint& b) {
  const double dx = a.x_px - b.x_px, dy = a.y_px - b.y_px;
  return std::sqrt(dx * dx + dy * dy);
}
view::ProjectedPoint project(const view::View& view, const mesh::Vec3d& p) {
  return view::projectToPixels(view, p.x, p.y, p.z);
}

// The piecewise-linear surface at a blend of tessellation vertices (points evaluated
// with a ScreenPattern's batch pattern: the vertices first).
mesh::Vec3d blendPosition(const techniques::BatchPoints& points, const VertexBlend& blend) {
  mesh::Vec3d r{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    r = r + blend.weight[k] * techniques::BatchPoints::at(points.position, blend.index[k]);
  }
  return r;
}

// One thread's evaluation buffers, reused from patch to patch.
struct Scratch {
  techniques::BatchPoints points, before;
  std::vector<view::ProjectedPoint> projected;
};

// What one patch contributes, reduced serially in patch order.
struct PatchSlot {
  ErrorSums tessellation, reference;
  size_t edges = 0;  // visible edge lengths written at the patch's offset
};

// Consecutive patches [begin, end) evaluated together, and their distinct patterns.
struct Chunk {
  size_t begin = 0, end = 0;
  std::vector<ScreenPatternKey> keys;           // distinct, in order of first use
  std::array<std::vector<uint32_t>, 2> key_of;  // per level set: the key of patch begin + i
};

// True when the chunk's patches share their patterns enough (on average 4 patches a
// pattern or more) for the technique's tabulated batch kernel to pay for building it;
// adaptive frames give most patches their own levels, and then point-by-point evaluation
// is cheaper. Either way the figures agree to rounding (~1e-12 relative).
bool sharesPatterns(const Chunk& chunk) { return 4 * chunk.keys.size() <= chunk.end - chunk.begin; }

// Splits the patches into chunks whose distinct patterns need about kScreenPatternPoints
// batch points at most (at least one patch each) and calls fn(chunk) in patch order.
template <class Fn>
void forEachChunk(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                  std::span<const std::span<const tess::Levels>> sets, Fn&& fn) {
  assert(sets.size() <= std::tuple_size_v<decltype(Chunk::key_of)>);
  Chunk chunk;
  std::map<ScreenPatternKey, uint32_t> index;
  size_t points = 0;
  const size_t patch_count = patches.patchCount();
  for (size_t p = 0; p < patch_count; ++p) {
    const techniques::PatchDomain domain = patches.patchDomain(p);
    auto new_points = [&] {
      size_t extra = 0;
      for (const auto& set : sets) {
        if (!index.contains(screenPatternKey(domain, spacing, set[p]))) {
          extra += estimateScreenPatternPoints(domain, set[p]);
        }
      }
      return extra;
    };
    size_t extra = new_points();
    if (p > chunk.begin && points + extra > kScreenPatternPoints) {
      chunk.end = p;
      fn(chunk);
      chunk = Chunk{p, p, {}, {}};
      index.clear();
      points = 0;
      extra = new_points();
    }
    points += extra;
    for (size_t s = 0; s < sets.size(); ++s) {
      const ScreenPatternKey key = screenPatternKey(domain, spacing, sets[s][p]);
      const auto [it, added] = index.emplace(key, uint32_t(chunk.keys.size()));
      if (added) chunk.keys.push_back(key);
      chunk.key_of[s].push_back(it->second);
    }
  }
  chunk.end = patch_count;
  if (chunk.end > chunk.begin) fn(chunk);
}

void requireLevels(const techniques::SurfacePatches& patches,
                   std::span<const tess::Levels> levels) {
  if (levels.size() != patches.patchCount()) {
    throw std::invalid_argument("screen metrics: " + std::to_string(levels.size()) +
                                " level sets for " + std::to_string(patches.patchCount()) +
                                " patches");
  }
}

void projectVertices(const view::View& view, size_t vertex_count,
                     const techniques::BatchPoints& points,
                     std::vector<view::ProjectedPoint>* projected) {
  projected->resize(vertex_count);
  for (size_t i = 0; i < vertex_count; ++i) {
    (*projected)[i] = project(view, techniques::BatchPoints::at(points.position, i));
  }
}

// FrameScreenFigures::tessellation_error of one patch.
void addTessellationError(const ScreenPattern& pattern, const techniques::BatchPoints& points,
                          const view::View& view, ErrorSums* sums) {
  const size_t first = pattern.vertexCount();
  for (size_t i = 0; i < pattern.samples.size(); ++i) {
    const view::ProjectedPoint surface =
        project(view, techniques::BatchPoints::at(points.position, first + i));
    if (!visible(view, surface)) continue;
    const view::ProjectedPoint linear = project(view, blendPosition(points, pattern.samples[i]));
    if (!inFront(view, linear)) continue;
    sums->add(distancePx(surface, linear));
  }
}

// The visible edges' lengths of one patch into `out`; returns how many.
size_t writeEdgeLengths(const ScreenPattern& pattern,
                        std::span<const view::ProjectedPoint> projected, const view::View& view,
                        double* out) {
  size_t written = 0;
  for (const auto& e : pattern.edges) {
    const view::ProjectedPoint& a = projected[e[0]];
    const view::ProjectedPoint& b = projected[e[1]];
    if (!inFront(view, a) || !inFront(view, b) || (!inside(view, a) && !inside(view, b))) continue;
    out[written++] = distancePx(a, b);
  }
  return written;
}

// FrameScreenFigures::reference_error of patch p, at its visible tessellation vertices.
void addReferenceError(const ref::LimitSurface& limit, size_t p, ReferenceMap map,
                       const ScreenPattern& pattern,
                       std::span<const view::ProjectedPoint> projected, const view::View& view,
                       ErrorSums* sums) {
  std::optional<ref::LimitFace> face;  // prepared at the first visible vertex
  const std::vector<techniques::DomainCoord>& coords = pattern.vertex_coords;
  for (size_t i = 0; i < coords.size(); ++i) {
    if (!visible(view, projected[i])) continue;
    if (!face) face.emplace(limit.face(p));
    const techniques::DomainCoord& c = coords[i];
    const ref::LimitPoint exact =
        map == kQuadUv ? face->evaluate(c[0], c[1]) : face->evaluate(c[1], c[2]);
    const view::ProjectedPoint reference = project(view, exact.position);
    if (!inFront(view, reference)) continue;
    sums->add(distancePx(projected[i], reference));
  }
}

// Percentiles and band of the visible edge lengths (any order; sorted here).
ScreenEdgeFigures edgeFigures(std::vector<double> lengths_px, double target_px) {
  ScreenEdgeFigures f;
  f.edges = lengths_px.size();
  if (lengths_px.empty()) return f;
  const size_t in_band = size_t(std::count_if(lengths_px.begin(), lengths_px.end(), [&](double l) {
    return l >= 0.5 * target_px && l <= 2 * target_px;
  }));
  f.fraction_in_band = double(in_band) / double(lengths_px.size());
  // Nearest rank: the smallest value with at least `percent` % of the values at or below it,
  // i.e. the value at that index of the sorted lengths (nth_element: the same value, found
  // in linear time, each rank above the last).
  const size_t n = lengths_px.size();
  size_t placed = 0;  // lengths before it are final: no larger than any after
  auto rank = [&](size_t percent) {
    const size_t index = std::max<size_t>(1, (percent * n + 99) / 100) - 1;
    if (index >= placed) {
      std::nth_element(lengths_px.begin() + ptrdiff_t(placed),
                       lengths_px.begin() + ptrdiff_t(index), lengths_px.end());
      placed = index + 1;
    }
    return lengths_px[index];
  };
  f.p05_px = rank(5);
  f.median_px = rank(50);
  f.p95_px = rank(95);
  return f;
}

}  // namespace

ScreenMetrics::ScreenMetrics(const techniques::SurfacePatches& patches,
                             const ref::LimitSurface* limit)
    : patches_(patches),
      limit_(limit),
      evaluated_(patches.patchCount()),
      evaluated_share_(kEvaluatedDoubles / std::max<size_t>(1, patches.patchCount())),
      cache_(patches, kScreenPatternPoints) {
  if (limit == nullptr) return;
  const osd::Scheme scheme = referenceScheme(patches.approximates());
  if (limit->scheme() != scheme || limit->faceCount() != patches.patchCount()) {
    throw std::logic_error("screen metrics: the limit surface (" +
                           std::string(osd::schemeName(limit->scheme())) + ", " +
                           std::to_string(limit->faceCount()) + " faces) is not the " +
                           std::string(osd::schemeName(scheme)) + " limit of the " +
                           std::to_string(patches.patchCount()) + " patches' control mesh");
  }
  reference_map_.assign(patches.patchCount(), kNoReference);
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    if (!limit->hasLimitSurface(p)) continue;
    const techniques::PatchDomain domain = patches.patchDomain(p);
    if (domain == techniques::PatchDomain::kQuad && scheme == osd::Scheme::kCatmullClark) {
      reference_map_[p] = kQuadUv;
    } else if (domain == techniques::PatchDomain::kTriangle && scheme == osd::Scheme::kLoop) {
      reference_map_[p] = kLoopUv;
    }
  }
}

const techniques::BatchPoints& ScreenMetrics::evaluated(size_t p, const ScreenPattern& pattern,
                                                        techniques::BatchPoints& scratch) {
  assert(p < evaluated_.size() && pattern.points != nullptr);
  KeptPair& kept = evaluated_[p];
  for (uint8_t k = 0; k < 2; ++k) {
    if (kept.slots[k].serial != 0 && kept.slots[k].serial == pattern.points_serial) {
      kept.recent = k;
      return kept.slots[k].points;
    }
  }
  patches_.evaluateBatch(p, *pattern.points, scratch);
  if (3 * scratch.position[0].size() > evaluated_share_) return scratch;
  const uint8_t older = kept.recent ^ 1;
  Evaluated& slot = kept.slots[older];
  slot.points.count = scratch.count;
  slot.points.position = scratch.position;
  slot.serial = pattern.points_serial;
  kept.recent = older;
  return slot.points;
}

FrameScreenFigures ScreenMetrics::frame(tess::Spacing spacing, std::span<const tess::Levels> levels,
                                        const view::View& view) {
  requireLevels(patches_, levels);
  FrameScreenFigures figures;
  figures.reference_measured = limit_ != nullptr;
  ErrorSums tessellation, reference;
  std::vector<double> lengths_px;
  tbb::enumerable_thread_specific<Scratch> scratch;
  const std::span<const tess::Levels> sets[] = {levels};
  forEachChunk(patches_, spacing, sets, [&](const Chunk& chunk) {
    const std::vector<const ScreenPattern*> patterns =
        cache_.acquire(chunk.keys, kPatternEdges | kPatternSamples, sharesPatterns(chunk));
    const size_t count = chunk.end - chunk.begin;
    auto pattern_of = [&](size_t i) -> const ScreenPattern& {
      return *patterns[chunk.key_of[0][i]];
    };
    std::vector<size_t> edge_start(count + 1, 0);
    for (size_t i = 0; i < count; ++i) {
      edge_start[i + 1] = edge_start[i] + pattern_of(i).edges.size();
    }
    std::vector<double> chunk_lengths_px(edge_start[count]);
    std::vector<PatchSlot> slots(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
      const ScreenPattern& pattern = pattern_of(i);
      if (pattern.culled) return;
      const size_t p = chunk.begin + i;
      Scratch& s = scratch.local();
      const techniques::BatchPoints& points = evaluated(p, pattern, s.points);
      projectVertices(view, pattern.vertexCount(), points, &s.projected);
      addTessellationError(pattern, points, view, &slots[i].tessellation);
      slots[i].edges =
          writeEdgeLengths(pattern, s.projected, view, chunk_lengths_px.data() + edge_start[i]);
      if (limit_ != nullptr && reference_map_[p] != kNoReference) {
        addReferenceError(*limit_, p, ReferenceMap(reference_map_[p]), pattern, s.projected, view,
                          &slots[i].reference);
      }
    });
    for (size_t i = 0; i < count; ++i) {
      const ScreenPattern& pattern = pattern_of(i);
      if (pattern.culled) continue;
      ++figures.patches;
      figures.triangles += pattern.triangles.size();
      figures.domain_points += pattern.vertexCount();
      tessellation.merge(slots[i].tessellation);
      reference.merge(slots[i].reference);
      if (limit_ != nullptr && reference_map_[chunk.begin + i] == kNoReference) {
        ++figures.patches_without_reference;
      }
      const double* first = chunk_lengths_px.data() + edge_start[i];
      lengths_px.insert(lengths_px.end(), first, first + slots[i].edges);
    }
  });
  figures.tessellation_error = tessellation.figures();
  figures.reference_error = reference.figures();
  figures.edges = edgeFigures(std::move(lengths_px), view.target_pixels_per_edge);
  return figures;
}

ScreenErrorFigures ScreenMetrics::tessellationError(tess::Spacing spacing,
                                                    std::span<const tess::Levels> levels,
                                                    const view::View& view, uint64_t* triangles,
                                                    std::vector<double>* patch_max_px) {
  requireLevels(patches_, levels);
  if (patch_max_px != nullptr) patch_max_px->assign(levels.size(), 0.0);
  ErrorSums sums;
  uint64_t triangle_count = 0;
  tbb::enumerable_thread_specific<Scratch> scratch;
  const std::span<const tess::Levels> sets[] = {levels};
  forEachChunk(patches_, spacing, sets, [&](const Chunk& chunk) {
    const std::vector<const ScreenPattern*> patterns =
        cache_.acquire(chunk.keys, kPatternSamples, sharesPatterns(chunk));
    const size_t count = chunk.end - chunk.begin;
    std::vector<ErrorSums> slots(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
      const ScreenPattern& pattern = *patterns[chunk.key_of[0][i]];
      if (pattern.culled) return;
      const size_t p = chunk.begin + i;
      Scratch& s = scratch.local();
      addTessellationError(pattern, evaluated(p, pattern, s.points), view, &slots[i]);
    });
    for (size_t i = 0; i < count; ++i) {
      sums.merge(slots[i]);
      triangle_count += patterns[chunk.key_of[0][i]]->triangles.size();
      if (patch_max_px != nullptr) (*patch_max_px)[chunk.begin + i] = slots[i].max_px;
    }
  });
  if (triangles != nullptr) *triangles = triangle_count;
  return sums.figures();
}

ScreenErrorFigures ScreenMetrics::pop(tess::Spacing spacing, std::span<const tess::Levels> before,
                                      std::span<const tess::Levels> after, const view::View& view) {
  requireLevels(patches_, before);
  requireLevels(patches_, after);
  ErrorSums sums;
  tbb::enumerable_thread_specific<Scratch> scratch;
  const std::span<const tess::Levels> sets[] = {before, after};
  forEachChunk(patches_, spacing, sets, [&](const Chunk& chunk) {
    const std::vector<const ScreenPattern*> patterns =
        cache_.acquire(chunk.keys, kPatternLattice, sharesPatterns(chunk));
    const size_t count = chunk.end - chunk.begin;
    std::vector<ErrorSums> slots(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
      const ScreenPattern& was = *patterns[chunk.key_of[0][i]];
      const ScreenPattern& is = *patterns[chunk.key_of[1][i]];
      if (was.culled || is.culled) return;
      const size_t p = chunk.begin + i;
      Scratch& s = scratch.local();
      const techniques::BatchPoints& is_points = evaluated(p, is, s.points);
      const techniques::BatchPoints* was_points = &is_points;
      if (&was != &is) was_points = &evaluated(p, was, s.before);
      for (size_t k = 0; k < is.lattice.size(); ++k) {
        const view::ProjectedPoint now = project(view, blendPosition(is_points, is.lattice[k]));
        if (!visible(view, now)) continue;
        const view::ProjectedPoint then = project(view, blendPosition(*was_points, was.lattice[k]));
        if (!inFront(view, then)) continue;
        slots[i].add(distancePx(now, then));
      }
    });
    for (const ErrorSums& slot : slots) sums.merge(slot);
  });
  return sums.figures();
}

}  // namespace tb::lod
