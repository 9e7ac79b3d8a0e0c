// Oracles: the cracks measure itself (measureCracks gives the count the picture must mark,
// points_not_equal) and the row data of results.json; Phong tessellation with alpha 0.75
// on catmark_cube cracks on the CPU at fractional_odd level 64 (the default run's report),
// ACC on the same cube is watertight there (the control: no mark at all).
#include "harness/pictures/crack_picture.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "core/gpu/render_target.h"
#include "core/mesh/obj_loader.h"
#include "harness/lod/reference_scheme.h"
#include "harness/measures/error/error.h"
#include "harness/measures/measure.h"
#include "harness/pictures/run_pictures.h"
#include "harness/pictures/surface_picture.h"
#include "harness/report/markdown_sections.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

results::MetricRow cracksRow(const char* backend, const char* level, double points, double gap,
                             const char* displacement = "") {
  results::MetricRow row;
  row.keys = {{"backend", backend}, {"spacing", "integer"}, {"level", level}};
  if (*displacement != 0) row.keys["displacement"] = displacement;
  row.metrics = {{"points_not_equal", points, "count"}, {"max_gap_world", gap, "world"}};
  return row;
}

TEST(CrackPicture, TheWorstCpuRowIsTheLargestGapOfACpuFloatRow) {
  results::Record record;
  results::MeasureResult cracks;
  cracks.measure = "cracks";
  cracks.rows = {cracksRow("cpu_float", "1", 0, 0), cracksRow("cpu_float", "16", 5, 2e-7),
                 cracksRow("gpu", "16", 9, 9e-7), cracksRow("cpu_float", "64", 7, 2e-7),
                 cracksRow("cpu_float", "7.3", 3, 8e-7, "map.exr")};
  record.measures = {cracks};
  const std::optional<pictures::CrackRow> worst = pictures::worstCpuCrackRow(record);
  ASSERT_TRUE(worst);
  EXPECT_EQ(worst->level, "16");  // the first of the two largest cpu_float gaps, undisplaced
  EXPECT_EQ(worst->points_not_equal, 5u);
  EXPECT_EQ(worst->text(), "cpu_float, integer, level 16");
  record.measures[0].rows = {cracksRow("cpu_float", "1", 0, 0), cracksRow("gpu", "1", 3, 1e-7)};
  EXPECT_FALSE(pictures::worstCpuCrackRow(record));
}

techniques::BuiltSurface cubeSurface(const char* technique_id) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  return techniques::buildSurface(
      *technique, mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj")),
      technique->variants().front());
}

// The crack picture of the default variant of `technique_id` on catmark_cube at the row.
struct Marked {
  pictures::CrackPicture picture;
  std::vector<measures::UnequalPair> pairs;
  view::View view;
};
Marked markCube(gpu::Context& context, const char* technique_id, const pictures::CrackRow& row) {
  const techniques::BuiltSurface surface = cubeSurface(technique_id);
  const ref::LimitSurface limit(surface->controlMesh(),
                                lod::referenceScheme(surface->approximates()));
  const pictures::SurfaceErrorMesh mesh = pictures::tessellateWithError(*surface, limit, 4);
  constexpr uint32_t kSize = 128;
  Marked marked;
  marked.view = pictures::threeQuarterView(mesh.bounds, kSize);
  gpu::RenderTarget target(context, kSize, kSize);
  const std::vector<uint32_t> ids = pictures::renderTriangleIds(target, mesh, marked.view);
  marked.pairs = pictures::crackPairsOf(*surface, row);
  marked.picture =
      pictures::composeCrackPicture(pictures::shadedPicture(mesh, marked.view, kSize, ids), mesh,
                                    marked.view, kSize, ids, marked.pairs);
  return marked;
}

