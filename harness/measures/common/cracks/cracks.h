// Crack gaps (docs/MEASURES.md) between patches that share an edge or a corner.
//
// Two patches share an edge when its two end corners weld to the same positions
// (weldByPosition over patchCorners(), so attribute seams count too). The tessellator emits
// each side's points mirrored (t and exactly 1 - t in 16.16), so the measure pairs them by t
// and compares the positions: CPU float in shader order (evaluateFloat) or the device's TES
// capture (crack_capture.h). Tessellations are shared process-wide (crack_boundaries.h);
// evaluation and pairing run in parallel with results independent of the thread count.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpu/patch_program_desc.h"
#include "core/mesh/float_ulp.h"  // ulpDistance, used with these figures
#include "harness/measures/common/cracks/crack_boundaries.h"
#include "harness/measures/common/cracks/crack_seams.h"
#include "techniques/technique.h"

namespace tb::measures {

// kGpu: the technique's TCS + TES through the tessellator; kGpuCompute: the same surface on
// the compute path (core/gpu/compute_path.h: compute tessellator, the technique's compute
// shader, no tessellation stage). Both are the row key backend = "gpu"; crackPath() gives
// the row key path.
enum class CrackBackend { kCpuFloat, kGpu, kGpuCompute };
const char* toString(CrackBackend backend);
// "tessellator" (the CPU float model and the TES both follow the tessellator's points) or
// "compute".
const char* crackPath(CrackBackend backend);

// One side of a shared edge or corner. Local edge k runs from corner k to corner k + 1
// (mod the corner count); corners follow technique.h (quad (0,0),(1,0),(1,1),(0,1);
// triangle corner i where gl_TessCoord[i] = 1).
struct PatchSide {
  uint32_t patch = 0;
  uint32_t local = 0;     // local edge or corner index
  bool reversed = false;  // edges: the patch runs the edge from the higher welded vertex
};

struct SharedEdge {
  uint32_t v0 = 0, v1 = 0;              // welded position indices, v0 < v1
  bool seam = false;                    // the sides use different (unwelded) position indices
  std::vector<PatchSide> sides;         // two or more, in patch order
  EdgeKind kind = EdgeKind::kInterior;  // seam or interior (classifySeams)
};

struct SharedCorner {
  uint32_t vertex = 0;                  // welded position index
  std::vector<PatchSide> sides;         // two or more, in patch order
  EdgeKind kind = EdgeKind::kInterior;  // seam, boundary or interior (classifySeams)
};

struct SharedBoundaries {
  std::vector<SharedEdge> edges;      // sorted by (v0, v1)
  std::vector<SharedCorner> corners;  // sorted by vertex
};

SharedBoundaries findSharedBoundaries(const techniques::SurfacePatches& patches);

// Where the largest gap is. For an edge, `t` is the edge parameter on side a, from its
// corner `local_a` (t = 0) towards the next corner (t = 1).
struct CrackLocation {
  bool found = false;
  bool corner = false;
  uint32_t patch_a = 0, patch_b = 0;
  uint32_t local_a = 0, local_b = 0;
  double t = 0;
};

struct CrackFigures {
  CrackBackend backend = CrackBackend::kCpuFloat;
  bool measured = false;
  std::string skipped_reason;  // non-empty when !measured (no GPU program, no device)

  uint64_t shared_edges = 0;    // edges with two or more patches
  uint64_t seam_edges = 0;      // of those, shared only through welding
  uint64_t shared_corners = 0;  // welded vertices at corners of two or more patches
  // Patches whose boundary points are paired: every patch, or the crack sample
  // (kCrackPatchBudget); shared_* then count the sample's edges and corners.
  uint64_t patches_compared = 0;
  // Pairs compared: each side of an edge (after the first) against the first side, at
  // every tessellated point strictly inside the edge; likewise at corners.
  uint64_t points_compared = 0;
  uint64_t points_not_equal = 0;  // some component differs (+0 and -0 count as equal)
  uint64_t unpaired_points = 0;   // edge points with no mirror on the other side; 0 expected
  double max_gap_world = 0;       // Euclidean distance, world (asset) units
  double mean_gap_world = 0;      // over all compared pairs
  // Max over pairs and components of the float ulp distance. Near zero a tiny gap spans
  // many ulps (1e-8 against 0 is ~8e8), hence the next figure.
  uint64_t max_gap_ulp = 0;
  // Max component gap in ulps of the asset's scale (the largest |coordinate| of the control
  // mesh): 1 means one rounding step of the model's largest coordinate.
  double max_gap_scale_ulp = 0;
  CrackLocation worst;  // pair with the largest world gap (first one on ties)

