// The "error" measure: measureSurfaceError against the limit of the scheme the patches
// approximate, one row per record.
#include <string>

#include "core/mesh/input_error.h"
#include "harness/measures/error.h"
#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"

namespace tb {
namespace {

// Every distance and angle is best at 0; the sample counts, holes left out and the
// diagonal that scales the distances are context.
const MetricTable<SurfaceErrorFigures>& errorTable() {
  using D = Direction;
  using F = SurfaceErrorFigures;
  static const MetricTable<F> kTable{
      {"parametric_max", Unit::kDiagonal, D::kLowerIsBetter, &F::parametric_max},
      {"parametric_rms", Unit::kDiagonal, D::kLowerIsBetter, &F::parametric_rms},
      {"parametric_max_near_xord", Unit::kDiagonal, D::kLowerIsBetter,
       &F::parametric_max_near_xord},
      {"parametric_max_elsewhere", Unit::kDiagonal, D::kLowerIsBetter,
       &F::parametric_max_elsewhere},
      {"hausdorff", Unit::kDiagonal, D::kLowerIsBetter, &F::hausdorff},
      {"hausdorff_tech_to_limit", Unit::kDiagonal, D::kLowerIsBetter,
       &F::hausdorff_technique_to_limit},
      {"hausdorff_limit_to_tech", Unit::kDiagonal, D::kLowerIsBetter,
       &F::hausdorff_limit_to_technique},
      {"rms_distance", Unit::kDiagonal, D::kLowerIsBetter, &F::rms_distance},
      {"normal_max", Unit::kDegrees, D::kLowerIsBetter, &F::normal_max_deg},
      {"normal_mean", Unit::kDegrees, D::kLowerIsBetter, &F::normal_mean_deg},
      {"samples", Unit::kCount, D::kNone, &F::samples},
      {"samples_near_xord", Unit::kCount, D::kNone, &F::samples_near_xord},
      {"patches_without_limit", Unit::kCount, D::kNone, &F::patches_without_limit},
      {"bbox_diagonal", Unit::kWorld, D::kNone, &F::bbox_diagonal},
  };
  return kTable;
}

class ErrorMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        "error",
        "Error against the exact limit surface",
        "parametric and two-sided Hausdorff distance (fraction of the bounding-box diagonal) "
        "and normal deviation (degrees) against the OpenSubdiv Bfr limit",
        errorTable().specs(),
        {"hausdorff", "parametric_max", "normal_max"},
        {"distances are fractions of the bounding-box diagonal; normals in degrees",
         "each technique against the limit of the scheme its patches approximate (row key "
         "reference): by default triangle techniques against the Loop limit of their triangle "
         "mesh, quad techniques against the Catmull-Clark limit (OpenSubdiv Bfr, double, "
         "approximation level 10)",
         "samples: a lattice of " + std::to_string(kErrorSampleLevel) +
             " segments per patch edge; reference tessellated at rate " +
             std::to_string(kErrorReferenceRate) +
             "; near extraordinary (xord): corner weight >= 0.75"},
        {},
        // What a technique's accuracy costs: its worst TES instruction count (the
        // instructions measure's summary scope) against its Hausdorff error, one chart per
        // asset, each technique × variant a point.
        {PlotSpec{.title = "Hausdorff error against TES instructions",
                  .kind = PlotKind::kScatter,
                  .x = "instructions.total",
                  .y = "hausdorff",
                  .series = "technique",
                  .facet = "asset",
                  .where = {},
                  .log_y = true,
                  .pareto_front = true}}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSurface}, VariantPolicy::kEveryVariant, {}};
  }

  MeasureResult run(const MeasureInput& input) const override {
    MeasureResult result;
    result.measure = info().id;
    const ref::Scheme scheme = referenceScheme(input.patches->approximates());
    try {
      const ref::LimitSurface limit(input.patches->controlMesh(), scheme);
      const SurfaceErrorFigures f = measureSurfaceError(*input.patches, limit);
      if (f.patches_through_sub_faces > 0) {
        // Only records whose technique puts triangle patches on a Catmull-Clark mesh.
        result.notes.push_back(
            "every patch, quad or triangle, against the Catmull-Clark limit of the control mesh, "
            "the scheme the technique approximates; its triangle patches (" +
            std::to_string(f.patches_through_sub_faces) +
            " here) are compared through Bfr's three quad sub-faces of the triangle: a " +
            std::to_string(kErrorSubFaceSampleLevel) +
            "-segment (s,t) grid on each sub-face, mapped bilinearly through its corners (patch "
            "corner, edge midpoints, centroid) to the patch's barycentric domain; their "
            "parametric error therefore depends on that map, their Hausdorff distance does not");
      }
      MetricRow row;
      row.keys["reference"] = scheme == ref::Scheme::kLoop ? "loop_limit" : "catmull_clark_limit";
      row.metrics = errorTable().metrics(f);
      result.rows.push_back(std::move(row));
    } catch (const InputError& error) {
      result.status = MeasureStatus::kSkipped;
      result.reason = std::string("reference cannot represent the mesh: ") + error.what();
    }
    return result;
  }
};

TB_REGISTER_MEASURE(ErrorMeasure);

}  // namespace
}  // namespace tb
