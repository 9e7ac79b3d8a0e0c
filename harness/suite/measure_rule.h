// The one rule that decides whether a measure runs on a technique instance × variant ×
// asset, from the measure's MeasureRequirements (harness/measures/measure.h).
#pragma once

#include "harness/measures/measure.h"
#include "techniques/technique.h"

namespace tb::suite {

// Which capabilities an instance has (or, before it is built, will have).
struct Capabilities {
  bool surface = false;
  bool simulation = false;
  // The simulation's optional capabilities (SimulationCapabilities, techniques/simulation.h).
  bool constraint_solver = false;
  bool wave_field = false;
};

// Before building: what the technique's family promises (a surface technique builds
// surfaces, a simulation technique simulations), to avoid building instances no measure
// would use.
Capabilities expectedCapabilities(const techniques::Technique& technique);
Capabilities capabilitiesOf(const techniques::TechniqueInstance& instance);

// Where the variant stands on the asset.
struct VariantStanding {
  bool is_default = false;  // the technique's first variant
  // The variant's patch data differ from the default variant's on this asset. Before the
  // instance is built: whether they may (the default's footprint is known).
  bool own_patch_data = false;
  bool full_suite = false;  // the run is --suite full
  // VariantInfo::evaluation_order_only: the default's surface in another float order.
  bool same_surface_as_default = false;
  // The technique's first supported input of the run (SuiteInput::first_supported).
  bool first_input = true;
};

// True when every need the suite decides on (surface, simulation, constraint solver, wave
// field) is met, the technique
// passes the requirement's filter, and the variant policy admits the variant. kView,
// kCameraPath and kGpu never stop a measure: the suite supplies views and camera paths,
// and a measure without a device reports its GPU parts skipped.
bool measureRuns(const measures::MeasureRequirements& requirements,
                 const techniques::Technique& technique, const Capabilities& capabilities,
                 const VariantStanding& standing);

}  // namespace tb::suite
