// Tessellation levels from the factor and culling policies in compute, "tessellation without
// the tessellator": shaders/gpu/policy_levels.comp runs the same includes as every
// technique's TCS (shaders/common/tess_factors.glsl, cull.glsl), one invocation a patch, on
// the same words (gpu::TcsFactorPolicy, TcsCullPolicy, packed by harness/lod), so its levels
// equal PatchProgramCapture::tcs_levels bit for bit. Either alone (computePolicyLevels), or
// chained into the compute tessellator (PolicyTessellator): the levels pass writes the
// tessellator's patch records and its count pass reads them in the same command buffer.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/gpu/compute_runner.h"
#include "core/gpu/compute_tessellator.h"
#include "core/gpu/patch_program.h"
#include "core/tess/tessellator.h"

namespace tb::gpu {

class Context;

// One job: one program's patches under one view's policies.
struct PolicyLevelsJob {
  tess::Domain domain = tess::Domain::kQuad;  // the program's (GpuPatchProgram::domain)
  tess::Spacing spacing = tess::Spacing::kInteger;
  uint32_t patch_count = 0;  // the program's patches; the policies' words cover them all
  // Non-null: the levels come from this policy (its words as runPatchProgram takes them).
  const TcsFactorPolicy* factor_policy = nullptr;
  // Non-null: outer levels 0 for the patches this policy culls.
  const TcsCullPolicy* cull_policy = nullptr;
  // Without a factor policy, every patch's levels as the TCS would read them (pow2 spacing:
  // already rounded, tess::roundPow2Levels); with one, ignored.
  tess::Levels levels;
  // The largest level the job can write (the policies clamp at 64; a smaller bound when the
  // caller knows one): sizes the tessellator's buffers, PolicyTessellator only.
  float level_bound = 64.0f;
  // Optional, with a factor policy: per patch, tighter bounds than level_bound (a caller
  // that knows the levels, e.g. a test holding the CPU twin's); they size buffers only.
  std::span<const tess::Levels> level_bounds;
};

// Every patch's levels for one job, as the TCS writes them back (tcs_levels: float bits
// outer[0..3], inner[0..1]; a culled patch has outer levels 0). Without a factor policy,
// every patch starts from `levels` (PolicyLevelsJob::levels). One submission, read back.
// Throws GpuError on a device error or when a policy's words do not cover patch_count.
std::vector<tess::LevelsBits> computePolicyLevels(Context& context, tess::Domain domain,
                                                  tess::Spacing spacing, uint32_t patch_count,
                                                  const TcsFactorPolicy* factor_policy,
                                                  const TcsCullPolicy* cull_policy,
                                                  const tess::Levels& levels = {});

// What one PolicyTessellator run gives: the jobs' patches one after another (job j's patch
// i is record firstRecord(j) + i).
struct PolicyTessellation {
  std::vector<tess::LevelsBits> levels;  // per record, read back from the levels pass
  ComputeTessellation tessellation;      // per record, as ComputeTessellator::read gives it
};

// The levels pass of every job chained into one compute tessellator batch: made once
// (pipelines and buffers; the jobs' policy words are copied in), run() recomputes every
// job's levels and re-tessellates, one submission with no CPU round trip in between.
class PolicyTessellator {
 public:
  // Throws GpuError on a device error, a policy whose words do not cover its job, or
  // buffers past the device's storage buffer range. counts_only: the tessellator's count
  // pass alone (ComputeTessellator's counts_only: counts per record, no points, any size).
  PolicyTessellator(Context& context, std::span<const PolicyLevelsJob> jobs,
                    bool counts_only = false);
  ~PolicyTessellator();
  PolicyTessellator(const PolicyTessellator&) = delete;
  PolicyTessellator& operator=(const PolicyTessellator&) = delete;

  ComputeRunTiming run();           // levels passes, count, scan, write: one submission
  PolicyTessellation read() const;  // throws GpuError when a kernel raised an error bit
  uint32_t firstRecord(size_t job) const { return first_record_.at(job); }
  uint32_t recordCount() const { return record_count_; }

 private:
  std::vector<uint32_t> first_record_;
  uint32_t record_count_ = 0;
  std::unique_ptr<ComputeTessellator> tessellator_;
};

// Builds a PolicyTessellator, runs it once and reads it back.
PolicyTessellation tessellateWithPolicies(Context& context, std::span<const PolicyLevelsJob> jobs);

}  // namespace tb::gpu
