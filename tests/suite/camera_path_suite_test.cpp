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
class WholePathMeasure final : public measures::Measure {
 public:
  const measures::MeasureInfo& info() const override {
    static const measures::MeasureInfo kInfo{
        .id = "test_whole_path",
        .title = "whole path",
        .description = "frames of the path",
        .metrics = {{"frames", results::Unit::kCount, results::Direction::kNone},
                    {"eye_x", results::Unit::kWorld, results::Direction::kNone},
                    {"full_suite", results::Unit::kCount, results::Direction::kNone}},
        .headline = {},
        .notes = {}};
    return kInfo;
  }
  measures::MeasureRequirements requirements() const override {
    return {{measures::MeasureNeed::kSurface, measures::MeasureNeed::kCameraPath},
            measures::VariantPolicy::kDefaultOnly,
            {}};
  }
  results::MeasureResult run(const measures::MeasureInput& input) const override {
    ++calls;
    results::MeasureResult result;
    result.measure = info().id;
    const view::CameraPath& path = *input.camera_path;
    for (size_t f = 0; f < path.views.size(); ++f) {
      result.rows.push_back(
          {{{"frame", std::to_string(f)}},
           {{"frames", double(path.views.size()), "count"},
            {"eye_x", path.views[f].eye[0], "world"},
            {"full_suite", input.suite == measures::SuiteMode::kFull ? 1.0 : 0.0, "count"}}});
    }
    return result;
  }
  mutable std::atomic<int> calls{0};
};

// Needs a view: one row per view (the suite keys it).
class OneViewMeasure final : public measures::Measure {
 public:
  const measures::MeasureInfo& info() const override {
    static const measures::MeasureInfo kInfo{
        .id = "test_one_view",
        .title = "one view",
        .description = "viewport width",
        .metrics = {{"width", results::Unit::kPixels, results::Direction::kNone}},
        .headline = {},
        .notes = {}};
    return kInfo;
  }
  measures::MeasureRequirements requirements() const override {
    return {{measures::MeasureNeed::kSurface, measures::MeasureNeed::kView},
            measures::VariantPolicy::kDefaultOnly,
            {}};
  }
  results::MeasureResult run(const measures::MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    result.rows.push_back({{}, {{"width", double(input.view->viewport_width_px), "px"}}});
    return result;
  }
};

// Rows per camera_path key, in order of first appearance.
std::vector<std::pair<std::string, size_t>> rowsPerPath(const results::MeasureResult& result) {
  std::vector<std::pair<std::string, size_t>> counts;
  for (const results::MetricRow& row : result.rows) {
    const std::string& path = row.keys.at("camera_path");
    if (counts.empty() || counts.back().first != path) counts.emplace_back(path, 0);
    ++counts.back().second;
  }
  return counts;
}

const results::MeasureResult& resultOf(const results::Results& results,
                                       const std::string& measure) {
  for (const results::MeasureResult& result : results.records.at(0).measures) {
    if (result.measure == measure) return result;
  }
  throw std::runtime_error("no result of " + measure);
}

results::Results runWith(const measures::Measure& a, const measures::Measure* b,
                         measures::SuiteMode mode, std::vector<suite::CameraPathFn> paths = {}) {
  static const SurfaceDoubleTechnique surface;
  suite::SuiteSelection selection;
  selection.techniques = {&surface};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.measures = {&a};
  if (b) selection.measures.push_back(b);
  selection.suite = mode;
  selection.camera_paths = std::move(paths);
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  return results;
}

TEST(CameraPathSuite, TheDefaultSuiteRunsTheMeasureOnceWithTheOrbitAtFourFrames) {
  const WholePathMeasure measure;
  const results::Results results = runWith(measure, nullptr, measures::SuiteMode::kDefault);
  ASSERT_EQ(results.records.size(), 1u);  // kDefaultOnly
  const results::MeasureResult& result = resultOf(results, "test_whole_path");
  EXPECT_EQ(result.status, results::MeasureStatus::kOk);
  EXPECT_EQ(measure.calls, 1);
  ASSERT_EQ(result.rows.size(), size_t(suite::kDefaultSuiteOrbitFrames));
  for (size_t f = 0; f < result.rows.size(); ++f) {
    // The suite adds only "camera_path"; the measure keyed the frame.
    const std::map<std::string, std::string> keys{{"camera_path", "orbit"},
                                                  {"frame", std::to_string(f)}};
    EXPECT_EQ(result.rows[f].keys, keys);
    EXPECT_EQ(result.rows[f].metrics[0].value, suite::kDefaultSuiteOrbitFrames);
    EXPECT_EQ(result.rows[f].metrics[2].value, 0);  // the measure sees the default suite
  }
}

TEST(CameraPathSuite, TheFullSuiteRunsItOncePerBundledPathAtItsOwnFrameCount) {
  const WholePathMeasure measure;
  const results::Results results = runWith(measure, nullptr, measures::SuiteMode::kFull);
  const results::MeasureResult& result = resultOf(results, "test_whole_path");
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
    const results::Results results = runWith(whole, &one_view, measures::SuiteMode::kDefault);
    const std::vector<std::pair<std::string, size_t>> test_orbit{{"test_orbit", 3}};
    EXPECT_EQ(rowsPerPath(resultOf(results, "test_one_view")), test_orbit);
    EXPECT_EQ(rowsPerPath(resultOf(results, "test_whole_path")),
              (std::vector<std::pair<std::string, size_t>>{{"orbit", 4}}));
  }
  // Selected paths (`run --camera`): both measures take them, at their own frame counts.
  const WholePathMeasure whole;
  const OneViewMeasure one_view;
  const suite::CameraPathFn two_views = [](const mesh::Aabb&) {
    return view::CameraPath{"two_views", {view::View{}, view::View{}}};
  };
  const results::Results results =
      runWith(whole, &one_view, measures::SuiteMode::kFull,
              {suite::cameraPathFn(suite::resolveCameraPath("flyby")), two_views});
  EXPECT_EQ(whole.calls, 2);
  const std::vector<std::pair<std::string, size_t>> selected{{"flyby", 48}, {"two_views", 2}};
  EXPECT_EQ(rowsPerPath(resultOf(results, "test_whole_path")), selected);
  EXPECT_EQ(rowsPerPath(resultOf(results, "test_one_view")), selected);
  EXPECT_EQ(resultOf(results, "test_one_view").rows[47].keys.at("view"), "47");
}

TEST(CameraPathSuite, ACameraPathNeedNeverStopsAMeasureAndTheSuiteModeIsRecorded) {
  const SurfaceDoubleTechnique surface;
  EXPECT_TRUE(
      suite::measureRuns({{measures::MeasureNeed::kSurface, measures::MeasureNeed::kCameraPath},
                          measures::VariantPolicy::kEveryVariant,
                          {}},
                         surface, {true, false}, {true, true}));
  suite::SuiteSelection selection;
  selection.techniques = {&surface};
  EXPECT_EQ(suite::describeSelection(selection, {}).suite, "default");
  selection.suite = measures::SuiteMode::kFull;
  EXPECT_EQ(suite::describeSelection(selection, {}).suite, "full");
}

}  // namespace
}  // namespace tb
