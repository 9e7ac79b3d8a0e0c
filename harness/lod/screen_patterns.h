// The per-level-set data the screen-space figures (screen_metrics.h) evaluate every patch
// with: one tessellation of a patch domain under one spacing and one set of levels, its
// domain points as a batch pattern (techniques/batch_eval.h), and the domain points the
// figures sample, each a fixed blend of tessellation vertices. Many patches share levels,
// so a ScreenPatternCache keeps patterns by (domain, spacing, level bits), bounded in size.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <vector>

#include "core/tess/tessellator.h"
#include "techniques/batch_eval.h"
#include "techniques/technique.h"

namespace tb::lod {

// Segments per patch edge of the fixed lattice the popping figure samples (latticeCoords):
// 81 points on a quad patch, 45 on a triangle patch.
inline constexpr int kPopSampleSegments = 8;

// What a ScreenPattern holds beyond its tessellation and the batch pattern of its vertices.
enum ScreenPatternPart : unsigned {
  kPatternEdges = 1,    // the unique edges of the tessellated triangles
  kPatternSamples = 2,  // the tessellation-error samples (implies the edges)
  kPatternLattice = 4,  // the pop lattice located in the triangles
};

// A domain point as a blend of tessellation vertices: its domain coordinate is
// sum_k weight[k] * vertex[index[k]], and the piecewise-linear (tessellated) surface there
// is the same blend of the evaluated vertex positions. Unused slots have weight 0.
struct VertexBlend {
  std::array<uint32_t, 3> index{};
  std::array<double, 3> weight{};
};

struct ScreenPatternKey {
  techniques::PatchDomain domain = techniques::PatchDomain::kQuad;
  tess::Spacing spacing = tess::Spacing::kInteger;
  tess::LevelsBits levels{};
  auto operator<=>(const ScreenPatternKey&) const = default;
};

ScreenPatternKey screenPatternKey(techniques::PatchDomain domain, tess::Spacing spacing,
                                  const tess::Levels& levels);

struct ScreenPattern {
  ScreenPatternKey key;
  unsigned parts = 0;        // ScreenPatternPart bits built so far
  bool tessellated = false;  // culled, triangles and vertex_coords are set
  bool culled = false;       // the tessellator culls the patch: no points, no triangles
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into vertex_coords
  // The tessellation's unique domain points as the technique takes them (DomainCoord:
  // quads (u, v, 0), triangles barycentric (u, v, w) = gl_TessCoord).
  std::vector<techniques::DomainCoord> vertex_coords;
  // kPatternEdges: each unique edge once, as (lower index, higher index), sorted.
  std::vector<std::array<uint32_t, 2>> edges;
  // kPatternSamples: the midpoint of every unique edge (in `edges` order), then the
  // centroid of every triangle (in `triangles` order).
  std::vector<VertexBlend> samples;
  // kPatternLattice: latticeCoords(domain, kPopSampleSegments) in its order, each as the
  // barycentric blend of the corners of the first triangle (in `triangles` order) that
  // contains it.
  std::vector<VertexBlend> lattice;
  // One batch pattern for every point a patch evaluates (one allocation and one kernel call
  // per patch): point i < vertexCount() is vertex i, and with kPatternSamples point
  // vertexCount() + k is sample k. Null when culled.
  std::unique_ptr<techniques::BatchPattern> points;
  // A process-wide id of `points`, new each time they are built (0: none): equal ids, the
  // same batch pattern, so the same evaluation bits (ScreenMetrics keeps evaluations by it).
  uint64_t points_serial = 0;

  size_t vertexCount() const { return vertex_coords.size(); }
  // Domain points held in the batch pattern (what bounds the cache).
  size_t patternPoints() const { return points ? points->pointCount() : 0; }
};

// Builds whatever of `parts` (and the tessellation) `pattern` lacks. For Spacing::kPow2
// the levels are rounded up to powers of two and tessellated with integer spacing, as the
// GPU path does (core/gpu/patch_program.cpp).
// technique_kernel: build the batch pattern with the technique's makeBatchPattern (its
// tabulated kernel: worth it when many patches share the pattern); false: a plain pattern,
// evaluated point by point (cheaper for a pattern one patch uses: gregory_acc tabulates
// ~15 basis evaluations per point).
void completeScreenPattern(const techniques::SurfacePatches& patches, unsigned parts,
                           ScreenPattern* pattern, bool technique_kernel = true);

// Domain points a pattern for `levels` may hold with every part (an upper estimate from the
// largest level, used to size chunks before tessellating).
size_t estimateScreenPatternPoints(techniques::PatchDomain domain, const tess::Levels& levels);

// Patterns of one surface by key. Not thread-safe; acquire() builds in parallel (TBB).
class ScreenPatternCache {
 public:
  // Keeps at most about `max_points` batch-pattern points between calls of acquire().
  ScreenPatternCache(const techniques::SurfacePatches& patches, size_t max_points);

  // The patterns of `keys` (distinct: no key twice), in their order, each with at least `parts`;
  // the missing ones are built in parallel. Entries not in `keys` may be dropped first to stay
  // within the bound. The pointers are valid until the next call.
  // technique_kernels: as completeScreenPattern's, for the patterns built by this call.
  std::vector<const ScreenPattern*> acquire(std::span<const ScreenPatternKey> keys, unsigned parts,
                                            bool technique_kernels = true);
  size_t size() const { return patterns_.size(); }

 private:
  const techniques::SurfacePatches& patches_;
  size_t max_points_;
  std::map<ScreenPatternKey, std::unique_ptr<ScreenPattern>> patterns_;
};

}  // namespace tb::lod