TEST(CrackPicture, ACrackingVariantIsMarkedWhereItCracksAWatertightOneNowhere) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const pictures::CrackRow row{"fractional_odd", "64", "", 0, 0};
  const std::vector<tess::Levels> levels(cubeSurface("phong")->patchCount(), [] {
    tess::Levels l;
    l.outer = {64, 64, 64, 64};
    l.inner = {64, 64};
    return l;
  }());
  const measures::CrackFigures figures =
      measures::measureCracks(*cubeSurface("phong"), tess::Spacing::kFractionalOdd, levels,
                              measures::CrackBackend::kCpuFloat);
  ASSERT_GT(figures.points_not_equal, 0u);

  const Marked phong = markCube(context, "phong", row);
  EXPECT_EQ(phong.pairs.size(), figures.points_not_equal);
  EXPECT_EQ(phong.picture.points_visible + phong.picture.points_hidden, phong.pairs.size());
  EXPECT_GT(phong.picture.points_visible, 0u);
  EXPECT_GT(phong.picture.marked_pixels, 0u);
  // The known location: the pixel of the largest gap is marked.
  const measures::UnequalPair* worst = &phong.pairs.front();
  for (const measures::UnequalPair& p : phong.pairs) worst = p.gap > worst->gap ? &p : worst;
  EXPECT_EQ(worst->gap, figures.max_gap_world);
  const view::ProjectedPoint at = view::projectToPixels(
      phong.view, 0.5 * (double(worst->a.x) + worst->b.x), 0.5 * (double(worst->a.y) + worst->b.y),
      0.5 * (double(worst->a.z) + worst->b.z));
  const pictures::Rgb pixel = phong.picture.image.at(uint32_t(at.x_px), uint32_t(at.y_px));
  EXPECT_TRUE(pixel == pictures::kCrackMark || pixel == pictures::kCrackHidden);

  // The same pairs, in the same order, on one thread (the picture does not depend on it).
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const std::vector<measures::UnequalPair> serial =
        pictures::crackPairsOf(*cubeSurface("phong"), row);
    ASSERT_EQ(serial.size(), phong.pairs.size());
    for (size_t i = 0; i < serial.size(); ++i) {
      EXPECT_TRUE(serial[i].a == phong.pairs[i].a && serial[i].b == phong.pairs[i].b) << i;
    }
  }

  // Control: ACC on the same cube is watertight there, so nothing is marked.
  const Marked acc = markCube(context, "acc", row);
  EXPECT_TRUE(acc.pairs.empty());
  EXPECT_EQ(acc.picture.marked_pixels, 0u);
  EXPECT_EQ(acc.picture.points_visible + acc.picture.points_hidden, 0u);
}

TEST(CrackPicture, FileNameFollowsTheOtherPicturesAndReportMdLinksIt) {
  EXPECT_EQ(pictures::crackPicturePath("phong", "opensubdiv/catmark_cube"),
            "pictures/phong--opensubdiv--catmark_cube--cracks.png");
  // report.md's link (harness/report, which cannot include the pictures) is the same path.
  results::Record record;
  record.technique = "phong";
  record.asset = "my dir/x+y.obj";
  results::MeasureResult error, cracks;
  error.measure = "error";
  cracks.measure = "cracks";
  cracks.rows = {cracksRow("gpu", "16", 9, 9e-7)};
  record.measures = {error, cracks};
  results::Results run;  // the registered measures' declarations, as a run has them
  for (const char* id : {"error", "cracks"}) {
    run.measures.push_back(
        measures::declarationOf(measures::MeasureRegistry::instance().find(id)->info()));
  }
  EXPECT_EQ(report::markdown_detail::crackPictureOf(run, record), "") << "no CPU float crack";
  record.measures[1].rows.push_back(cracksRow("cpu_float", "16", 5, 2e-7));
  EXPECT_EQ(report::markdown_detail::crackPictureOf(run, record),
            pictures::crackPicturePath(record.technique, record.asset));
  record.measures[0].status = results::MeasureStatus::kSkipped;
  EXPECT_EQ(report::markdown_detail::crackPictureOf(run, record), "") << "no error picture";
}

}  // namespace
}  // namespace tb
