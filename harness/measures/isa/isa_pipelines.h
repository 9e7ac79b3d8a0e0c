// Which pipelines the ISA measure compiles for a technique × variant: the builds the suite
// makes of each of its GPU programs (the harness's levels, the factor policy's and the
// culling policy's TCS, the displaced TES, the compute path's two passes) or, for a
// simulation, each compute pass of each step program.
#pragma once

#include <string>
#include <vector>

#include "harness/measures/common/isa/isa_request.h"
#include "techniques/technique.h"

namespace tb::measures::isa {

struct NamedPipeline {
  // "tessellator", "factor_policy", "cull_policy", "cull_policy/frustum_hull", "displaced",
  // "compute_build", "compute_evaluate"; a simulation's "<program>/<shader>".
  std::string pipeline;
  std::string program;  // "quad" or "triangle" when the technique's programs mix them
  std::string shaders;  // the embedded stages it compiles, "acc/acc.tesc + acc/acc.tese"
  PipelineRequest request;
};

// The builds of the surface's programs: the harness's levels (tessellator) and the compute
// path's passes; `full` adds the factor and culling policies' TCS builds (the runtime
// switch, and one per culling policy fixed at compile time, kTbCullPolicyFixed + p) and the
// displaced TES.
std::vector<NamedPipeline> surfacePipelines(const techniques::SurfacePatches& patches, bool full);

// Every compute pass of the simulation's step programs.
std::vector<NamedPipeline> simulationPipelines(const techniques::Simulation& simulation);

}  // namespace tb::measures::isa
