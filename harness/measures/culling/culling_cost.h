// What a culling policy costs in the TCS: the technique's own control shaders (its
// gpuPrograms()), specialised with the policy fixed at compile time (cull.glsl's
// kTbCullPolicy = kTbCullPolicyFixed + policy) and optimised (spirv-opt -O), counted in SPIR-V
// instructions (common/instruction_counts), against the same shaders without culling.
#pragma once

#include <span>
#include <vector>

#include "harness/lod/cull_policy.h"
#include "techniques/technique.h"

namespace tb::measures {

struct CullTcsCost {
  // tcs_instructions: SPIR-V instructions (one per instruction, after spirv-opt -O) of the
  //   TCS with this policy, mean over the patches (each patch counts its program's TCS).
  //   Best: the unculled TCS's; worst: unbounded.
  double tcs_instructions = 0;
  // cull_instructions: tcs_instructions minus the unculled TCS's (policy none: 0). The
  //   policy's own code; a loop body counts once, so hull loops count one iteration.
  double cull_instructions = 0;
  bool measured = false;  // false when the technique has no GPU program
};

// One entry per policy, in `policies` order. Cached per shader and specialisation for the
// life of the process. Throws std::runtime_error when a shader does not optimise.
std::vector<CullTcsCost> cullTcsCosts(const techniques::SurfacePatches& patches,
                                      std::span<const lod::CullPolicy> policies);

}  // namespace tb::measures
