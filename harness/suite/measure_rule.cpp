#include "harness/suite/measure_rule.h"

namespace tb {

Capabilities expectedCapabilities(const Technique& technique) {
  const bool surface = technique.info().family == TechniqueFamily::kSurface;
  const SimulationCapabilities promised =
      surface ? SimulationCapabilities{} : technique.simulationCapabilities();
  return {surface, !surface, promised.constraint_solver, promised.wave_field};
}

Capabilities capabilitiesOf(const TechniqueInstance& instance) {
  const Simulation* simulation = instance.simulation();
  return {instance.surface() != nullptr, simulation != nullptr,
          simulation != nullptr && simulation->constraintSolver() != nullptr,
          simulation != nullptr && simulation->waveField() != nullptr};
}

namespace {
bool policyAdmits(VariantPolicy policy, const VariantStanding& standing) {
  switch (policy) {
    case VariantPolicy::kDefaultOnly:
      return standing.is_default;
    case VariantPolicy::kEveryVariant:
      return true;
    case VariantPolicy::kWhenPatchDataDiffers:
      return standing.is_default || standing.own_patch_data;
    case VariantPolicy::kEveryVariantInFullSuite:
      return standing.is_default || standing.full_suite;
    case VariantPolicy::kEveryDistinctSurface:
      return standing.is_default || standing.full_suite || !standing.same_surface_as_default;
  }
  return false;
}
}  // namespace

bool measureRuns(const MeasureRequirements& requirements, const Technique& technique,
                 const Capabilities& capabilities, const VariantStanding& standing) {
  if (requirements.has(MeasureNeed::kSurface) && !capabilities.surface) return false;
  if (requirements.has(MeasureNeed::kSimulation) && !capabilities.simulation) return false;
  if (requirements.has(MeasureNeed::kSurfaceOrSimulation) && !capabilities.surface &&
      !capabilities.simulation) {
    return false;
  }
  if (requirements.has(MeasureNeed::kConstraintSolver) && !capabilities.constraint_solver) {
    return false;
  }
  if (requirements.has(MeasureNeed::kWaveField) && !capabilities.wave_field) return false;
  if (requirements.technique_filter && !requirements.technique_filter(technique)) return false;
  return policyAdmits(requirements.variants, standing);
}

}  // namespace tb
