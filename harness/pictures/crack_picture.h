// Where a variant cracks, as a picture (docs/REPORTS.md, "Pictures"): the
// surface shaded grey with every pair of shared points that differ
// (measures::unequalPairs) marked, for the cracks row of results.json with the largest gap
// on the CPU float backend. What glViewer or RenderDoc users look for: where the unequal
// points are, not only how many.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/view/view.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/pictures/rgb_image.h"
#include "harness/pictures/surface_error_mesh.h"
#include "harness/results/results_model.h"

namespace tb::pictures {

// The cracks row a crack picture repeats.
struct CrackRow {
  std::string spacing;  // its keys: spacing, level, levels ("" uniform, or "edge_pattern")
  std::string level;
  std::string levels;
  uint64_t points_not_equal = 0;  // its figures
  double max_gap_world = 0;
  // "cpu_float, fractional_odd, level 64" (", edge_pattern" for per-edge levels).
  std::string text() const;
};

// The record's ok cracks row on the cpu_float backend, without displacement, with
// points_not_equal > 0 and the largest max_gap_world (the first in row order on ties);
// nullopt when the record has none (watertight on the CPU, or not measured).
std::optional<CrackRow> worstCpuCrackRow(const results::Record& record);

// The unequal pairs of that row, recomputed (measures::unequalPairs at the row's spacing and
// uniform or per-edge levels): as many as the row's points_not_equal. Throws
// std::invalid_argument for a spacing or level the row cannot have.
std::vector<measures::UnequalPair> crackPairsOf(const techniques::SurfacePatches& patches,
                                                const CrackRow& row);

// The marks: a pair seen from the camera (nothing of the surface in front of it) is a
// filled disc of radius kCrackDotRadiusPx in kCrackMark, one behind the surface a smaller
// disc in the pale kCrackHidden under them; the pair with the largest gap is circled too
// (radius kCrackWorstRadiusPx, kCrackMark). The grey surface never uses either colour.
inline constexpr Rgb kCrackMark{255, 0, 160};
inline constexpr Rgb kCrackHidden{255, 175, 225};
inline constexpr double kCrackDotRadiusPx = 2.0;
inline constexpr double kCrackHiddenRadiusPx = 1.5;
inline constexpr double kCrackWorstRadiusPx = 7.5;
// How far a point may lie behind the rendered triangle in front of it and still count as
// seen, a fraction of the bounding-box diagonal (the render is a level-8 tessellation, the
// points are on the technique's own tessellation of the row).
inline constexpr double kCrackDepthTolerance = 0.02;

struct CrackPicture {
  RgbImage image;               // size_px x size_px
  uint64_t marked_pixels = 0;   // pixels in kCrackMark
  uint64_t points_visible = 0;  // pairs drawn as discs
  uint64_t points_hidden = 0;   // pairs drawn pale
  uint64_t points_outside = 0;  // pairs off the picture (none for the fixed view)
};

// `shaded` (surface_picture.h's shadedPicture of the same mesh, view and triangle IDs)
// with `pairs` marked at the midpoints of their two positions. No pairs: `shaded`
// unchanged. Deterministic.
CrackPicture composeCrackPicture(const RgbImage& shaded, const SurfaceErrorMesh& mesh,
                                 const view::View& view, uint32_t size_px,
                                 std::span<const uint32_t> triangle_ids,
                                 std::span<const measures::UnequalPair> pairs);

}  // namespace tb::pictures
