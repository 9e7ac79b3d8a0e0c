// A mass_spring scenario built in code, as the bundled assets/scenarios/mass_spring_*.json
// files describe it: the bundled pawn (catmark_pawn) as the skin around a vertical bone
// chain, with a stomp or a blast.
#pragma once

#include <memory>
#include <string>

#include "techniques/mass_spring/mass_spring.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb::testing {

// The "mass_spring" section of the bundled scenarios, with `animation` (a JSON array).
inline std::string massSpringSection(const std::string& animation) {
  return R"({
    "bone_chain_m": [[1.7468, -1.2749, 0.03], [1.7468, -1.2749, 0.25], [1.7468, -1.2749, 0.50]],
    "stiffness": {"surface": 1.0, "inner": 0.3, "goal": 0.3},
    "softness": {"default": 0.4,
                 "spheres": [{"center_m": [1.90, -1.2749, 0.20], "radius_m": 0.15, "value": 0.95}]},
    "damping": 0.02,
    "gravity_m_per_s2": [0, 0, -9.81],
    "animation": )" +
         animation + "}";
}

inline const char* kStompAnimation =
    R"([{"kind": "stomp", "direction": [0, 0, 1], "frequency_hz": 2,
         "joint_amplitudes_m": [0.02, 0.01, 0.0]}])";
inline const char* kBlastAnimation =
    R"([{"kind": "blast", "time_s": 0.1, "center_m": [1.95, -1.2749, 0.30], "radius_m": 0.2,
         "speed_m_per_s": 1.0}])";

inline techniques::Scenario massSpringScenario(const std::string& animation = kStompAnimation,
                                               const std::string& name = "mass_spring_stomp") {
  techniques::Scenario scenario;
  scenario.name = name;
  scenario.time_step_s = 1.0 / 60;
  scenario.duration_s = 1.0;
  scenario.parameters = {{"dispatches_per_step", 8}};
  scenario.technique = "mass_spring";
  scenario.sections["mass_spring"] = massSpringSection(animation);
  scenario.mesh_path = assetPath("opensubdiv/catmark_pawn.obj");
  return scenario;
}

// A built simulation of the registered technique's variant `name`, with extra parameters.
inline std::unique_ptr<techniques::TechniqueInstance> buildMassSpring(
    const techniques::Scenario& scenario, const std::string& name,
    const std::map<std::string, double>& extra = {}) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find("mass_spring");
  for (techniques::VariantInfo variant : technique->variants()) {
    if (variant.name != name) continue;
    for (const auto& [key, value] : extra) variant.parameters[key] = value;
    return technique->build({nullptr, &scenario}, variant);
  }
  return nullptr;
}

inline mass_spring::MassSpringSimulation& massSpringOf(techniques::TechniqueInstance& instance) {
  return dynamic_cast<mass_spring::MassSpringSimulation&>(*instance.simulation());
}

}  // namespace tb::testing
