// The capabilities, the view axis and the measure rule through runSuite, with test doubles
// (capability_doubles.h) and test-only measures; nothing here is registered.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/suite/measure_rule.h"
#include "harness/suite/suite.h"
#include "tests/suite/capability_doubles.h"

namespace tb {
namespace {

using testing::SimulationDoubleTechnique;
using testing::SurfaceDoubleTechnique;

// Needs a surface: one row with the patch count.
class SurfaceCountMeasure final : public measures::Measure {
 public:
  const measures::MeasureInfo& info() const override {
    static const measures::MeasureInfo kInfo{
        .id = "test_surface_count",
        .title = "patches",
        .description = "patch count",
        .metrics = {{"patches", results::Unit::kCount, results::Direction::kNone}},
        .headline = {},
        .notes = {}};
    return kInfo;
  }
  measures::MeasureRequirements requirements() const override {
    return {{measures::MeasureNeed::kSurface}, measures::VariantPolicy::kEveryVariant, {}};
  }
  results::MeasureResult run(const measures::MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    result.rows.push_back({{}, {{"patches", double(input.patches->patchCount()), "count"}}});
    return result;
  }
};

// Needs a simulation: steps it through the scenario and reads the state back.
class SimulationStepMeasure final : public measures::Measure {
 public:
  const measures::MeasureInfo& info() const override {
    static const measures::MeasureInfo kInfo{
        .id = "test_simulation_steps",
        .title = "steps",
        .description = "state after the scenario",
        .metrics = {{"start_time", results::Unit::kSeconds, results::Direction::kNone},
                    {"time", results::Unit::kSeconds, results::Direction::kNone},
                    {"elements", results::Unit::kCount, results::Direction::kNone},
                    {"last_position", results::Unit::kWorld, results::Direction::kNone},
                    {"state_bytes", results::Unit::kBytes, results::Direction::kLowerIsBetter}},
        .headline = {"state_bytes"},
        .notes = {}};
    return kInfo;
  }
  measures::MeasureRequirements requirements() const override {
    return {{measures::MeasureNeed::kSimulation}, measures::VariantPolicy::kDefaultOnly, {}};
  }
  results::MeasureResult run(const measures::MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    techniques::Simulation& simulation = *input.simulation;
    const double start_s = simulation.state().time_s;
    const size_t steps = simulation.scenario().stepCount();
    for (size_t i = 0; i < steps; ++i) simulation.step(simulation.scenario().time_step_s);
    const techniques::SimulationState state = simulation.state();
    const techniques::StateChannel* position = state.find("position");
    result.rows.push_back({{},
                           {{"start_time", start_s, "s"},
                            {"time", state.time_s, "s"},
                            {"elements", double(state.element_count), "count"},
                            {"last_position", double(position->values.back()), "world"},
                            {"state_bytes", double(simulation.footprint().state_bytes), "bytes"}}});
    return result;
  }
};

// Needs a surface and a view: the pixel the asset's first vertex projects to.
class ViewMeasure final : public measures::Measure {
 public:
  const measures::MeasureInfo& info() const override {
    static const measures::MeasureInfo kInfo{
        .id = "test_view",
        .title = "view",
        .description = "projected first vertex",
        .metrics = {{"x", results::Unit::kPixels, results::Direction::kNone},
                    {"y", results::Unit::kPixels, results::Direction::kNone},
                    {"width", results::Unit::kPixels, results::Direction::kNone}},
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
    const mesh::Vec3d p = input.patches->controlMesh().positions[0];
    const view::ProjectedPoint px = view::projectToPixels(*input.view, p.x, p.y, p.z);
    result.rows.push_back({{{"level", "1"}},
                           {{"x", px.x_px, "px"},
                            {"y", px.y_px, "px"},
                            {"width", double(input.view->viewport_width_px), "px"}}});
    return result;
  }
};

const results::Metric& metric(const results::MetricRow& row, const std::string& name) {
  for (const results::Metric& m : row.metrics) {
    if (m.name == name) return m;
  }
  throw std::runtime_error("no metric " + name);
}

TEST(Capabilities, SurfaceAndSimulationDoublesRunThroughTheSuiteWithTheMeasuresThatNeedThem) {
  const SurfaceDoubleTechnique surface;
  const SimulationDoubleTechnique chain;
  const SurfaceCountMeasure surface_measure;
  const SimulationStepMeasure simulation_measure;
  suite::SuiteSelection selection;
  selection.techniques = {&surface, &chain};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.scenarios = {testing::chainScenario()};
  selection.measures = {&simulation_measure, &surface_measure};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  EXPECT_TRUE(results.skipped.empty());
  ASSERT_EQ(results.records.size(), 3u);  // the surface's two variants, the chain's one
  for (const results::Record& record : results.records) {
    ASSERT_EQ(record.measures.size(), 1u) << record.technique;
    ASSERT_EQ(record.measures[0].rows.size(), 1u);
    const results::MetricRow& row = record.measures[0].rows[0];
    if (record.technique == "test_flat_faces") {
      EXPECT_EQ(record.asset, "opensubdiv/catmark_cube");
      EXPECT_EQ(record.measures[0].measure, "test_surface_count");
      EXPECT_EQ(metric(row, "patches").value, 6);
    } else {
      EXPECT_EQ(record.technique, "test_spring_chain");
      EXPECT_EQ(record.asset, "test/chain");
      EXPECT_EQ(record.measures[0].measure, "test_simulation_steps");
      EXPECT_EQ(metric(row, "start_time").value, 0);
      EXPECT_NEAR(metric(row, "time").value, 0.1, 1e-12);
      EXPECT_EQ(metric(row, "elements").value, 4);
      EXPECT_EQ(metric(row, "state_bytes").value, 32);
      // Stretched springs pull the free end back from its start at 6 m.
      EXPECT_LT(metric(row, "last_position").value, 6);
    }
  }
}

// Counts patches like SurfaceCountMeasure, on the technique's first supported input alone.
class FirstInputMeasure final : public measures::Measure {
 public:
  const measures::MeasureInfo& info() const override {
    static const measures::MeasureInfo kInfo{
        .id = "test_first_input",
        .title = "patches, once per variant",
        .description = "patch count",
        .metrics = {{"patches", results::Unit::kCount, results::Direction::kNone}}};
    return kInfo;
  }
  measures::MeasureRequirements requirements() const override {
    measures::MeasureRequirements r{
        {measures::MeasureNeed::kSurface}, measures::VariantPolicy::kEveryVariant, {}};
    r.first_input_only = true;
    return r;
  }
  results::MeasureResult run(const measures::MeasureInput& input) const override {
    return SurfaceCountMeasure().run(input);
  }
};

TEST(Capabilities, AFirstInputOnlyMeasureRunsOnTheFirstSupportedInputOfEachVariant) {
  const SurfaceDoubleTechnique surface;
  const auto recordsOf = [&](const measures::Measure& measure) {
    suite::SuiteSelection selection;
    selection.techniques = {&surface};
    selection.assets = {suite::resolveAsset("catmark_cube"), suite::resolveAsset("catmark_torus")};
    selection.measures = {&measure};
    results::Results results;
    suite::runSuite(selection, nullptr, &results);
    return results.records;
  };
  const std::vector<results::Record> once = recordsOf(FirstInputMeasure());
  ASSERT_EQ(once.size(), 2u);  // the two variants, on the first asset only
  for (const results::Record& record : once) EXPECT_EQ(record.asset, "opensubdiv/catmark_cube");
  // The control: the same measure on every input.
  EXPECT_EQ(recordsOf(SurfaceCountMeasure()).size(), 4u);
}

TEST(Capabilities, EachSimulationMeasureGetsAFreshSimulation) {
  const SimulationDoubleTechnique chain;
  const SimulationStepMeasure simulation_measure;
  const ViewMeasure view_measure;  // needs a surface: never runs on the chain
  suite::SuiteSelection selection;
  selection.techniques = {&chain};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.scenarios = {testing::chainScenario(), testing::chainScenario()};
  selection.measures = {&simulation_measure, &view_measure};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  ASSERT_EQ(results.records.size(), 2u);
  for (const results::Record& record : results.records) {
    ASSERT_EQ(record.measures.size(), 1u);
    EXPECT_EQ(metric(record.measures[0].rows[0], "start_time").value, 0);
  }
}

TEST(Capabilities, OnASimulationOnlyTheMeasuresForSimulationsRun) {
  const SimulationDoubleTechnique chain;
  suite::SuiteSelection selection;
  selection.techniques = {&chain};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.scenarios = {testing::chainScenario()};
  results::Results results;
  suite::runSuite(selection, nullptr,
                  &results);  // every registered measure, published_figures included
  EXPECT_TRUE(results.skipped.empty());
  ASSERT_EQ(results.records.size(), 1u);
  std::vector<std::string> ids;
  for (const results::MeasureResult& measure : results.records[0].measures)
    ids.push_back(measure.measure);
  // wave_error is for wave particles only; the surface measures need a surface.
  EXPECT_EQ(ids, (std::vector<std::string>{"instructions", "isa", "memory", "sim_cost"}));
  for (const results::MeasureResult& measure : results.records[0].measures) {
    EXPECT_EQ(measure.status, results::MeasureStatus::kOk)
        << measure.measure << ": " << measure.reason;
  }
  // The chain has no GPU path and no shaders: those parts are skips with their reason.
  const results::MeasureResult& instructions = results.records[0].measures[0];
  ASSERT_EQ(instructions.rows.size(), 1u);
  EXPECT_EQ(instructions.rows[0].status, results::MeasureStatus::kSkipped);
  // 4 masses x (position + velocity) in float: 32 bytes, as SpringChain::footprint says.
  EXPECT_EQ(metric(results.records[0].measures[2].rows.at(0), "state_bytes").value, 32);
}

TEST(Capabilities, ASimulationRunsOnlyOnTheScenariosWrittenForIt) {
  const SimulationDoubleTechnique chain;
  const SimulationStepMeasure simulation_measure;
  techniques::Scenario mine = testing::chainScenario(), any = testing::chainScenario(),
                       other = testing::chainScenario();
  mine.name = "mine";
  mine.technique = "test_spring_chain";
  any.name = "any";
  other.name = "other";
  other.technique = "wave_particles";
  suite::SuiteSelection selection;
  selection.techniques = {&chain};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.scenarios = {mine, any, other};
  selection.measures = {&simulation_measure};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  std::vector<std::string> assets;
  for (const results::Record& record : results.records) assets.push_back(record.asset);
  EXPECT_EQ(assets, (std::vector<std::string>{"mine", "any"}));
}

TEST(Capabilities, AViewMeasureRunsOncePerViewOfTheTestPathWithTheViewAsRowKeys) {
  const SurfaceDoubleTechnique surface;
  const ViewMeasure view_measure;
  suite::SuiteSelection selection;
  selection.techniques = {&surface};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.measures = {&view_measure};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  ASSERT_EQ(results.records.size(), 1u);  // kDefaultOnly
  const results::MeasureResult& result = results.records[0].measures.at(0);
  EXPECT_EQ(result.status, results::MeasureStatus::kOk);
  ASSERT_EQ(result.rows.size(), 3u);
  for (size_t v = 0; v < 3; ++v) {
    const std::map<std::string, std::string> keys{
        {"camera_path", "test_orbit"}, {"level", "1"}, {"view", std::to_string(v)}};
    EXPECT_EQ(result.rows[v].keys, keys);
    EXPECT_EQ(metric(result.rows[v], "width").value, 640);
    // The cube's corner is inside the viewport from every side.
    EXPECT_GT(metric(result.rows[v], "x").value, 0);
    EXPECT_LT(metric(result.rows[v], "x").value, 640);
    EXPECT_GT(metric(result.rows[v], "y").value, 0);
    EXPECT_LT(metric(result.rows[v], "y").value, 480);
  }
  // Three different views: the corner lands on different pixels.
  EXPECT_NE(metric(result.rows[0], "x").value, metric(result.rows[1], "x").value);
}

TEST(Capabilities, EveryCameraPathOfTheSelectionIsWalked) {
  const SurfaceDoubleTechnique surface;
  const ViewMeasure view_measure;
  suite::SuiteSelection selection;
  selection.techniques = {&surface};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.measures = {&view_measure};
  selection.camera_paths = {
      suite::testOrbitPath, [](const mesh::Aabb&) {
        return view::CameraPath{"two_identity_views", {view::View{}, view::View{}}};
      }};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  ASSERT_EQ(results.records.size(), 1u);
  const std::vector<results::MetricRow>& rows = results.records[0].measures.at(0).rows;
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[3].keys.at("camera_path"), "two_identity_views");
  EXPECT_EQ(rows[4].keys.at("view"), "1");
}

TEST(CameraPath, TestOrbitLooksAtTheBoxCentreInVulkanConventions) {
  const mesh::Aabb box{{-1, -2, -3}, {3, 2, 1}};
  const view::CameraPath path = suite::testOrbitPath(box);
  ASSERT_EQ(path.views.size(), 3u);
  for (const view::View& view : path.views) {
    const view::ProjectedPoint centre = view::projectToPixels(view, 1, 0, -1);
    EXPECT_GT(centre.clip_w, 0);
    EXPECT_NEAR(centre.x_px, 320, 1e-9);
    EXPECT_NEAR(centre.y_px, 240, 1e-9);
    // Vulkan clip space: y down, so a point above the centre has a smaller pixel y.
    EXPECT_LT(view::projectToPixels(view, 1, 1, -1).y_px, 240);
    // Depth in [0, 1] for the centre (between the near and far planes).
    const auto clip = view.view_projection.transform({1, 0, -1, 1});
    EXPECT_GT(clip[2] / clip[3], 0);
    EXPECT_LT(clip[2] / clip[3], 1);
  }
}

// The rule against the two booleans it replaces (dependsOnVariant, dependsOnPatchData):
// default variant always; others when the measure follows the variant, or follows the
// patch data and this variant's differ.
TEST(MeasureRule, VariantPoliciesMatchTheFormerBooleans) {
  const SurfaceDoubleTechnique surface;
  const suite::Capabilities caps{true, false};
  struct Case {
    measures::VariantPolicy policy;
    bool depends_on_variant, depends_on_patch_data;
  };
  for (const Case& c : {Case{measures::VariantPolicy::kDefaultOnly, false, false},
                        Case{measures::VariantPolicy::kEveryVariant, true, false},
                        Case{measures::VariantPolicy::kWhenPatchDataDiffers, false, true}}) {
    for (bool is_default : {false, true}) {
      for (bool own : {false, true}) {
        const bool former = is_default || c.depends_on_variant || (c.depends_on_patch_data && own);
        EXPECT_EQ(suite::measureRuns({{measures::MeasureNeed::kSurface}, c.policy, {}}, surface,
                                     caps, {is_default, own}),
                  former);
      }
    }
  }
  // Needs decide before the policy; kView and kGpu never stop a measure.
  EXPECT_FALSE(suite::measureRuns(
      {{measures::MeasureNeed::kSimulation}, measures::VariantPolicy::kEveryVariant, {}}, surface,
      caps, {true, true}));
  EXPECT_TRUE(suite::measureRuns(
      {{measures::MeasureNeed::kSurface, measures::MeasureNeed::kView, measures::MeasureNeed::kGpu},
       measures::VariantPolicy::kEveryVariant,
       {}},
      surface, caps, {true, true}));
  EXPECT_FALSE(suite::measureRuns({{measures::MeasureNeed::kSurface},
                                   measures::VariantPolicy::kEveryVariant,
                                   [](const techniques::Technique&) { return false; }},
                                  surface, caps, {true, true}));
}

// kEveryDistinctSurface: the default variant, every variant in --suite full, and otherwise only
// variants that are not the default's surface in another float order.
TEST(MeasureRule, EveryDistinctSurfaceSkipsEvaluationOrderVariantsInTheDefaultSuite) {
  const SurfaceDoubleTechnique surface;
  const suite::Capabilities caps{true, false};
  const measures::MeasureRequirements r{
      {measures::MeasureNeed::kSurface}, measures::VariantPolicy::kEveryDistinctSurface, {}};
  for (bool is_default : {false, true}) {
    for (bool full : {false, true}) {
      for (bool same_surface : {false, true}) {
        const bool expected = is_default || full || !same_surface;
        EXPECT_EQ(suite::measureRuns(r, surface, caps, {is_default, false, full, same_surface}),
                  expected)
            << is_default << full << same_surface;
      }
    }
  }
}

TEST(MeasureRule, RegisteredMeasuresDeclareWhatTheyDeclaredBefore) {
  const auto requirements = [](const char* id) {
    return measures::MeasureRegistry::instance().find(id)->requirements();
  };
  EXPECT_EQ(requirements("memory").variants, measures::VariantPolicy::kWhenPatchDataDiffers);
  EXPECT_EQ(requirements("cracks").variants, measures::VariantPolicy::kEveryVariant);
  EXPECT_EQ(requirements("instructions").variants, measures::VariantPolicy::kEveryVariant);
  // Since issue 16: a variant that only reorders the float evaluation is graded once.
  EXPECT_EQ(requirements("error").variants, measures::VariantPolicy::kEveryDistinctSurface);
  EXPECT_EQ(requirements("published_figures").variants, measures::VariantPolicy::kDefaultOnly);
  // Which family each measure applies to (memory and instructions: both).
  for (const measures::Measure* measure : measures::MeasureRegistry::instance().all()) {
    const measures::MeasureRequirements r = measure->requirements();
    const std::string id = measure->info().id;
    if (id == "memory" || id == "instructions" || id == "isa") {
      EXPECT_TRUE(r.has(measures::MeasureNeed::kSurfaceOrSimulation)) << id;
    } else if (id == "sim_cost" || id == "wave_error" || id == "convergence" || id == "stability") {
      EXPECT_TRUE(r.has(measures::MeasureNeed::kSimulation)) << id;
    } else {
      EXPECT_TRUE(r.has(measures::MeasureNeed::kSurface)) << id;
    }
  }
  // published_figures: only the technique with the probe shader.
  const SurfaceDoubleTechnique surface;
  EXPECT_FALSE(requirements("published_figures").technique_filter(surface));
}

}  // namespace
}  // namespace tb
