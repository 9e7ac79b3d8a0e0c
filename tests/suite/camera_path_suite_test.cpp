// Measures that take a whole camera path (MeasureNeed::kCameraPath) through runSuite, with
// the flat-face test double (capability_doubles.h) and a test-only measure; nothing here is
// registered. Oracle: the bundled path files' frame counts, and the suite's documented
// choice of paths per suite mode.
#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <string>
#include <vector>

#include "harness/suite/measure_rule.h"
#include "harness/suite/suite.h"
#include "tests/suite/capability_doubles.h"

namespace tb {
namespace {

using testing::SurfaceDoubleTechnique;

// One row per frame of the path it is given, keyed "frame"; counts its calls.
class WholePathMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{"test_whole_path",
                                   "whole path",
                                   "frames of the path",
                                   {{"frames", Unit::kCount, Direction::kNone},
                                    {"eye_x", Unit::kWorld, Direction::kNone},
                                    {"full_suite", Unit::kCount, Direction::kNone}},
                                   {},
                                   {}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSurface, MeasureNeed::kCameraPath}, VariantPolicy::kDefaultOnly, {}};
  }
  MeasureResult run(const MeasureInput& input) const override {
    ++calls;
    MeasureResult result;
    result.measure = info().id;
    const CameraPath& path = *input.camera_path;
    for (size_t f = 0; f < path.views.size(); ++f) {
      result.rows.push_back(
          {{{"frame", std::to_string(f)}},
           {{"frames", double(path.views.size()), "count"},
            {"eye_x", path.views[f].eye[0], "world"},
            {"full_suite", input.suite == SuiteMode::kFull ? 1.0 : 0.0, "count"}}});
    }
    return result;
  }
  mutable std::atomic<int> calls{0};
};

// Needs a view: one row per view (the suite keys it).
class OneViewMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{"test_one_view",
                                   "one view",
                                   "viewport width",
                                   {{"width", Unit::kPixels, Direction::kNone}},
                                   {},
                                   {}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSurface, MeasureNeed::kView}, VariantPolicy::kDefaultOnly, {}};
  }
  MeasureResult run(const MeasureInput& input) const override {
    MeasureResult result;
    result.measure = info().id;
    result.rows.push_back({{}, {{"width", double(input.view->viewport_width_px), "px"}}});
    return result;
  }
};

// Rows per camera_path key, in order of first appearance.
std::vector<std::pair<std::string, size_t>> rowsPerPath(const MeasureResult& result) {
  std::vector<std::pair<std::string, size_t>> counts;
  for (const MetricRow& row : result.rows) {
    const std::string& path = row.keys.at("camera_path");
    if (counts.empty() || counts.back().first != path) counts.emplace_back(path, 0);
    ++counts.back().second;
  }
  return counts;
}

const MeasureResult& resultOf(const Results& results, const std::string& measure) {
  for (const MeasureResult& result : results.records.at(0).measures) {
    if (result.measure == measure) return result;
  }
  throw std::runtime_error("no result of " + measure);
}

Results runWith(const Measure& a, const Measure* b, SuiteMode mode,
                std::vector<CameraPathFn> paths = {}) {
  static const SurfaceDoubleTechnique surface;
  SuiteSelection selection;
  selection.techniques = {&surface};
  selection.assets = {resolveAsset("catmark_cube")};
  selection.measures = {&a};
  if (b) selection.measures.push_back(b);
  selection.suite = mode;
  selection.camera_paths = std::move(paths);
  Results results;
  runSuite(selection, nullptr, &results);
  return results;
}

