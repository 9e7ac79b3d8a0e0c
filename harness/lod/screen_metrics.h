// Screen-space figures of a tessellated surface under one view (CPU only): what a factor
// policy (seed 002) buys and costs on screen. The CPU tessellator tessellates each patch as
// the GPU would, the technique's double evaluator places the points (batched) and the view's
// matrix projects them. A point is in front when clip w >= view.near_plane and inside when its
// pixel is in the closed viewport. Patches run in parallel into per-patch slots reduced in
// patch order, so results do not depend on the thread count (docs/derivations/adaptivity.md).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/tess/tessellator.h"
#include "core/view/view.h"
#include "harness/lod/screen_patterns.h"
#include "reference/limit_surface.h"
#include "techniques/technique.h"

namespace tb::lod {

// On-screen length of tessellated triangle edges, pixels. Each patch's unique edges (an
// edge shared by two patches counts once in each); an edge is visible when both ends are
// in front and at least one is inside.
struct ScreenEdgeFigures {
  uint64_t edges = 0;  // visible edges (0 when nothing is on screen)
  // Nearest-rank percentiles of the visible edges' lengths, pixels (0 without edges). A
  // factor policy aims them at view.target_pixels_per_edge; edges cut by the viewport
  // border count at their full projected length.
  double median_px = 0, p05_px = 0, p95_px = 0;
  // Fraction of visible edges within [0.5, 2] x view.target_pixels_per_edge: best 1, worst 0.
  double fraction_in_band = 0;
};

// A screen-space distance over samples, pixels: best 0; a visible artefact starts near 0.5.
struct ScreenErrorFigures {
  uint64_t samples = 0;  // visible samples (0: the other fields are 0)
  double max_px = 0;     // largest distance
  double rms_px = 0;     // root mean square over the visible samples
};

struct FrameScreenFigures {
  // The CPU tessellator's output over the non-culled patches (visible or not).
  uint64_t patches = 0;        // patches not culled by their levels
  uint64_t triangles = 0;      // tessellated triangles
  uint64_t domain_points = 0;  // unique domain points (TES invocations)
  ScreenEdgeFigures edges;
  // Piecewise-linear tessellation against the technique's own surface (chord error): in
  // every triangle, at its centroid and at the midpoint of each of its edges (each unique
  // edge once per patch), the surface S(c) against the blend of the triangle's evaluated
  // vertices with the same barycentric weights; both projected. Visible: S(c) in front and
  // inside, the blended point in front. 0 on a surface affine in its parameter (flat).
  ScreenErrorFigures tessellation_error;
  // The technique's surface against the reference limit at the same parameter, sampled at
  // the tessellation's vertices (its visible points: what the GPU draws there). Visible:
  // the technique's point in front and inside, the limit's point in front. 0 where the
  // technique is exact (acc on regular faces); all zero when no limit was given.
  ScreenErrorFigures reference_error;
  bool reference_measured = false;  // a limit was given
  // Non-culled patches left out of reference_error: faces without a limit surface (holes,
  // boundary faces without interpolation) and patches whose domain does not share the
  // limit face's parameterisation (triangle patches on a Catmull-Clark mesh, whose faces
  // Bfr splits into quad sub-faces). 0 when no limit was given.
  uint64_t patches_without_reference = 0;
};

// Batch-pattern points kept between calls (each costs its coordinates plus the technique's
// basis weights, up to ~0.5 KB for a Gregory patch), and the most a chunk of patches
// evaluated together may need: large assets are processed in consecutive chunks.
inline constexpr size_t kScreenPatternPoints = size_t(1) << 18;

// One per technique instance; not thread-safe itself, parallel inside (TBB). Every call
// takes one level set per patch (levels.size() == patches.patchCount(), else
// std::invalid_argument); a patch whose levels cull it contributes nothing.
class ScreenMetrics {
 public:
  // `limit`: null, or the reference limit of patches.controlMesh() under the scheme
  // patches.approximates() names (referenceScheme, harness/lod/reference_scheme.h);
  // std::logic_error when its scheme or face count does not match. Both must outlive this object.
  ScreenMetrics(const techniques::SurfacePatches& patches, const ref::LimitSurface* limit);

  FrameScreenFigures frame(tess::Spacing spacing, std::span<const tess::Levels> levels,
                           const view::View& view);

  // Only FrameScreenFigures::tessellation_error and, when `triangles` is not null, the
  // triangle count (what a parameter sweep needs; no edges, no reference); when
  // `patch_max_px` is not null, each patch's largest visible error (0 without visible samples).
  ScreenErrorFigures tessellationError(tess::Spacing spacing, std::span<const tess::Levels> levels,
                                       const view::View& view, uint64_t* triangles = nullptr,
                                       std::vector<double>* patch_max_px = nullptr);

  // Popping between consecutive frames: how far the tessellated (piecewise-linear) surface
  // moves on screen at fixed surface points because the levels changed, the camera held
  // at `view` (the later frame's). At latticeCoords(domain, kPopSampleSegments) of every
  // patch, the tessellation's point under `before` and under `after` (the blend of the
  // evaluated corners of the triangle containing it); visible: the `after` point in front
  // and inside, the `before` point in front. Patches culled in either frame are left out.
  // Best 0 (identical levels give exactly 0).
  ScreenErrorFigures pop(tess::Spacing spacing, std::span<const tess::Levels> before,
                         std::span<const tess::Levels> after, const view::View& view);

 private:
  // Patch p's points under `pattern` (positions at least): the ones kept from one of its
  // last two evaluations when that was under the same batch pattern (the same bits
  // evaluateBatch gives again), else evaluated into `scratch` and kept, in place of the
  // less recently used, when they fit the patch's share of kEvaluatedDoubles. A search
  // passes the same levels over many frames, and pop() compares a frame's levels with the
  // previous frame's: this spares the technique's evaluation of both. Call once per patch
  // at a time; two calls for one patch (pop) need two scratches.
  const techniques::BatchPoints& evaluated(size_t p, const ScreenPattern& pattern,
                                           techniques::BatchPoints& scratch);

  struct Evaluated {
    uint64_t serial = 0;             // ScreenPattern::points_serial; 0: nothing kept
    techniques::BatchPoints points;  // positions only
  };
  struct KeptPair {
    std::array<Evaluated, 2> slots;
    uint8_t recent = 0;  // the slot used last
  };
  // Per slot: 64 MB over all patches, 128 MB with both slots.
  static constexpr size_t kEvaluatedDoubles = size_t(1) << 23;

  const techniques::SurfacePatches& patches_;
  const ref::LimitSurface* limit_;
  std::vector<KeptPair> evaluated_;  // per patch
  size_t evaluated_share_ = 0;       // doubles a patch may keep in each slot
  // Per patch: how the reference is sampled (screen_metrics.cpp, ReferenceMap).
  std::vector<uint8_t> reference_map_;
  ScreenPatternCache cache_;
};

}  // namespace tb::lod
