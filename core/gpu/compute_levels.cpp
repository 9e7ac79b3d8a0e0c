#include "core/gpu/compute_levels.h"

#include <algorithm>
#include <cassert>
#include <string>

#include "core/gpu/context.h"
#include "core/gpu/gpu_error.h"
#include "shaders/common/layout/bindings.h"

namespace tb::gpu {
namespace {

constexpr uint32_t kLevelsGroupSize = 64;                    // policy_levels.comp's local_size_x
constexpr size_t kLevelsCornerWords = kTcsFactorPatchWords;  // TbFactorPatch
constexpr uint32_t kLevelsReadBackWords = layout::kTbFactorOutWordsPerPatch;
constexpr const char* kLevelsReadBack = "policy_levels";  // layout::kBindingFactorOut

void checkJob(const PolicyLevelsJob& job) {
  if (job.factor_policy != nullptr &&
      job.factor_policy->corner_words.size() != size_t(job.patch_count) * kLevelsCornerWords) {
    throw GpuError("compute levels: factor policy corners for " +
                   std::to_string(job.factor_policy->corner_words.size() / kLevelsCornerWords) +
                   " patches, the job has " + std::to_string(job.patch_count));
  }
  if (job.cull_policy != nullptr &&
      job.cull_policy->patch_words.size() != size_t(job.patch_count) * kTcsCullPatchWords) {
    throw GpuError("compute levels: culling bounds for " +
                   std::to_string(job.cull_policy->patch_words.size() / kTcsCullPatchWords) +
                   " patches, the job has " + std::to_string(job.patch_count));
  }
}

GpuComputeBuffer levelsBuffer(uint32_t binding, std::string name, std::vector<uint32_t> words) {
  GpuComputeBuffer b;
  b.binding = binding;
  b.name = std::move(name);
  b.size_bytes = std::max<uint64_t>(16, 4 * uint64_t(words.size()));
  b.initial_words = std::move(words);
  return b;
}

// Job `index`'s dispatch of policy_levels.comp over its records from `first_record` on.
// Every binding 0..6 is bound (a policy the job lacks gets an empty buffer of its own), as
// the shader uses them all; the records and the read-back are the batch's, sized elsewhere.
GpuComputePass levelsPass(const PolicyLevelsJob& job, size_t index, uint32_t first_record) {
  checkJob(job);
  std::string suffix = std::to_string(index);
  suffix.insert(suffix.begin(), '_');  // (not "_" + ...: GCC 12 warns -Wrestrict)
  const TcsFactorPolicy no_factor;
  const TcsCullPolicy no_cull;
  const TcsFactorPolicy& factor = job.factor_policy ? *job.factor_policy : no_factor;
  const TcsCullPolicy& cull = job.cull_policy ? *job.cull_policy : no_cull;
  GpuComputePass pass;
  pass.shader = "gpu/policy_levels.comp";
  using namespace layout;
  pass.buffers = {
      levelsBuffer(kBindingTessPatchRecords, kTessPatchRecords, {}),
      levelsBuffer(kBindingFactorPatches, "factor_corners" + suffix, factor.corner_words),
      levelsBuffer(kBindingFactorParams, "factor_params" + suffix, factor.param_words),
      levelsBuffer(kBindingFactorOut, kLevelsReadBack, {}),
      levelsBuffer(kBindingCullParams, "cull_params" + suffix, cull.param_words),
      levelsBuffer(kBindingCullPatches, "cull_patches" + suffix, cull.patch_words),
      levelsBuffer(kBindingCullTangentPlanes, "cull_tangents" + suffix, cull.tangent_words)};
  // Listed in binding order, so buffers[b] is binding b's.
  for (size_t b = 0; b < pass.buffers.size(); ++b) assert(pass.buffers[b].binding == b);
  pass.push_constants = {job.patch_count, first_record, job.factor_policy ? 1u : 0u,
                         job.cull_policy ? 1u : 0u};
  pass.groups_x =
      std::max<uint32_t>(1, (job.patch_count + kLevelsGroupSize - 1) / kLevelsGroupSize);
  return pass;
}

// The tessellator's record for one of a job's patches: its starting levels (a factor
// policy's bound, or the job's levels) and codes.
TessPatch recordOf(const PolicyLevelsJob& job) {
  TessPatch patch;
  patch.domain = job.domain;
  patch.spacing = job.spacing;
  patch.levels = job.levels;
  if (job.factor_policy != nullptr) {
    patch.levels.outer.fill(job.level_bound);
    patch.levels.inner.fill(job.level_bound);
  }
  return patch;
}

std::vector<tess::LevelsBits> levelsOf(const std::vector<uint32_t>& words, uint32_t records) {
  std::vector<tess::LevelsBits> levels(records);
  for (uint32_t r = 0; r < records; ++r) {
    std::copy_n(words.begin() + ptrdiff_t(r) * kLevelsReadBackWords, 6, levels[r].begin());
  }
  return levels;
}

}  // namespace

std::vector<tess::LevelsBits> computePolicyLevels(Context& context, tess::Domain domain,
                                                  tess::Spacing spacing, uint32_t patch_count,
                                                  const TcsFactorPolicy* factor_policy,
                                                  const TcsCullPolicy* cull_policy,
                                                  const tess::Levels& levels) {
  PolicyLevelsJob job;
  job.levels = levels;
  job.domain = domain;
  job.spacing = spacing;
  job.patch_count = patch_count;
  job.factor_policy = factor_policy;
  job.cull_policy = cull_policy;
  GpuComputePass pass = levelsPass(job, 0, 0);
  const TessPatch record = recordOf(job);
  std::vector<uint32_t> words;
  words.reserve(size_t(patch_count) * kTessPatchRecordWords);
  for (uint32_t p = 0; p < patch_count; ++p) appendTessPatchRecord(words, record);
  pass.buffers[layout::kBindingTessPatchRecords] =
      levelsBuffer(layout::kBindingTessPatchRecords, kTessPatchRecords, std::move(words));
  pass.buffers[layout::kBindingFactorOut].size_bytes =
      std::max<uint64_t>(16, 4ull * kLevelsReadBackWords * patch_count);
  ComputeRunner runner(context, {{"levels", {pass}}});
  runner.run(1);
  return levelsOf(runner.read(kLevelsReadBack), patch_count);
}

PolicyTessellator::PolicyTessellator(Context& context, std::span<const PolicyLevelsJob> jobs,
                                     bool counts_only) {
  std::vector<TessPatch> records;
  std::vector<GpuComputePass> passes;
  for (size_t j = 0; j < jobs.size(); ++j) {
    first_record_.push_back(static_cast<uint32_t>(records.size()));
    passes.push_back(levelsPass(jobs[j], j, first_record_.back()));
    const PolicyLevelsJob& job = jobs[j];
    if (!job.level_bounds.empty() && job.level_bounds.size() != job.patch_count) {
      throw GpuError("compute levels: " + std::to_string(job.level_bounds.size()) +
                     " level bounds for a job of " + std::to_string(job.patch_count) + " patches");
    }
    for (uint32_t i = 0; i < job.patch_count; ++i) {
      records.push_back(recordOf(job));
      if (job.factor_policy != nullptr && !job.level_bounds.empty()) {
        records.back().levels = job.level_bounds[i];
      }
    }
  }
  record_count_ = static_cast<uint32_t>(records.size());
  if (!passes.empty()) {
    passes[0].buffers[layout::kBindingFactorOut].size_bytes =
        std::max<uint64_t>(16, 4ull * kLevelsReadBackWords * record_count_);
  }
  tessellator_ =
      std::make_unique<ComputeTessellator>(context, records, std::move(passes), counts_only);
}

PolicyTessellator::~PolicyTessellator() = default;

ComputeRunTiming PolicyTessellator::run() { return tessellator_->run(); }

PolicyTessellation PolicyTessellator::read() const {
  PolicyTessellation out;
  out.tessellation = tessellator_->read();
  if (record_count_ > 0) {
    out.levels = levelsOf(tessellator_->readBuffer(kLevelsReadBack), record_count_);
  }
  return out;
}

PolicyTessellation tessellateWithPolicies(Context& context, std::span<const PolicyLevelsJob> jobs) {
  PolicyTessellator tessellator(context, jobs);
  tessellator.run();
  return tessellator.read();
}

}  // namespace tb::gpu