TEST(CameraPathSuite, TheDefaultSuiteRunsTheMeasureOnceWithTheOrbitAtFourFrames) {
  const WholePathMeasure measure;
  const Results results = runWith(measure, nullptr, SuiteMode::kDefault);
  ASSERT_EQ(results.records.size(), 1u);  // kDefaultOnly
  const MeasureResult& result = resultOf(results, "test_whole_path");
  EXPECT_EQ(result.status, MeasureStatus::kOk);
  EXPECT_EQ(measure.calls, 1);
  ASSERT_EQ(result.rows.size(), size_t(kDefaultSuiteOrbitFrames));
  for (size_t f = 0; f < result.rows.size(); ++f) {
    // The suite adds only "camera_path"; the measure keyed the frame.
    const std::map<std::string, std::string> keys{{"camera_path", "orbit"},
                                                  {"frame", std::to_string(f)}};
    EXPECT_EQ(result.rows[f].keys, keys);
    EXPECT_EQ(result.rows[f].metrics[0].value, kDefaultSuiteOrbitFrames);
    EXPECT_EQ(result.rows[f].metrics[2].value, 0);  // the measure sees the default suite
  }
}

TEST(CameraPathSuite, TheFullSuiteRunsItOncePerBundledPathAtItsOwnFrameCount) {
  const WholePathMeasure measure;
  const Results results = runWith(measure, nullptr, SuiteMode::kFull);
  const MeasureResult& result = resultOf(results, "test_whole_path");
  EXPECT_EQ(measure.calls, 3);
  const std::vector<std::pair<std::string, size_t>> expected{
      {"orbit", 24}, {"dolly", 120}, {"flyby", 48}};
  EXPECT_EQ(rowsPerPath(result), expected);
  EXPECT_EQ(result.rows.front().metrics[2].value, 1);  // the measure sees the full suite
}

TEST(CameraPathSuite, SelectedPathsServeBothKindsAndViewMeasuresKeepTheTestOrbitOtherwise) {
  // No paths selected: the view measure still walks the test orbit (3 views).
  {
    const WholePathMeasure whole;
    const OneViewMeasure one_view;
    const Results results = runWith(whole, &one_view, SuiteMode::kDefault);
    const std::vector<std::pair<std::string, size_t>> test_orbit{{"test_orbit", 3}};
    EXPECT_EQ(rowsPerPath(resultOf(results, "test_one_view")), test_orbit);
    EXPECT_EQ(rowsPerPath(resultOf(results, "test_whole_path")),
              (std::vector<std::pair<std::string, size_t>>{{"orbit", 4}}));
  }
  // Selected paths (`run --camera`): both measures take them, at their own frame counts.
  const WholePathMeasure whole;
  const OneViewMeasure one_view;
  const CameraPathFn two_views = [](const Aabb&) {
    return CameraPath{"two_views", {View{}, View{}}};
  };
  const Results results = runWith(whole, &one_view, SuiteMode::kFull,
                                  {cameraPathFn(resolveCameraPath("flyby")), two_views});
  EXPECT_EQ(whole.calls, 2);
  const std::vector<std::pair<std::string, size_t>> selected{{"flyby", 48}, {"two_views", 2}};
  EXPECT_EQ(rowsPerPath(resultOf(results, "test_whole_path")), selected);
  EXPECT_EQ(rowsPerPath(resultOf(results, "test_one_view")), selected);
  EXPECT_EQ(resultOf(results, "test_one_view").rows[47].keys.at("view"), "47");
}

TEST(CameraPathSuite, ACameraPathNeedNeverStopsAMeasureAndTheSuiteModeIsRecorded) {
  const SurfaceDoubleTechnique surface;
  EXPECT_TRUE(measureRuns(
      {{MeasureNeed::kSurface, MeasureNeed::kCameraPath}, VariantPolicy::kEveryVariant, {}},
      surface, {true, false}, {true, true}));
  SuiteSelection selection;
  selection.techniques = {&surface};
  EXPECT_EQ(describeSelection(selection, {}).suite, "default");
  selection.suite = SuiteMode::kFull;
  EXPECT_EQ(describeSelection(selection, {}).suite, "full");
}

}  // namespace
}  // namespace tb
