// The "adaptivity" measure: view-dependent factor policies along camera paths
// (adaptivity.h). Rows keyed policy, spacing and frame (camera_path added by the suite),
// and per policy and spacing one summary row (key summary) with the triangles needed for
// a 1 px tessellation error over the whole path against the best uniform level.
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "harness/lod/reference_scheme.h"
#include "harness/measures/adaptivity/adaptivity.h"
#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "reference/limit_surface.h"

namespace tb::measures {
namespace {

constexpr double kErrorTargetPx = 1.0;
constexpr const char* kSummaryKey = "max_error_1px";

// What runs in each suite. Default: three policies at fractional_odd along the default
// path (the suite's 4-frame orbit), about 0.1-0.3 s a record. Full: every policy (the
// order-dependent ones show what a crack-unsafe policy does), every spacing.
struct Grid {
  std::vector<std::string> policies;
  std::vector<tess::Spacing> spacings;
  std::vector<std::string> summary_policies;
  std::vector<tess::Spacing> summary_spacings;
  int search_steps = 7;
};

Grid gridFor(SuiteMode suite, const techniques::SurfacePatches& patches) {
  Grid grid;
  if (suite == SuiteMode::kFull) {
    grid.policies = {
        "uniform",     "distance",          "sphere_diameter",  "lp2_edge", "lp2_edge_silhouette",
        "error_bound", "error_bound_loose", "error_bound_dense"};
    // Roundness scales by how the vertex normals turn: the surfaces built from them
    // (PN triangles, Phong tessellation: the techniques graded against Loop).
    if (patches.approximates() == techniques::LimitScheme::kLoop)
      grid.policies.push_back("lp2_edge_roundness");
    grid.policies.push_back("sphere_diameter_order_dependent");
    grid.policies.push_back("distance_order_dependent");
    grid.spacings = {tess::Spacing::kInteger, tess::Spacing::kPow2, tess::Spacing::kFractionalOdd,
                     tess::Spacing::kFractionalEven};
    grid.summary_policies = {"distance", "sphere_diameter", "lp2_edge", "lp2_edge_silhouette",
                             "error_bound"};
    if (patches.approximates() == techniques::LimitScheme::kLoop) {
      grid.summary_policies.push_back("lp2_edge_roundness");
    }
    grid.summary_spacings = {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd};
    return grid;
  }
  // error_bound's frames run in --suite full; its summary (one pass, no search) here.
  grid.policies = {"sphere_diameter", "distance", "lp2_edge"};
  grid.spacings = {tess::Spacing::kFractionalOdd};
  grid.summary_policies = {"sphere_diameter", "error_bound"};
  grid.search_steps = 5;
  grid.summary_spacings = grid.spacings;
  return grid;
}

// Accessors of the frame table's figures that a frame may lack.
constexpr auto frameGpu = [](auto member) {
  return [member](const AdaptivityFrame& f) -> std::optional<double> {
    return f.gpu_measured ? std::optional<double>(double(f.*member)) : std::nullopt;
  };
};
constexpr auto frameCpuCrack = [](auto member) {
  return [member](const AdaptivityFrame& f) { return double(f.cracks_cpu.*member); };
};
constexpr auto frameGpuCrack = [](auto member) {
  return [member](const AdaptivityFrame& f) -> std::optional<double> {
    return f.gpu_measured && f.cracks_gpu.measured
               ? std::optional<double>(double(f.cracks_gpu.*member))
               : std::nullopt;
  };
};
constexpr auto frameReference = [](auto member) {
  return [member](const AdaptivityFrame& f) -> std::optional<double> {
    return f.screen.reference_measured && f.screen.reference_error.samples > 0
               ? std::optional<double>(f.screen.reference_error.*member)
               : std::nullopt;
  };
};

// The compute path's figures (core/gpu/compute_path.h), after the table's own.
std::vector<MetricField<AdaptivityFrame>> adaptivityComputeFields() {
  using D = results::Direction;
  using F = AdaptivityFrame;
  return {
      // compute_level_mismatches: count; 0 when the compute path's levels (the same policy in
      //   compute) equal the TCS's bitwise (best), up to patches (worst); only where the compute
      //   path runs
      {"compute_level_mismatches", results::Unit::kCount, D::kLowerIsBetter,
       [](const F& f) -> std::optional<double> {
         if (!f.compute_measured) return std::nullopt;
         return double(f.compute_level_mismatches);
       }},
      // compute_counts_differ: flag; 0 when the compute tessellator's points and triangles
      //   equal the CPU tessellator's (best), 1 (worst)
      {"compute_counts_differ", results::Unit::kFlag, D::kLowerIsBetter,
       [](const F& f) -> std::optional<double> {
         if (!f.compute_measured) return std::nullopt;
         return f.compute_triangles != f.triangles || f.compute_domain_points != f.domain_points
                    ? 1.0
                    : 0.0;
       }},
  };
}

// The frame table's screen-space fields (edge lengths, errors and pops in pixels), then its
// compute-path fields: the rows' metric order after the counts and crack figures.
std::vector<MetricField<AdaptivityFrame>> screenAndComputeFields() {
  using D = results::Direction;
  using F = AdaptivityFrame;
  std::vector<MetricField<F>> fields{
      // visible_edges: count; context: tessellated edges with an end in the viewport
      {"visible_edges", results::Unit::kCount, D::kNone,
       [](const F& f) { return double(f.screen.edges.edges); }},
      // edge_px_median: pixels; context (the band around the target is what counts)
      {"edge_px_median", results::Unit::kPixels, D::kNone,
       [](const F& f) { return f.screen.edges.median_px; }},
      // edge_px_p05: pixels; context
      {"edge_px_p05", results::Unit::kPixels, D::kNone,
       [](const F& f) { return f.screen.edges.p05_px; }},
      // edge_px_p95: pixels; context
      {"edge_px_p95", results::Unit::kPixels, D::kNone,
       [](const F& f) { return f.screen.edges.p95_px; }},
      // edge_fraction_in_band: ratio; 1 when every edge is within [0.5, 2] x target (best), 0
      //   (worst)
      {"edge_fraction_in_band", results::Unit::kRatio, D::kHigherIsBetter,
       [](const F& f) { return f.screen.edges.fraction_in_band; }},
      // error_samples: count; context
      {"error_samples", results::Unit::kCount, D::kNone,
       [](const F& f) { return double(f.screen.tessellation_error.samples); }},
      // tess_error_max_px: pixels; 0 (best), unbounded (worst); 1 px is the criterion
      {"tess_error_max_px", results::Unit::kPixels, D::kLowerIsBetter,
       [](const F& f) { return f.screen.tessellation_error.max_px; }},
      // tess_error_rms_px: pixels; 0 (best), unbounded (worst)
      {"tess_error_rms_px", results::Unit::kPixels, D::kLowerIsBetter,
       [](const F& f) { return f.screen.tessellation_error.rms_px; }},
      // reference_error_max_px: pixels; 0 (best), unbounded (worst); against the reference limit
      {"reference_error_max_px", results::Unit::kPixels, D::kLowerIsBetter,
       frameReference(&lod::ScreenErrorFigures::max_px)},
      // reference_error_rms_px: pixels; 0 (best), unbounded (worst)
      {"reference_error_rms_px", results::Unit::kPixels, D::kLowerIsBetter,
       frameReference(&lod::ScreenErrorFigures::rms_px)},
      // pop_max_px: pixels; 0 when a factor change moves nothing (best), unbounded (worst)
      {"pop_max_px", results::Unit::kPixels, D::kLowerIsBetter,
       [](const F& f) -> std::optional<double> {
         return f.frame > 0 ? std::optional<double>(f.pop.max_px) : std::nullopt;
       }},
  };
  for (MetricField<F>& field : adaptivityComputeFields()) fields.push_back(std::move(field));
  return fields;
}

// Per-frame rows. Best cases: mismatches and crack figures 0, errors and pops 0 px,
// edge_fraction_in_band 1; worst: any mismatch (a crack), errors of many pixels.
const MetricTable<AdaptivityFrame>& frameTable() {
  using D = results::Direction;
  using F = AdaptivityFrame;
  static const MetricTable<F> kTable{
      {
          // patches: count; context
          {"patches", results::Unit::kCount, D::kNone, &F::patches},
          // triangles: count; 0 (best), unbounded (worst); the CPU tessellator under the twin's
          // levels
          {"triangles", results::Unit::kCount, D::kLowerIsBetter, &F::triangles},
          // domain_points: count; 0 (best), unbounded (worst)
          {"domain_points", results::Unit::kCount, D::kLowerIsBetter, &F::domain_points},
          // gpu_tcs_patches: count; context: lavapipe's pipeline statistics
          {"gpu_tcs_patches", results::Unit::kCount, D::kNone, frameGpu(&F::gpu_tcs_patches)},
          // gpu_tes_invocations: count; context
          {"gpu_tes_invocations", results::Unit::kCount, D::kNone,
           frameGpu(&F::gpu_tes_invocations)},
          // gpu_triangles: count; context
          {"gpu_triangles", results::Unit::kCount, D::kNone,
           [](const F& f) -> std::optional<double> {
             if (!f.gpu_measured || !f.gpu_triangles_counted) return std::nullopt;
             return double(f.gpu_triangles);
           }},
          // gpu_counts_differ: flag; 0 when the device counts equal the CPU tessellator's (best), 1
          //   (worst)
          {"gpu_counts_differ", results::Unit::kFlag, D::kLowerIsBetter,
           [](const F& f) -> std::optional<double> {
             if (!f.gpu_measured) return std::nullopt;
             const bool differ = f.gpu_tes_invocations != f.domain_points ||
                                 f.gpu_tcs_patches != f.patches ||
                                 (f.gpu_triangles_counted && f.gpu_triangles != f.triangles);
             return differ ? 1.0 : 0.0;
           }},
          // twin_level_mismatches: count; 0 when the TCS levels equal the twin's bitwise (best), up
          // to
          //   patches (worst)
          {"twin_level_mismatches", results::Unit::kCount, D::kLowerIsBetter,
           frameGpu(&F::twin_level_mismatches)},
          // factor_mismatches_cpu: count; 0 when shared edges agree (best), up to the shared edges
          //   (worst)
          {"factor_mismatches_cpu", results::Unit::kCount, D::kLowerIsBetter,
           &F::factor_mismatches_cpu},
          // factor_mismatches_gpu: count; 0 (best), up to the shared edges (worst)
          {"factor_mismatches_gpu", results::Unit::kCount, D::kLowerIsBetter,
           frameGpu(&F::factor_mismatches_gpu)},
          // crack_points_not_equal_cpu: count; 0 when watertight (best), up to the points compared
          //   (worst)
          {"crack_points_not_equal_cpu", results::Unit::kCount, D::kLowerIsBetter,
           frameCpuCrack(&CrackFigures::points_not_equal)},
          // crack_unpaired_points_cpu: count; 0 (best), up to the edge points (worst)
          {"crack_unpaired_points_cpu", results::Unit::kCount, D::kLowerIsBetter,
           frameCpuCrack(&CrackFigures::unpaired_points)},
          // crack_max_gap_world_cpu: world units; 0 when watertight (best), unbounded (worst)
          {"crack_max_gap_world_cpu", results::Unit::kWorld, D::kLowerIsBetter,
           frameCpuCrack(&CrackFigures::max_gap_world)},
          // crack_points_not_equal_gpu: count; 0 when watertight (best), up to the points compared
          //   (worst)
          {"crack_points_not_equal_gpu", results::Unit::kCount, D::kLowerIsBetter,
           frameGpuCrack(&CrackFigures::points_not_equal)},
          // crack_unpaired_points_gpu: count; 0 (best), up to the edge points (worst)
          {"crack_unpaired_points_gpu", results::Unit::kCount, D::kLowerIsBetter,
           frameGpuCrack(&CrackFigures::unpaired_points)},
          // crack_max_gap_world_gpu: world units; 0 when watertight (best), unbounded (worst)
          {"crack_max_gap_world_gpu", results::Unit::kWorld, D::kLowerIsBetter,
           frameGpuCrack(&CrackFigures::max_gap_world)},
      },
      screenAndComputeFields()};
  return kTable;
}

// Summary rows: the number to choose by.
const MetricTable<AdaptivitySummary>& summaryTable() {
  using D = results::Direction;
  using S = AdaptivitySummary;
  static const MetricTable<S> kTable{
      // triangle_ratio_vs_uniform: ratio; towards 0 (best), 1 as uniform, above 1 (worse than
      //   uniform)
      {"triangle_ratio_vs_uniform", results::Unit::kRatio, D::kLowerIsBetter,
       [](const S& s) -> std::optional<double> {
         return s.reached && s.uniform_reached ? std::optional<double>(s.triangle_ratio_vs_uniform)
                                               : std::nullopt;
       }},
      // triangle_ratio_vs_ideal: ratio; 1 (best: as few triangles as the per-patch ideal),
      //   unbounded (worst); only where the policy reached the target
      {"triangle_ratio_vs_ideal", results::Unit::kRatio, D::kLowerIsBetter,
       [](const S& s) -> std::optional<double> {
         return s.reached && s.ideal_triangles_per_frame > 0
                    ? std::optional<double>(s.triangle_ratio_vs_ideal)
                    : std::nullopt;
       }},
      // triangles_per_frame_at_target: count; 0 (best), unbounded (worst)
      {"triangles_per_frame_at_target", results::Unit::kCount, D::kLowerIsBetter,
       &S::triangles_per_frame},
      // ideal_triangles_per_frame: count; context: the per-patch ideal's mean triangles per frame
      {"ideal_triangles_per_frame", results::Unit::kCount, D::kNone, &S::ideal_triangles_per_frame},
      // ideal_path_max_error_px: pixels; context: the ideal's largest error, within the target
      //   wherever a uniform level reaches it (frames the per-patch search misses take uniform)
      {"ideal_path_max_error_px", results::Unit::kPixels, D::kNone, &S::ideal_max_error_px},
      // ideal_uniform_frames: frames; context: frames where the ideal took the uniform level
      //   (the per-patch search missed the target there or needed more triangles); best 0
      {"ideal_uniform_frames", results::Unit::kCount, D::kNone, &S::ideal_uniform_frames},
      // frames_beyond_top_level: frames; context (error_bound only, else empty): frames where
      //   some patch's bound is above the target even at the top level, so no tessellation is
      //   certain to meet it there; best 0, worst every frame
      {"frames_beyond_top_level", results::Unit::kCount, D::kNone,
       [](const S& s) -> std::optional<double> {
         return s.error_bound ? std::optional<double>(s.beyond_top_frames) : std::nullopt;
       }},
      // uniform_triangles_per_frame: count; context
      {"uniform_triangles_per_frame", results::Unit::kCount, D::kNone,
       &S::uniform_triangles_per_frame},
      // uniform_level: level; context
      {"uniform_level", results::Unit::kCount, D::kNone, &S::uniform_level},
      // error_target_px: pixels; context
      {"error_target_px", results::Unit::kPixels, D::kNone, &S::error_target_px},
      // target_reached: flag; 1 (best), 0 (worst)
      {"target_reached", results::Unit::kFlag, D::kHigherIsBetter,
       [](const S& s) { return s.reached ? 1.0 : 0.0; }},
      // policy_target: the policy's own unit; context
      {"policy_target", results::Unit::kRatio, D::kNone, &S::target},
      // path_max_error_px: pixels; context: at the target found
      {"path_max_error_px", results::Unit::kPixels, D::kNone, &S::max_error_px},
      // uniform_reached: flag; context
      {"uniform_reached", results::Unit::kFlag, D::kNone,
       [](const S& s) { return s.uniform_reached ? 1.0 : 0.0; }},
      // uniform_path_max_error_px: pixels; context
      {"uniform_path_max_error_px", results::Unit::kPixels, D::kNone, &S::uniform_max_error_px},
      // search_passes: count; context
      {"search_passes", results::Unit::kCount, D::kNone, &S::evaluations},
  };
  return kTable;
}

std::vector<results::MetricSpec> allSpecs() {
  std::vector<results::MetricSpec> specs = summaryTable().specs();
  for (const results::MetricSpec& spec : frameTable().specs()) specs.push_back(spec);
  return specs;
}

// Notes true of every adaptivity record: the method, once under the measure.
std::vector<std::string> adaptivityNotes() {
  return {
      "per frame of a camera path, each factor policy's levels (computed in the technique's own "
      "TCS and by its bitwise CPU twin, harness/lod) give the triangles drawn, the factor and "
      "crack mismatches on shared edges (CPU and lavapipe), on-screen edge lengths, the "
      "tessellation's screen-space error and popping in pixels; gpu_* and compute_* are the "
      "device's and the compute path's counts against the CPU tessellator's",
      "summary rows (summary = max_error_1px): per policy, the coarsest target whose error "
      "stays within 1 px on every frame, its mean triangles per frame, against the lowest "
      "uniform level and the per-patch ideal that do the same (controls: the order-dependent, "
      "loose and dense policies, made to fail)",
      "how each figure is found (the searches, the ideal, error_bound's bound and its floor, "
      "which grid each suite runs): docs/derivations/adaptivity.md"};
}

class AdaptivityMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "adaptivity",
        .title = "Tessellation-factor adaptivity along camera paths",
        .description =
            "view-dependent factor policies per frame of a camera path: triangles, crack safety of "
            "the factors, on-screen edge length, screen-space error and popping in pixels; and the "
            "triangles a policy needs for a 1 px tessellation error against uniform levels",
        .metrics = allSpecs(),
        .headline = {"triangle_ratio_vs_uniform", "triangle_ratio_vs_ideal",
                     "factor_mismatches_cpu", "tess_error_max_px"},
        .notes = adaptivityNotes(),
        .summary_scope = {},
        // The per-frame trade-off of each policy: triangles drawn against the largest
        // on-screen tessellation error, one chart per asset (every technique's frames).
        .plots = {results::PlotSpec{
            .title = "Triangles against tessellation error in pixels, per frame",
            .kind = results::PlotKind::kScatter,
            .x = "tess_error_max_px",
            .y = "triangles",
            .series = "policy",
            .facet = "asset",
            .where = {{"frame", "*"}},
            .log_x = true,
            .log_y = true}},
        // control_rows: the crack-unsafe policies, and the error bound loosened on purpose.
        .control_rows = {{{"policy", "*_order_dependent"}},
                         {{"policy", "error_bound_loose"}},
                         {{"policy", "error_bound_dense"}}},
        // comparisons: triangles per frame at 1 px per policy, against uniform and the ideal.
        .comparisons = {results::ComparisonSpec{
            .title = "Triangles per frame at a 1 px tessellation error (fewer is better); "
                     "ideal = the per-patch optimum every policy is held against",
            .where = {{"summary", kSummaryKey}},
            .column_key = "policy",
            .metric = "triangles_per_frame_at_target",
            .valid_flag = "target_reached",
            .extra_columns = {{"uniform", "uniform_triangles_per_frame"},
                              {"ideal", "ideal_triangles_per_frame"}},
            .facets = {"asset", "camera_path"}}},
        .decision_inputs = {{.role = results::DecisionRole::kTrianglesAtTarget,
                             .label = "triangles at 1 px",
                             .column = "triangles/frame at 1 px (count, best policy)",
                             .metrics = {"triangles_per_frame_at_target"},
                             .where = {{"summary", kSummaryKey}},
                             .reduce = results::DecisionReduce::kMin,
                             .valid_flag = "target_reached",
                             .first_of = "camera_path",
                             .chosen_key = "policy"},
                            {.role = results::DecisionRole::kTriangleRatio,
                             .label = "triangles against uniform's at 1 px",
                             .metrics = {"triangle_ratio_vs_uniform"},
                             .where = {{"summary", kSummaryKey}},
                             .chosen_key = "policy"}}};
    return kInfo;
  }

  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSurface, MeasureNeed::kCameraPath, MeasureNeed::kGpu},
            VariantPolicy::kDefaultOnly,
            {}};
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    const techniques::SurfacePatches& patches = *input.patches;
    const view::CameraPath& path = requireCameraPath(input);

    std::unique_ptr<ref::LimitSurface> limit;
    try {
      limit = std::make_unique<ref::LimitSurface>(patches.controlMesh(),
                                                  lod::referenceScheme(patches.approximates()));
    } catch (const mesh::InputError& error) {
      // The per-frame rows then lack reference_error_*; this row says why.
      result.rows.push_back(results::unmeasuredRow({{"part", "reference_error"}},
                                                   results::MeasureStatus::kSkipped, error.what()));
    }
    AdaptivityRun run(patches, input.gpu, input.gpu_unavailable, limit.get());
    if (!run.gpuSkipReason().empty()) {
      // The gpu_* and *_gpu figures live in the per-frame rows; without them, this row says why.
      result.rows.push_back(results::unmeasuredRow(
          {{"part", "gpu"}}, results::MeasureStatus::kSkipped, run.gpuSkipReason()));
    }
    const Grid grid = gridFor(input.suite, patches);
    AdaptivityParts parts;
    parts.compute = runsComputePath(input);

    for (const std::string& name : grid.summary_policies) {
      const lod::FactorPolicy policy = *lod::parseFactorPolicy(name);
      for (tess::Spacing spacing : grid.summary_spacings) {
        results::MetricRow row;
        row.keys["policy"] = name;
        row.keys["spacing"] = std::string(tess::toString(spacing));
        row.keys["summary"] = kSummaryKey;
        if (const std::string& why = run.policyUnavailable(policy); !why.empty()) {
          result.rows.push_back(
              results::unmeasuredRow(row.keys, results::MeasureStatus::kSkipped, why));
          continue;
        }
        row.metrics = summaryTable().metrics(
            run.summarise(policy, spacing, path.views, kErrorTargetPx, grid.search_steps));
        result.rows.push_back(std::move(row));
      }
    }
    for (const std::string& name : grid.policies) {
      const lod::FactorPolicy policy = *lod::parseFactorPolicy(name);
      for (tess::Spacing spacing : grid.spacings) {
        if (const std::string& why = run.policyUnavailable(policy); !why.empty()) {
          result.rows.push_back(
              results::unmeasuredRow({{"policy", name},
                                      {"spacing", std::string(tess::toString(spacing))},
                                      {"frame", "all"}},
                                     results::MeasureStatus::kSkipped, why));
          continue;
        }
        for (const AdaptivityFrame& frame : run.frames(policy, spacing, path.views, parts)) {
          results::MetricRow row;
          row.keys["policy"] = name;
          row.keys["spacing"] = std::string(tess::toString(spacing));
          row.keys["frame"] = std::to_string(frame.frame);
          row.metrics = frameTable().metrics(frame);
          result.rows.push_back(std::move(row));
        }
      }
    }
    return result;
  }
};

TB_REGISTER_MEASURE(AdaptivityMeasure);

}  // namespace
}  // namespace tb::measures
