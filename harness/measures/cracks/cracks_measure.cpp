// The "cracks" measure: measureCracks over spacings × levels × backends.
#include <exception>
#include <span>
#include <string>
#include <vector>

#include "harness/lod/edge_pattern_levels.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"

namespace tb::measures {
namespace {

struct LevelChoice {
  float level;
  const char* text;
};
constexpr LevelChoice kCrackLevels[] = {{1.0f, "1"}, {7.3f, "7.3"}, {16.0f, "16"}, {64.0f, "64"}};
constexpr tess::Spacing kCrackSpacings[] = {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                            tess::Spacing::kFractionalEven, tess::Spacing::kPow2};
// Rows under per-edge levels (edge_pattern_levels.h), keyed levels = "edge_pattern" with
// level = the pattern's base level; one base keeps the suite short.
constexpr LevelChoice kEdgePatternBase = {7.0f, "7"};
// A displaced surface in the default suite (two samplings per map): two spacings and two
// levels, enough to show naive gaps and watertight sampling's 0; --suite full runs the grid.
constexpr LevelChoice kDisplacedDefaultLevels[] = {{7.3f, "7.3"}, {16.0f, "16"}};
constexpr tess::Spacing kDisplacedDefaultSpacings[] = {tess::Spacing::kInteger,
                                                       tess::Spacing::kFractionalOdd};
constexpr const char* kEdgePatternKey = "edge_pattern";
// The rows of one kind of edge and corner (crack_seams.h): seam, interior or boundary.
constexpr const char* kEdgeKindKey = "edge_kind";
// Why a backend's rows cannot run ("" when they can).
const std::string& reasonOf(CrackBackend backend, const std::string& gpu_reason,
                            const std::string& compute_reason) {
  return backend == CrackBackend::kGpuCompute ? compute_reason : gpu_reason;
}

// The backends of one (spacing, levels): the CPU float model, the TES capture, and the compute
// path where the suite runs it (never on a displaced surface: the compute path does not
// displace yet).
std::vector<CrackBackend> crackBackends(const MeasureInput& input) {
  std::vector<CrackBackend> backends{CrackBackend::kCpuFloat, CrackBackend::kGpu};
  if (runsComputePath(input)) backends.push_back(CrackBackend::kGpuCompute);
  return backends;
}

// Best case of every gap figure is 0 (watertight); worst_* locate the largest world gap
// and are context. points_compared, shared_* and seam_edges describe the asset.
const MetricTable<CrackFigures>& crackTable() {
  using D = results::Direction;
  using F = CrackFigures;
  // The worst pair's location, -1 when no pair was compared.
  auto where = [](uint32_t CrackLocation::*member) {
    return [member](const F& f) { return f.worst.found ? double(f.worst.*member) : -1.0; };
  };
  static const MetricTable<F> kTable{
      // shared_edges: count; context (no best or worst): edges two or more patches share
      {"shared_edges", results::Unit::kCount, D::kNone, &F::shared_edges},
      // seam_edges: count; context: of shared_edges, shared only through welding
      {"seam_edges", results::Unit::kCount, D::kNone, &F::seam_edges},
      // shared_corners: count; context: welded vertices at corners of two or more patches
      {"shared_corners", results::Unit::kCount, D::kNone, &F::shared_corners},
      // patches_compared: count; context: patches whose boundary points are paired, every
      //   patch, or the crack sample of an asset of more than kCrackPatchBudget (2,048)
      {"patches_compared", results::Unit::kCount, D::kNone, &F::patches_compared},
      // points_compared: count; context: side pairs compared at shared tessellated points
      {"points_compared", results::Unit::kCount, D::kNone, &F::points_compared},
      // points_not_equal: count; 0 when watertight (best), up to points_compared (worst)
      {"points_not_equal", results::Unit::kCount, D::kLowerIsBetter, &F::points_not_equal},
      // unpaired_points: count; 0 when every edge point has its mirror (best), up to the edge
      //   points (worst)
      {"unpaired_points", results::Unit::kCount, D::kLowerIsBetter, &F::unpaired_points},
      // max_gap_world: world units; 0 when watertight (best), unbounded (worst)
      {"max_gap_world", results::Unit::kWorld, D::kLowerIsBetter, &F::max_gap_world},
      // mean_gap_world: world units; 0 when watertight (best), up to max_gap_world (worst)
      {"mean_gap_world", results::Unit::kWorld, D::kLowerIsBetter, &F::mean_gap_world},
      // max_gap_ulp: float ulps; 0 when bitwise equal (best), up to ~2^32 (worst: a sign or
      //   exponent apart)
      {"max_gap_ulp", results::Unit::kUlp, D::kLowerIsBetter, &F::max_gap_ulp},
      // max_gap_scale_ulp: ulps of the asset scale; 0 (best), 1 is one rounding step of the largest
      //   coordinate, unbounded (worst)
      {"max_gap_scale_ulp", results::Unit::kScaleUlp, D::kLowerIsBetter, &F::max_gap_scale_ulp},
      // worst_patch_a: patch id; context: side a of the pair with the largest world gap
      {"worst_patch_a", results::Unit::kId, D::kNone, where(&CrackLocation::patch_a)},
      // worst_patch_b: patch id; context: side b of that pair
      {"worst_patch_b", results::Unit::kId, D::kNone, where(&CrackLocation::patch_b)},
      // worst_is_corner: flag; context: 1 when the worst pair sits at a shared corner, 0 on an edge
      {"worst_is_corner", results::Unit::kFlag, D::kNone,
       [](const F& f) { return f.worst.found && f.worst.corner ? 1.0 : 0.0; }},
      // worst_local_a: local edge or corner id; context: on side a
      {"worst_local_a", results::Unit::kId, D::kNone, where(&CrackLocation::local_a)},
      // worst_local_b: local edge or corner id; context: on side b
      {"worst_local_b", results::Unit::kId, D::kNone, where(&CrackLocation::local_b)},
      // worst_t: edge parameter in [0, 1]; context: where on side a's edge the worst gap is
      {"worst_t", results::Unit::kEdgeParameter, D::kNone, [](const F& f) { return f.worst.t; }},
      // vs_cpu_float_points: count; context: captured GPU boundary points compared with the CPU
      //   float model
      {"vs_cpu_float_points", results::Unit::kCount, D::kNone, &F::device_points},
      // vs_cpu_float_points_differing: count; 0 when the device agrees with the CPU float model
      //   (best), up to vs_cpu_float_points (worst)
      {"vs_cpu_float_points_differing", results::Unit::kCount, D::kLowerIsBetter,
       &F::device_points_differing},
      // vs_cpu_float_max_ulp: float ulps; 0 (best), up to ~2^32 (worst)
      {"vs_cpu_float_max_ulp", results::Unit::kUlp, D::kLowerIsBetter, &F::device_max_ulp},
  };
  return kTable;
}

// What the decision, advise and the report read of the crack rows (results::DecisionInput).
std::vector<results::DecisionInput> cracksDecisionInputs() {
  return {{.role = results::DecisionRole::kCrackPoints,
           .label = "points that differ or are unpaired",
           .metrics = {"points_not_equal", "unpaired_points"},
           .where = {{kEdgeKindKey, ""}},
           .rows_on_path = true,
           .device_rows = {{"backend", "gpu"}}},
          {.role = results::DecisionRole::kCrackGap,
           .label = "largest gap",
           .metrics = {"max_gap_world"},
           .where = {{kEdgeKindKey, ""}}},
          {.role = results::DecisionRole::kCrackPlace,
           .label = "where the largest gap is",
           .metrics = {"worst_patch_a", "worst_local_a", "worst_patch_b", "worst_local_b",
                       "worst_is_corner", "worst_t"},
           .where = {{kEdgeKindKey, ""}}},
          {.role = results::DecisionRole::kCrackPicture,
           .label = "CPU float cracks drawn",
           .metrics = {"points_not_equal"},
           .where = {{"backend", "cpu_float"}, {"displacement", ""}, {kEdgeKindKey, ""}}},
          {.role = results::DecisionRole::kAdviceCracks,
           .label = "watertight",
           .column = "yes when every row is bitwise watertight",
           .metrics = {"points_not_equal", "unpaired_points"},
           .where = {{kEdgeKindKey, ""}}}};
}

class CracksMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "cracks",
        .title = "Crack gaps between patches",
        .description =
            "gaps between the positions two patches compute at the same tessellated point of a "
            "shared edge or corner, in world units and float ulps, on the CPU (float, shader "
            "order) "
            "and on the device",
        .metrics = crackTable().specs(),
        .headline = {"points_not_equal", "max_gap_world"},
        .notes =
            {"an asset of more than 2,048 patches (kCrackPatchBudget) is compared on a sample "
             "(patches_compared): every feature patch (a corner whose welded vertex has another "
             "patch count than the regular 4 or 6, a boundary, hole or seam edge, a crease or "
             "corner tag), then runs of 16 consecutive other patches, evenly spaced; shared_* "
             "count "
             "its edges and corners with two or more sampled sides, and every figure covers a "
             "subset "
             "of the full pairs (never more cracks, never a larger gap)",
             "rows without a levels key: uniform levels (every outer and inner level = level); "
             "shared edges and corners found "
             "by welded control-mesh position (seam_edges: shared only after welding); each side "
             "after the first is compared with the first at every tessellated point, paired by "
             "edge "
             "parameter t <-> 1 - t",
             "points_not_equal: some float component differs (+0 = -0); max_gap_ulp: max over "
             "components of the float ulp distance (huge near 0: 1e-8 against 0 is ~8e8 ulp); "
             "max_gap_scale_ulp: the largest component gap over the float spacing at the control "
             "mesh's largest |coordinate|; worst_*: the pair with the largest world gap (local "
             "edge k "
             "runs from corner k to k + 1; t from corner local_a), -1 when none",
             "cpu_float: SurfacePatches::evaluateFloat (the shader's operation order); gpu: the "
             "technique's TCS/TES on the run's Vulkan device, positions captured by SSBO (path "
             "tessellator), or its surface on the compute path (path compute: the compute "
             "tessellator and the technique's compute shader, the same surface functions as its "
             "TES, the boundary points kept; the default suite on catmark_xord_interior and "
             "loop_xord_interior, --suite full on every asset of up to 2,048 patches; never "
             "displaced); "
             "vs_cpu_float_*: "
             "every captured vertex (every boundary point of every patch) against evaluateFloat at "
             "the same gl_TessCoord (0 on cpu_float rows by definition)",
             "gpu backend at every level on every asset; the device captures only the boundary "
             "points (vs_cpu_float_* cover those) and tessellates each patch with its outer levels "
             "and its inner levels lowered to at most 1 (integer, pow2), 2 (fractional_even) or 3 "
             "(fractional_odd) wherever the CPU tessellator shows the boundary points unchanged "
             "(the interior is never compared)",
             "levels = edge_pattern rows: per-edge levels, level = the base (edge levels base x "
             "{0.5, 0.75, 1, 1.375, 1.75} by a hash of the edge's two welded end vertices, so both "
             "sides of a shared edge agree; inner levels the D3D11 average of the patch's edges)",
             "displaced surfaces (rows with displacement and sampling keys): the technique's "
             "patches "
             "moved by a baked map; naive sampling reads each patch's own tile at its own (u, v), "
             "watertight sampling reads a shared corner or edge from its owner's tile at the "
             "owner's (u, v) (displacement direction from per-vertex data both sides share); "
             "summaries leave these rows out, the chart below shows them",
             "rows with an edge_kind key (assets with a seam only, CPU float, uniform levels): the "
             "same figures over one kind of shared edge and corner: seam (the control mesh's "
             "faces there carry different normals or uvs, or positions welded together: where an "
             "engine's mesh, a glTF file's, splits its vertices), boundary (corners on the mesh "
             "boundary) or interior; summaries and decisions read the rows without the key"},
        .summary_scope = {{"displacement", ""}, {kEdgeKindKey, ""}},
        // Which variants crack, on which backend: 0 (no bar on the log axis) is watertight.
        .plots = {results::PlotSpec{
                      .title =
                          "Points where two patches differ, per variant (the largest count over "
                          "assets, spacings and levels; no bar: 0, watertight)",
                      .kind = results::PlotKind::kBar,
                      .x = "variant",
                      .y = "points_not_equal",
                      .series = "backend",
                      .facet = "",
                      .where = {{"displacement", ""}, {kEdgeKindKey, ""}},
                      .log_y = true,
                      .reduce = results::PlotReduce::kMax},
                  results::PlotSpec{
                      .title = "Displaced surfaces: points where two patches differ, per sampling "
                               "(largest count over maps, spacings and levels; no bar: watertight)",
                      .kind = results::PlotKind::kBar,
                      .x = "sampling",
                      .y = "points_not_equal",
                      .series = "backend",
                      .facet = "",
                      .where = {{"displacement", "*"}},
                      .log_y = true,
                      .reduce = results::PlotReduce::kMax}},
        .decision_inputs = cracksDecisionInputs()};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    MeasureRequirements requirements{
        {MeasureNeed::kSurface, MeasureNeed::kGpu}, VariantPolicy::kEveryVariant, {}};
    requirements.displaced_surfaces = true;
    return requirements;
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    const techniques::SurfacePatches& patches = *input.patches;
    // Why the GPU rows cannot run here; they are then rows with status skipped and this
    // reason, under the keys a run with a device measures them by.
    std::string gpu_reason;
    if (patches.gpuPrograms().empty()) {
      gpu_reason = "the technique has no GPU program";
    } else if (input.gpu == nullptr) {
      gpu_reason = "no Vulkan device (" + input.gpu_unavailable + ")";
    }
    // The compute path's rows, skipped on an asset above the crack budget: its capture
    // uploads the program and builds every patch once per chunk of its buffers (530 s for
    // acc's six variants on the 20,480-quad catmark_single_crease_r4, against 14 s for the
    // rest of the measure).
    std::string compute_reason = gpu_reason;
    if (compute_reason.empty() && patches.patchCount() > kCrackPatchBudget) {
      compute_reason = "the compute path's crack capture runs on assets of up to " +
                       std::to_string(kCrackPatchBudget) + " patches (this one has " +
                       std::to_string(patches.patchCount()) + ")";
    }
    // Both backends of one spacing and level in turn: the session evaluates on the CPU
    // once for the two.
    CrackSession session(patches);
    const std::vector<CrackBackend> backends = crackBackends(input);
    const bool short_grid = input.displacement != nullptr && input.suite == SuiteMode::kDefault;
    const std::span<const tess::Spacing> spacings =
        short_grid ? std::span<const tess::Spacing>(kDisplacedDefaultSpacings)
                   : std::span<const tess::Spacing>(kCrackSpacings);
    const std::span<const LevelChoice> crack_levels =
        short_grid ? std::span<const LevelChoice>(kDisplacedDefaultLevels)
                   : std::span<const LevelChoice>(kCrackLevels);
    for (tess::Spacing spacing : spacings) {
      for (const LevelChoice& level : crack_levels) {
        for (CrackBackend backend : backends) {
          result.rows.push_back(crackRow(
              spacing, level.text, backend, nullptr, reasonOf(backend, gpu_reason, compute_reason),
              [&] { return session.measure(spacing, level.level, backend, input.gpu); }));
        }
      }
    }
    // The per-edge pattern rows come last so the uniform rows keep their places.
    for (tess::Spacing spacing : spacings) {
      const std::vector<tess::Levels> levels =
          lod::edgePatternLevels(patches, spacing, kEdgePatternBase.level);
      for (CrackBackend backend : backends) {
        result.rows.push_back(
            crackRow(spacing, kEdgePatternBase.text, backend, kEdgePatternKey,
                     reasonOf(backend, gpu_reason, compute_reason),
                     [&] { return session.measure(spacing, levels, backend, input.gpu); }));
      }
    }
    // Seams apart, after every other row so those keep their places.
    if (session.hasSeams()) appendEdgeKindRows(session, spacings, crack_levels, &result);
    return result;
  }

 private:
  // The CPU float rows of each edge kind, keyed edge_kind, at the uniform levels.
  static void appendEdgeKindRows(CrackSession& session, std::span<const tess::Spacing> spacings,
                                 std::span<const LevelChoice> crack_levels,
                                 results::MeasureResult* result) {
    for (EdgeKind kind : kEdgeKinds) {
      for (tess::Spacing spacing : spacings) {
        for (const LevelChoice& level : crack_levels) {
          results::MetricRow row =
              crackRow(spacing, level.text, CrackBackend::kCpuFloat, nullptr, "", [&] {
                return session.measure(spacing, level.level, CrackBackend::kCpuFloat, nullptr,
                                       kind);
              });
          row.keys[kEdgeKindKey] = std::string(toString(kind));
          result->rows.push_back(std::move(row));
        }
      }
    }
  }

  // One row: keys spacing, level, backend (and levels when not uniform), then the
  // figures, or status skipped or failed with the reason there are none. A GPU row is
  // skipped with gpu_reason when that is set; a GPU failure is a failed row, a CPU one throws.
  template <class MeasureFn>
  static results::MetricRow crackRow(tess::Spacing spacing, const char* level, CrackBackend backend,
                                     const char* levels_key, const std::string& gpu_reason,
                                     MeasureFn measure) {
    results::MetricRow row;
    row.keys["spacing"] = std::string(tess::toString(spacing));
    row.keys["level"] = std::string(level);
    row.keys["backend"] = toString(backend);
    row.keys["path"] = std::string(crackPath(backend));
    if (levels_key != nullptr) row.keys["levels"] = std::string(levels_key);
    if (backend != CrackBackend::kCpuFloat && !gpu_reason.empty()) {
      return results::unmeasuredRow(std::move(row.keys), results::MeasureStatus::kSkipped,
                                    gpu_reason);
    }
    try {
      const CrackFigures f = measure();
      if (!f.measured) {
        return results::unmeasuredRow(std::move(row.keys), results::MeasureStatus::kSkipped,
                                      f.skipped_reason);
      }
      row.metrics = crackTable().metrics(f);
    } catch (const std::exception& error) {
      if (backend == CrackBackend::kCpuFloat) throw;
      return results::unmeasuredRow(std::move(row.keys), results::MeasureStatus::kFailed,
                                    error.what());
    }
    return row;
  }
};

TB_REGISTER_MEASURE(CracksMeasure);

}  // namespace
}  // namespace tb::measures