  // GPU only: the captured position against evaluateFloat at the same gl_TessCoord, over
  // every captured vertex, i.e. every boundary point of every patch (agreement of the CPU
  // float model with the device where the pairs are taken).
  uint64_t device_points = 0;
  uint64_t device_points_differing = 0;
  uint64_t device_max_ulp = 0;
  uint32_t draws = 0;
};

// Per-patch levels: patch p is tessellated in its patchDomain(p) with patch_levels[p] under
// `spacing`; two sides of a shared edge pair point for point only where their levels for it
// agree (edge_pattern_levels.h), else the extra points are unpaired_points. kGpu runs every
// program of patches.gpuPrograms() on `context` at the same outer levels, capturing boundary
// points; without a program or context (or when a level culls) the result says why. Throws
// gpu::GpuError when the device fails, std::invalid_argument on a levels-count mismatch.
CrackFigures measureCracks(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                           std::span<const tess::Levels> patch_levels, CrackBackend backend,
                           gpu::Context* context = nullptr);

// One pair of a shared edge or corner whose positions differ (points_not_equal counts them).
struct UnequalPair {
  mesh::Vec3f a, b;  // the first side's position and the other side's
  double gap = 0;    // |a - b|, world units
};

// Every pair that measureCracks(patches, spacing, patch_levels, kCpuFloat) counts in
// points_not_equal, in its pair order (shared edges, then corners); empty when watertight
// or when the levels cull a patch (then `figures`, when given, says not measured). The
// figures of the same call go to `figures`. Where a crack is, for the pictures
// (harness/pictures/crack_picture.h). Throws std::invalid_argument when patch_levels.size()
// != patches.patchCount().
std::vector<UnequalPair> unequalPairs(const techniques::SurfacePatches& patches,
                                      tess::Spacing spacing,
                                      std::span<const tess::Levels> patch_levels,
                                      CrackFigures* figures = nullptr);

// Uniform levels: every outer and inner level of every patch = `level`.
CrackFigures measureCracks(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                           float level, CrackBackend backend, gpu::Context* context = nullptr);

// measureCracks over one asset's patches, many times: shared edges and corners are found
// once, and CPU positions and pair figures are kept per set of boundary points, so both
// backends (and spacings whose boundary points coincide bit for bit) evaluate on the CPU
// once; a device capture equal bit for bit takes their figures. One thread at a time. Above
// kCrackPatchBudget patches the pairs are sampled (patch_sample.h: every feature patch, then
// evenly spaced runs of 16; the rest neither evaluated nor drawn): points_not_equal and max
// gaps never exceed the full ones (tests/measures/crack_sample_test.cpp; docs/ARCHITECTURE.md
// §3, "Production-size assets").
inline constexpr size_t kCrackPatchBudget = 2048;

// The crack sample of `patches` (every patch when they fit the budget). !keep_features: the
// control's sample, runs only.
std::vector<uint8_t> crackSample(const techniques::SurfacePatches& patches,
                                 const SharedBoundaries& shared, size_t budget,
                                 bool keep_features = true);

class CrackSession {
 public:
  explicit CrackSession(const techniques::SurfacePatches& patches,
                        size_t patch_budget = kCrackPatchBudget, bool keep_features = true);

  // Patches the pair figures cover: every patch, or the sample above the budget.
  size_t sampledPatches() const { return sampled_count_; }
  // Whether a compared edge lies on a seam (then the measure adds its edge_kind rows).
  bool hasSeams() const { return has_seams_; }

  // With `kind`, the figures of that kind's edges and corners only (shared_*, seam_edges
  // and every pair figure); kCpuFloat only.
  CrackFigures measure(tess::Spacing spacing, std::span<const tess::Levels> patch_levels,
                       CrackBackend backend, gpu::Context* context = nullptr,
                       std::optional<EdgeKind> kind = std::nullopt);
  CrackFigures measure(tess::Spacing spacing, float level, CrackBackend backend,
                       gpu::Context* context = nullptr,
                       std::optional<EdgeKind> kind = std::nullopt);

 private:
  // The CPU float side of one set of boundary points.
  struct CpuSide {
    std::vector<mesh::Vec3f> positions;  // per boundary point; empty until evaluated
    // Pair figures of `positions`, once computed: every kind, then per EdgeKind.
    std::array<std::optional<CrackFigures>, 4> pairs;
  };
  struct Evaluated {
    tess::Spacing spacing;
    std::vector<tess::LevelsBits> levels;
    PatchBoundaries boundaries;
    std::shared_ptr<CpuSide> cpu;
  };
  static constexpr size_t kKeptEvaluations = 8;  // a spacing's levels and the next's

  Evaluated& evaluated(tess::Spacing spacing, std::span<const tess::Levels> patch_levels);
  const CrackFigures& cpuPairs(const Evaluated& e, std::optional<EdgeKind> kind);

  const techniques::SurfacePatches& patches_;
  std::vector<gpu::GpuPatchProgram> programs_;  // patches_.gpuPrograms(), built once
  SharedBoundaries shared_;                     // of the sampled patches
  std::vector<uint8_t> sampled_;                // per patch; empty: every patch
  size_t sampled_count_ = 0;
  uint64_t seam_edges_ = 0;
  bool has_seams_ = false;
  double scale_ulp_ = 0;
  std::vector<Evaluated> kept_;  // latest last, at most kKeptEvaluations
};

}  // namespace tb::measures
