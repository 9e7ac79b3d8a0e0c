// Scenario files (harness/suite/scenario_file.h). Oracle: the fields written into the
// file, read back; every bad input one line naming the file and the field.
#include "harness/suite/scenario_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "tests/test_support.h"

namespace tb {
namespace {

const std::string kValid = R"({
  "format": "tessbench-scenario-1", "name": "ok", "technique": "wave_particles",
  "time_step_s": 0.01, "duration_s": 0.5,
  "parameters": {"domain_size_m": 4, "wave_speed_m_per_s": 1.5},
  "wave_particles": {"sources": [{"position_m": [0, 0], "amplitude_m": 0.1}]},
  "mass_spring": {"stiffness": [1, 2]}
})";

// The loader's message for `text`, or "" when it loads.
std::string loadError(const std::string& text) {
  const auto dir = testing::scratchDirectory("scenario_bad");
  const std::string file = testing::writeTextFile(dir / "bad.json", text);
  try {
    suite::loadScenarioFile(file, "scenarios/bad.json");
  } catch (const mesh::InputError& error) {
    return error.what();
  }
  return "";
}

// kValid with `from` replaced by `to` (the first occurrence).
std::string validWith(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(ScenarioFile, FieldsAndSectionsAreReadBack) {
  const auto dir = testing::scratchDirectory("scenario_ok");
  const std::string file = testing::writeTextFile(dir / "ok.json", kValid);
  const techniques::Scenario scenario = suite::loadScenarioFile(file);
  EXPECT_EQ(scenario.name, "ok");
  EXPECT_EQ(scenario.technique, "wave_particles");
  EXPECT_EQ(scenario.time_step_s, 0.01);
  EXPECT_EQ(scenario.duration_s, 0.5);
  EXPECT_EQ(scenario.stepCount(), 50u);
  EXPECT_EQ(scenario.parameters.at("domain_size_m"), 4.0);
  EXPECT_EQ(scenario.parameters.at("wave_speed_m_per_s"), 1.5);
  ASSERT_EQ(scenario.sections.size(), 2u);
  EXPECT_EQ(scenario.sections.at("mass_spring"), R"({"stiffness":[1,2]})");
  EXPECT_NE(scenario.sections.at("wave_particles").find("amplitude_m"), std::string::npos);
  EXPECT_TRUE(scenario.mesh_path.empty());
  EXPECT_TRUE(std::filesystem::path(scenario.path).is_absolute());
}

TEST(ScenarioFile, AMeshResolvesBesideTheFileOrAsABundledAsset) {
  const auto dir = testing::scratchDirectory("scenario_mesh");
  testing::writeTextFile(dir / "skin.obj", "v 0 0 0\n");
  const std::string beside = testing::writeTextFile(
      dir / "a.json", validWith(R"("name": "ok")", R"("name": "ok", "mesh": "skin.obj")"));
  EXPECT_EQ(suite::loadScenarioFile(beside).mesh_path, (dir / "skin.obj").string());
  const std::string bundled = testing::writeTextFile(
      dir / "b.json", validWith(R"("name": "ok")", R"("name": "ok", "mesh": "catmark_cube")"));
  const std::string mesh = suite::loadScenarioFile(bundled).mesh_path;
  EXPECT_TRUE(std::filesystem::path(mesh).is_absolute()) << mesh;
  EXPECT_TRUE(std::filesystem::is_regular_file(mesh)) << mesh;
}

TEST(ScenarioFile, EveryBadInputIsOneLineNamingTheFileAndTheField) {
  struct Case {
    std::string text;
    std::string expected;  // after "scenarios/bad.json: "
  };
  const std::vector<Case> cases = {
      {R"({"format": )", "malformed JSON"},
      {"[1, 2]", "expected a JSON object"},
      {validWith("tessbench-scenario-1", "tessbench-scenario-9"), "format: expected"},
      {validWith(R"("name": "ok", )", ""), "name: missing"},
      {validWith(R"("name": "ok")", R"("name": "")"), "name: empty"},
      {validWith(R"("time_step_s": 0.01, )", ""), "time_step_s: missing"},
      {validWith("0.01", "0"), "time_step_s: must be > 0"},
      {validWith("0.01", "-1"), "time_step_s: must be > 0"},
      {validWith("0.01", R"("fast")"), "time_step_s: expected a number"},
      {validWith("0.01", "1e999"), "not a finite number"},
      {validWith("0.5", "0.001"), "duration_s: must be >= time_step_s"},
      {validWith("1.5}", R"("x"})"), "parameters.wave_speed_m_per_s: expected a number"},
      {validWith(R"("parameters": {)", R"("parameters": 3, "p": {)"), "parameters: expected"},
      {validWith(R"("name": "ok")", R"("name": "ok", "colour": 3)"), "colour: unknown field"},
      {validWith(R"("technique": "wave_particles")", R"("technique": 7)"),
       "technique: expected a string"},
      {validWith(R"("name": "ok")", R"("name": "ok", "mesh": "no_such_mesh")"),
       "mesh: 'no_such_mesh' is neither"},
  };
  for (const Case& c : cases) {
    const std::string message = loadError(c.text);
    EXPECT_EQ(message.rfind("scenarios/bad.json: ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << message << "\n  wanted " << c.expected;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_EQ(loadError(kValid), "");
}

TEST(ScenarioFile, AMissingFileAndAnUnknownNameAreInputErrors) {
  EXPECT_THROW(suite::loadScenarioFile("/no/such/scenario.json"), mesh::InputError);
  EXPECT_THROW(suite::resolveScenario("not_a_scenario"), mesh::InputError);
}

TEST(ScenarioFile, TheBundledScenariosLoadSortedAndNamedAfterTheirFiles) {
  const std::vector<std::string> names = suite::bundledScenarioNames();
  ASSERT_GE(names.size(), 2u);
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  const std::vector<techniques::Scenario> scenarios = suite::bundledScenarios();
  ASSERT_EQ(scenarios.size(), names.size());
  for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(scenarios[i].name, names[i]);
  EXPECT_EQ(suite::resolveScenario("wave_point_impulse").technique, "wave_particles");
  EXPECT_EQ(suite::resolveScenario("wave_straight_wall").name, "wave_straight_wall");
}

}  // namespace
}  // namespace tb
