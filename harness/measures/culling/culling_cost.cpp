#include "harness/measures/culling/culling_cost.h"

#include "core/gpu/patch_program_desc.h"
#include "harness/measures/common/instruction_counts/instructions.h"

namespace tb::measures {
namespace {

constexpr uint32_t kCullPolicyConstantId = 202;  // kTbCullPolicy in shaders/common/cull.glsl
constexpr uint32_t kCullPolicyFixed = 100;       // kTbCullPolicyFixed

// Patch-weighted mean of the programs' TCS instruction counts with kTbCullPolicy = value
// (0: no culling).
double meanTcsInstructions(std::span<const gpu::GpuPatchProgram> programs, uint32_t value) {
  double weighted = 0, patches = 0;
  for (const gpu::GpuPatchProgram& program : programs) {
    const SpecConstantsById by_id =
        value == 0 ? SpecConstantsById{} : SpecConstantsById{{kCullPolicyConstantId, value}};
    const StageInstructionCounts counts =
        cachedEmbeddedShaderCounts(program.control_shader, program.specialization, by_id);
    weighted += double(counts.vector.total()) * double(program.patch_count);
    patches += double(program.patch_count);
  }
  return patches > 0 ? weighted / patches : 0;
}

}  // namespace

std::vector<CullTcsCost> cullTcsCosts(const techniques::SurfacePatches& patches,
                                      std::span<const lod::CullPolicy> policies) {
  std::vector<CullTcsCost> costs(policies.size());
  const std::vector<gpu::GpuPatchProgram> programs = patches.gpuPrograms();
  if (programs.empty()) return costs;
  const double unculled = meanTcsInstructions(programs, 0);
  for (size_t k = 0; k < policies.size(); ++k) {
    const uint32_t policy = uint32_t(policies[k]);
    costs[k].tcs_instructions =
        policy == 0 ? unculled : meanTcsInstructions(programs, kCullPolicyFixed + policy);
    costs[k].cull_instructions = costs[k].tcs_instructions - unculled;
    costs[k].measured = true;
  }
  return costs;
}

}  // namespace tb::measures
