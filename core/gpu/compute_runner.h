// Runs a simulation's compute programs (compute_program_desc.h) on a Vulkan device: one
// allocation per buffer name, kept across passes, programs and steps; every pass of every
// step of one run() recorded into one command buffer with a barrier after each dispatch,
// so no CPU read-back happens inside the step loop (indirect dispatches read their sizes
// from device buffers). Buffers are read back only after a run.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/gpu/compute_program_desc.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

// A compute pass's pipeline with its layouts, immutable once made.
struct CachedComputePipeline {
  VkDescriptorSetLayoutOwner set_layout;
  VkPipelineLayoutOwner layout;
  VkPipelineOwner pipeline;
};

// The pass's set-0 binding count: its highest binding + 1 (0 without buffers).
uint32_t bindingCountOf(const GpuComputePass& pass);

// The pass's pipeline (specialisation constants 0..M-1, `binding_count` storage buffers,
// the push block's size), created with `flags` (0, or the capture bits of
// pipeline_executables.h). Throws GpuError.
std::shared_ptr<const CachedComputePipeline> createComputePassPipeline(
    VkDevice device, const GpuComputePass& desc, uint32_t binding_count,
    VkPipelineCreateFlags flags = 0);

struct ComputeRunTiming {
  uint32_t steps = 0;            // steps this run() recorded
  double gpu_ns = 0;             // timestamps around the whole run; NaN without timestamps
  double submit_to_fence_s = 0;  // host seconds, submit to fence
};

class ComputeRunner {
 public:
  // Creates one pipeline per pass (specialisation constants 0..M-1 from the pass; passes
  // with the same shader, specialisation, binding count and push block size share one) and one
  // buffer per name (the largest size_bytes any pass declares, filled with the first
  // non-empty initial_words, zero elsewhere). Throws GpuError on a device error or an
  // inconsistent description (a missing shader, an indirect buffer no pass binds, initial
  // words beyond the size, a step_index_word beyond the push block, repeats_per_step 0).
  ComputeRunner(Context& context, const std::vector<GpuComputeProgram>& programs);
  ~ComputeRunner();
  ComputeRunner(const ComputeRunner&) = delete;
  ComputeRunner& operator=(const ComputeRunner&) = delete;

  // Records `steps` steps (programs in order, passes in order, each pass repeats_per_step
  // times) into one command buffer, submits it and waits. Step indices continue from the
  // previous run, so ping-pong parity and step_index_word stay consistent across runs.
  ComputeRunTiming run(uint32_t steps);
  // The same, then `after` records into the same command buffer once the last dispatch's
  // writes are visible to compute, indirect-command and index/vertex reads (a draw of the
  // buffers: core/gpu/compute_path.h), before the host may read the buffers.
  ComputeRunTiming run(uint32_t steps, const std::function<void(VkCommandBuffer)>& after);
  // The device buffer `name` (for `after`). Throws GpuError for an unknown name.
  VkBuffer bufferHandle(const std::string& name) const;
  // Dispatches recorded per step: the sum over passes of repeats_per_step.
  uint32_t dispatchesPerStep() const;
  uint32_t stepsDone() const;
  // The whole buffer `name`, as 32-bit words. Throws GpuError for an unknown name.
  std::vector<uint32_t> read(const std::string& name) const;
  // Words [first_word, first_word + word_count) of buffer `name`. Throws GpuError for an
  // unknown name or a range past the buffer's end.
  std::vector<uint32_t> read(const std::string& name, uint64_t first_word,
                             uint64_t word_count) const;
  // Bytes of every buffer the runner allocated (the GPU-resident state of the programs).
  uint64_t residentBytes() const;
  std::vector<std::string> bufferNames() const;  // sorted

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::gpu
