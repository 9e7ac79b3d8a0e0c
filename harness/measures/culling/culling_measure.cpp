// The "culling" measure: patch culling policies (cull_policy.h) along camera paths
// (culling.h). Rows keyed policy and frame (camera_path added by the suite), and per policy
// one summary row (key summary = path) with what a person chooses a policy by: the share of
// patches and TES work it removes, and the visible patches it wrongly removes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "harness/measures/culling/culling.h"
#include "harness/measures/culling/culling_cost.h"
#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"

namespace tb::measures {
namespace {

constexpr const char* kSummaryKey = "path";

// Default suite: level 4, the oracle at half the path's resolution per axis (960 x 540 for
// the bundled paths); full: level 8 at the path's own resolution.
CullingOptions optionsFor(SuiteMode suite) {
  if (suite == SuiteMode::kFull) return {.level = 8, .render_scale = 1};
  return {.level = 4, .render_scale = 0.5};
}

// A figure of a frame or summary (T: CullingFrame or CullingSummary) present only when the
// device ran (gpu) or the oracle rendered (oracle).
template <class T, class M>
auto gpu(M T::*member) {
  return [member](const T& t) -> std::optional<double> {
    return t.gpu_measured ? std::optional<double>(double(t.*member)) : std::nullopt;
  };
}
template <class T, class M>
auto oracle(M T::*member) {
  return [member](const T& t) -> std::optional<double> {
    return t.oracle_measured ? std::optional<double>(double(t.*member)) : std::nullopt;
  };
}
// culled / cullable when the oracle ran and something was cullable; absent otherwise.
template <class T>
auto efficiency(uint64_t T::*culled, uint64_t T::*cullable) {
  return [culled, cullable](const T& t) -> std::optional<double> {
    if (!t.oracle_measured || t.*cullable == 0) return std::nullopt;
    return double(t.*culled) / double(t.*cullable);
  };
}

// The compute path's figures (core/gpu/compute_path.h), after the table's own.
std::vector<MetricField<CullingFrame>> cullingComputeFields() {
  using D = results::Direction;
  using F = CullingFrame;
  return {
      // compute_mismatches: count; 0 when the compute path (the policy in compute) decides as
      //   the TCS (best), up to patches (worst); only where the compute path runs
      {"compute_mismatches", results::Unit::kCount, D::kLowerIsBetter,
       [](const F& f) -> std::optional<double> {
         if (!f.compute_measured) return std::nullopt;
         return double(f.compute_mismatches);
       }},
  };
}

// Per-frame rows. Best cases: false_culls 0, missed_culls 0, twin_mismatches 0, culled
// as many patches as show no pixel; worst: a visible patch culled (a hole in the image).
const MetricTable<CullingFrame>& frameTable() {
  using D = results::Direction;
  using F = CullingFrame;
  static const MetricTable<F> kTable{
      {
          // patches: count; context
          {"patches", results::Unit::kCount, D::kNone, &F::patches},
          // culled_patches: count; context (see culled_fraction)
          {"culled_patches", results::Unit::kCount, D::kNone, &F::culled_patches},
          // culled_fraction: ratio; up to cullable / patches with no false cull (best), 0 (worst:
          //   nothing culled)
          {"culled_fraction", results::Unit::kRatio, D::kHigherIsBetter,
           [](const F& f) {
             return f.patches > 0 ? double(f.culled_patches) / double(f.patches) : 0.0;
           }},
          // tes_invocations: count; 0 (best), tes_invocations_unculled (worst: no saving)
          {"tes_invocations", results::Unit::kCount, D::kLowerIsBetter, &F::tes_invocations},
          // tes_invocations_unculled: count; context
          {"tes_invocations_unculled", results::Unit::kCount, D::kNone,
           &F::tes_invocations_unculled},
          // tes_saving: ratio 1 - TES invocations / unculled; 1 (best), 0 (worst)
          {"tes_saving", results::Unit::kRatio, D::kHigherIsBetter,
           [](const F& f) {
             return f.tes_invocations_unculled > 0
                        ? 1 - double(f.tes_invocations) / double(f.tes_invocations_unculled)
                        : 0.0;
           }},
          // triangles: count; 0 (best), the unculled triangles (worst)
          {"triangles", results::Unit::kCount, D::kLowerIsBetter, &F::triangles},
          // gpu_culled_patches: count; context: the device's pipeline statistics
          {"gpu_culled_patches", results::Unit::kCount, D::kNone, gpu(&F::gpu_culled_patches)},
          // gpu_tes_invocations: count; 0 (best), gpu_tes_invocations_unculled (worst)
          {"gpu_tes_invocations", results::Unit::kCount, D::kLowerIsBetter,
           gpu(&F::gpu_tes_invocations)},
          // gpu_tes_invocations_unculled: count; context
          {"gpu_tes_invocations_unculled", results::Unit::kCount, D::kNone,
           gpu(&F::gpu_tes_invocations_unculled)},
          // gpu_primitives: count; 0 (best), gpu_primitives_unculled (worst)
          {"gpu_primitives", results::Unit::kCount, D::kLowerIsBetter,
           [](const F& f) -> std::optional<double> {
             return f.gpu_measured && f.gpu_primitives_counted
                        ? std::optional<double>(double(f.gpu_primitives))
                        : std::nullopt;
           }},
          // gpu_primitives_unculled: count; context
          {"gpu_primitives_unculled", results::Unit::kCount, D::kNone,
           [](const F& f) -> std::optional<double> {
             return f.gpu_measured && f.gpu_primitives_counted
                        ? std::optional<double>(double(f.gpu_primitives_unculled))
                        : std::nullopt;
           }},
          // gpu_counts_differ: flag; 0 when the device counts equal the CPU tessellator's (best), 1
          //   (worst)
          {"gpu_counts_differ", results::Unit::kFlag, D::kLowerIsBetter,
           [](const F& f) -> std::optional<double> {
             if (!f.gpu_measured) return std::nullopt;
             const bool differ = f.gpu_tes_invocations != f.tes_invocations ||
                                 (f.gpu_primitives_counted && f.gpu_primitives != f.triangles);
             return differ ? 1.0 : 0.0;
           }},
          // twin_mismatches: count; 0 when the TCS decides as the CPU twin (best), up to patches
          //   (worst)
          {"twin_mismatches", results::Unit::kCount, D::kLowerIsBetter, gpu(&F::twin_mismatches)},
          // visible_patches: count; context: patches with a pixel in the unculled render
          {"visible_patches", results::Unit::kCount, D::kNone, oracle(&F::visible_patches)},
          // cullable_patches: count; context: what an ideal back-face + frustum culler removes
          {"cullable_patches", results::Unit::kCount, D::kNone, oracle(&F::cullable_patches)},
          // false_culls: count; 0 (best), up to visible_patches (worst)
          {"false_culls", results::Unit::kCount, D::kLowerIsBetter, oracle(&F::false_culls)},
          // false_cull_pixels: pixels; 0 (best), up to the render's pixels (worst)
          {"false_cull_pixels", results::Unit::kPixels, D::kLowerIsBetter,
           oracle(&F::false_cull_pixels)},
          // missed_culls: count; 0 (best), up to cullable_patches (worst)
          {"missed_culls", results::Unit::kCount, D::kLowerIsBetter, oracle(&F::missed_culls)},
          // frame_cull_efficiency: ratio culled cullable patches / the oracle's cullable patches; 1
          //   (best: every patch an ideal back-face + frustum culler removes), 0 (worst); absent
          //   when the frame has no cullable patch
          {"frame_cull_efficiency", results::Unit::kRatio, D::kHigherIsBetter,
           efficiency(&F::culled_cullable_patches, &F::cullable_patches)},
          // frame_back_facing_efficiency: ratio, the policy's back-facing half over the patches
          // whose
          //   every triangle faces away; 1 (best), 0 (worst, or no such half); absent when none
          {"frame_back_facing_efficiency", results::Unit::kRatio, D::kHigherIsBetter,
           efficiency(&F::culled_back_facing_patches, &F::back_facing_patches)},
          // frame_frustum_efficiency: ratio, the policy's frustum half over the patches whose every
          //   triangle lies outside the frustum; 1 (best), 0 (worst, or no such half)
          {"frame_frustum_efficiency", results::Unit::kRatio, D::kHigherIsBetter,
           efficiency(&F::culled_outside_frustum_patches, &F::outside_frustum_patches)},
          // back_facing_patches, outside_frustum_patches: count; context (the oracle's, by cause)
          {"back_facing_patches", results::Unit::kCount, D::kNone, oracle(&F::back_facing_patches)},
          {"outside_frustum_patches", results::Unit::kCount, D::kNone,
           oracle(&F::outside_frustum_patches)},
          // render_width_px: pixels; context
          {"render_width_px", results::Unit::kPixels, D::kNone, oracle(&F::render_width_px)},
          // render_height_px: pixels; context
          {"render_height_px", results::Unit::kPixels, D::kNone, oracle(&F::render_height_px)},
      },
      cullingComputeFields()};
  return kTable;
}

// Summary rows, one per policy over the path: the numbers to choose a policy by.
const MetricTable<CullingSummary>& summaryTable() {
  using D = results::Direction;
  using S = CullingSummary;
  static const MetricTable<S> kTable{
      // mean_culled_fraction: ratio, mean over frames; as culled_fraction
      {"mean_culled_fraction", results::Unit::kRatio, D::kHigherIsBetter, &S::mean_culled_fraction},
      // mean_tes_saving: ratio, mean over frames; 1 (best), 0 (worst)
      {"mean_tes_saving", results::Unit::kRatio, D::kHigherIsBetter, &S::mean_tes_saving},
      // total_false_culls: count over frames; 0 (best), unbounded (worst)
      {"total_false_culls", results::Unit::kCount, D::kLowerIsBetter, oracle(&S::false_culls)},
      // total_false_cull_pixels: pixels over frames; 0 (best), unbounded (worst)
      {"total_false_cull_pixels", results::Unit::kPixels, D::kLowerIsBetter,
       oracle(&S::false_cull_pixels)},
      // total_missed_culls: count over frames; 0 (best), unbounded (worst)
      {"total_missed_culls", results::Unit::kCount, D::kLowerIsBetter, oracle(&S::missed_culls)},
      // cull_efficiency: ratio over the path, culled cullable / cullable patches summed over
      //   the frames; 1 (best: the ideal culler), 0 (worst); back_facing_efficiency and
      //   frustum_efficiency: the same for each half of the policy and its cause
      {"cull_efficiency", results::Unit::kRatio, D::kHigherIsBetter,
       efficiency(&S::culled_cullable_patches, &S::cullable_patches)},
      {"back_facing_efficiency", results::Unit::kRatio, D::kHigherIsBetter,
       efficiency(&S::culled_back_facing_patches, &S::back_facing_patches)},
      {"frustum_efficiency", results::Unit::kRatio, D::kHigherIsBetter,
       efficiency(&S::culled_outside_frustum_patches, &S::outside_frustum_patches)},
      // mean_cullable_fraction: ratio; context: the ideal culler's share
      {"mean_cullable_fraction", results::Unit::kRatio, D::kNone,
       oracle(&S::mean_cullable_fraction)},
      // total_twin_mismatches: count over frames; 0 (best), unbounded (worst)
      {"total_twin_mismatches", results::Unit::kCount, D::kLowerIsBetter,
       [](const S& s) -> std::optional<double> {
         return s.gpu_measured ? std::optional<double>(double(s.twin_mismatches)) : std::nullopt;
       }},
      // cull_bytes_per_patch: bytes of per-patch cull data the policy's test reads, mean
      //   over the patches (lod::cullBytesPerPatch); 0 (best: none), 16 + 21 x 16 (worst)
      {"cull_bytes_per_patch", results::Unit::kBytes, D::kLowerIsBetter, &S::cull_bytes_per_patch},
      // tcs_instructions: SPIR-V instructions of the technique's TCS with the policy fixed
      //   (after spirv-opt -O), mean over patches; the unculled TCS's (best), unbounded
      //   (worst); cull_instructions: the same less the unculled TCS's, 0 for none
      {"tcs_instructions", results::Unit::kCount, D::kLowerIsBetter,
       [](const S& s) { return s.tcs_instructions; }},
      {"cull_instructions", results::Unit::kCount, D::kLowerIsBetter,
       [](const S& s) { return s.cull_instructions; }},
      // frames: count; context
      {"frames", results::Unit::kCount, D::kNone, &S::frames},
  };
  return kTable;
}

std::vector<results::MetricSpec> allSpecs() {
  std::vector<results::MetricSpec> specs = summaryTable().specs();
  for (const results::MetricSpec& spec : frameTable().specs()) specs.push_back(spec);
  return specs;
}

std::vector<std::string> policyNotes() {
  std::string text =
      "policies (shaders/common/cull.glsl, run in every technique's own TCS, which "
      "writes outer level 0 for a culled patch; CPU twin "
      "harness/lod/cull_policy.h):";
  for (lod::CullPolicy policy : lod::allCullPolicies()) {
    text += " ";
    text += lod::cullPolicyName(policy);
    text += " = ";
    text += lod::cullPolicyDescription(policy);
    text += ";";
  }
  return {text};
}

class CullingMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo = [] {
      MeasureInfo info{
          .id = "culling",
          .title = "Patch culling effectiveness, with false culls counted against a render",
          .description =
              "patch culling policies per frame of a camera path: patches culled, TES invocations "
              "saved (lavapipe pipeline statistics), false culls (culled patches that show pixels "
              "in "
              "a render of the unculled surface) and missed culls (patches an ideal back-face and "
              "frustum culler would remove)",
          .metrics = allSpecs(),
          .headline = {"cull_efficiency", "total_false_culls", "mean_tes_saving",
                       "mean_culled_fraction"},
          .notes =
              {"efficiency: cull_efficiency = the oracle's cullable patches the policy culls / the "
               "oracle's cullable patches (summed over the path's frames in the summary rows); "
               "back_facing_efficiency = what the policy's back-facing half (backface_lp2, cone; "
               "combined: its cone) culls of the patches whose every triangle faces away; "
               "frustum_efficiency = what its frustum half (frustum_*; combined: frustum_hull) "
               "culls "
               "of the patches whose every triangle lies outside the frustum",
               "summary rows (summary = path), one per policy over the camera path: "
               "mean_culled_fraction and mean_tes_saving are means over the frames (0.5: half the "
               "patches or TES invocations removed); total_* are sums over the frames",
               "false culls: a patch the policy culls that covers at least one pixel of a render "
               "of "
               "the unculled tessellated surface on lavapipe (the technique's own TCS and TES, "
               "depth "
               "test, fixed-function back-face culling, a per-patch ID target); false_cull_pixels "
               "= "
               "the pixels those patches show. Occlusion by other patches is not a reason to cull",
               "missed culls: a patch kept although every one of its tessellated triangles is "
               "back-facing (screen-space winding) or entirely outside one frustum plane (clip "
               "test): "
               "an ideal back-face + frustum culler removes it; a front-facing patch too small to "
               "cover a pixel is not missed",
               "counts: tes_invocations and triangles from the CPU tessellator for the patches the "
               "twin keeps, at one uniform integer level; gpu_*: lavapipe's pipeline statistics "
               "(TES invocations) and VK_EXT_primitives_generated_query with the TCS culling; "
               "twin_mismatches: patches whose TCS decision differs from the CPU twin's",
               "compute_mismatches: patches whose decision on the compute path (the policy in "
               "compute through the TCS's own cull.glsl, core/gpu/compute_levels.h) differs from "
               "the TCS's; --suite full, and the default suite on catmark_xord_interior and "
               "loop_xord_interior",
               "default suite: level 4, the render at half the path's resolution per axis (960 x "
               "540), the default variant, along orbit (2 frames), dolly (4) and flyby (4); "
               "--suite "
               "full: level 8 at the path's resolution, every variant, every frame of the three "
               "paths"},
          .decision_inputs = {{.role = results::DecisionRole::kCullEfficiency,
                               .label = "share of what an ideal culler removes",
                               .metrics = {"cull_efficiency"},
                               .where = {{"summary", "path"}},
                               .chosen_key = "policy"},
                              {.role = results::DecisionRole::kFalseCulls,
                               .label = "false culls",
                               .metrics = {"total_false_culls"},
                               .where = {{"summary", "path"}},
                               .reduce = results::DecisionReduce::kSum}}};
      for (std::string& note : policyNotes()) info.notes.push_back(std::move(note));
      // The share of TES work each policy removes (its path summary rows; median over
      // assets and camera paths).
      info.plots = {results::PlotSpec{.title = "TES invocations saved per culling policy",
                                      .kind = results::PlotKind::kBar,
                                      .x = "policy",
                                      .y = "mean_tes_saving",
                                      .series = "technique",
                                      .facet = "",
                                      .where = {{"summary", kSummaryKey}}}};
      return info;
    }();
    return kInfo;
  }

  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSurface, MeasureNeed::kCameraPath, MeasureNeed::kGpu},
            VariantPolicy::kEveryVariantInFullSuite,
            {}};
  }

  // Culling needs the camera close as well as far: the dolly's last frames and the flyby put
  // patches off screen, which the orbit never does.
  std::vector<std::pair<std::string, uint32_t>> defaultSuitePaths() const override {
    return {{"orbit", 2}, {"dolly", 4}, {"flyby", 4}};
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    const view::CameraPath& path = requireCameraPath(input);
    return std::move(runPaths(input, std::span(&path, 1)).front());
  }

  // The culling bounds, the device's unculled run and surface, the oracle and the TCS costs
  // do not depend on the path: built once for all of them.
  std::vector<results::MeasureResult> runPaths(
      MeasureInput input, std::span<const view::CameraPath> paths) const override {
    CullingOptions options = optionsFor(input.suite);
    options.compute = runsComputePath(input);
    CullingRun run(*input.patches, input.gpu, input.gpu_unavailable, options);
    const std::span<const lod::CullPolicy> policies = lod::allCullPolicies();
    const std::vector<CullTcsCost> costs = cullTcsCosts(*input.patches, policies);
    std::vector<results::MeasureResult> out;
    for (const view::CameraPath& path : paths) {
      input.camera_path = &path;
      out.push_back(pathResult(run, costs, policies, requireCameraPath(input)));
    }
    return out;
  }

 private:
  results::MeasureResult pathResult(CullingRun& run, std::span<const CullTcsCost> costs,
                                    std::span<const lod::CullPolicy> policies,
                                    const view::CameraPath& path) const {
    results::MeasureResult result;
    result.measure = info().id;
    const std::vector<std::vector<CullingFrame>> frames = run.frames(policies, path.views);
    if (!run.gpuSkipReason().empty()) {
      // gpu_*, twin_mismatches and the oracle's figures live in the per-frame rows; without
      // them, this row says why.
      result.rows.push_back(results::unmeasuredRow(
          {{"part", "gpu"}}, results::MeasureStatus::kSkipped, run.gpuSkipReason()));
    }
    const lod::CullBounds& bounds = run.bounds();
    result.notes = boundsNotes(bounds);
    for (size_t k = 0; k < policies.size(); ++k) {
      results::MetricRow row;
      row.keys["policy"] = std::string(lod::cullPolicyName(policies[k]));
      row.keys["summary"] = kSummaryKey;
      CullingSummary summary = summarise(frames[k]);
      summary.cull_bytes_per_patch = lod::cullBytesPerPatch(policies[k], bounds.patches);
      if (costs[k].measured) {
        summary.tcs_instructions = costs[k].tcs_instructions;
        summary.cull_instructions = costs[k].cull_instructions;
      }
      row.metrics = summaryTable().metrics(summary);
      result.rows.push_back(std::move(row));
    }
    for (size_t k = 0; k < policies.size(); ++k) {
      for (const CullingFrame& frame : frames[k]) {
        results::MetricRow row;
        row.keys["policy"] = std::string(lod::cullPolicyName(policies[k]));
        row.keys["frame"] = std::to_string(frame.frame);
        row.metrics = frameTable().metrics(frame);
        result.rows.push_back(std::move(row));
      }
    }
    return result;
  }

  static std::vector<std::string> boundsNotes(const lod::CullBounds& bounds) {
    std::vector<std::string> notes;
    if (bounds.patches_without_hull > 0 || bounds.patches_without_cone > 0) {
      notes.push_back(std::to_string(bounds.patches_without_cone) + " of " +
                      std::to_string(bounds.patches.size()) +
                      " patches have no cone of normals (none given, or normals spanning "
                      "90 degrees or more): cone never culls them; " +
                      std::to_string(bounds.patches_without_hull) +
                      " have no control hull (their corners stand in)");
    }
    if (bounds.patches_without_tangent_plane > 0) {
      notes.push_back(std::to_string(bounds.patches_without_tangent_plane) + " of " +
                      std::to_string(bounds.patches.size()) +
                      " patches have no polynomial Bezier net (rational or displaced "
                      "patches, or sub-patches): tangent_plane tests them with the cone");
    }
    return notes;
  }
};

TB_REGISTER_MEASURE(CullingMeasure);

}  // namespace
}  // namespace tb::measures
