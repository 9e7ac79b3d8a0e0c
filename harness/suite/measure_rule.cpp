#include "harness/suite/measure_rule.h"

namespace tb::suite {

Capabilities expectedCapabilities(const techniques::Technique& technique) {
  const bool surface = technique.info().family == techniques::TechniqueFamily::kSurface;
  const techniques::SimulationCapabilities promised =
      surface ? techniques::SimulationCapabilities{} : technique.simulationCapabilities();
  return {surface, !surface, promised.constraint_solver, promised.wave_field};
}

Capabilities capabilitiesOf(const techniques::TechniqueInstance& instance) {
  const techniques::Simulation* simulation = instance.simulation();
  return {instance.surface() != nullptr, simulation != nullptr,
          simulation != nullptr && simulation->constraintSolver() != nullptr,
          simulation != nullptr && simulation->waveField() != nullptr};
}

namespace {
bool policyAdmits(measures::VariantPolicy policy, const VariantStanding& standing) {
  switch (policy) {
    case measures::VariantPolicy::kDefaultOnly:
      return standing.is_default;
    case measures::VariantPolicy::kEveryVariant:
      return true;
    case measures::VariantPolicy::kWhenPatchDataDiffers:
      return standing.is_default || standing.own_patch_data;
    case measures::VariantPolicy::kEveryVariantInFullSuite:
      return standing.is_default || standing.full_suite;
    case measures::VariantPolicy::kEveryDistinctSurface:
      return standing.is_default || standing.full_suite || !standing.same_surface_as_default;
  }
  return false;
}
}  // namespace

bool measureRuns(const measures::MeasureRequirements& requirements,
                 const techniques::Technique& technique, const Capabilities& capabilities,
                 const VariantStanding& standing) {
  if (requirements.has(measures::MeasureNeed::kSurface) && !capabilities.surface) return false;
  if (requirements.has(measures::MeasureNeed::kSimulation) && !capabilities.simulation)
    return false;
  if (requirements.has(measures::MeasureNeed::kSurfaceOrSimulation) && !capabilities.surface &&
      !capabilities.simulation) {
    return false;
  }
  if (requirements.has(measures::MeasureNeed::kConstraintSolver) &&
      !capabilities.constraint_solver) {
    return false;
  }
  if (requirements.has(measures::MeasureNeed::kWaveField) && !capabilities.wave_field) return false;
  if (requirements.technique_filter && !requirements.technique_filter(technique)) return false;
  if (requirements.first_input_only && !standing.first_input) return false;
  return policyAdmits(requirements.variants, standing);
}

}  // namespace tb::suite
