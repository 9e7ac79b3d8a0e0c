#include "core/gpu/compute_runner.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

#include "core/gpu/buffer.h"
#include "core/gpu/context.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
    VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
    VK_BUFFER_USAGE_TRANSFER_DST_BIT;

[[noreturn]] void fail(const GpuComputePass& pass, const std::string& rule) {
  throw GpuError("compute runner: pass " + pass.shader + ": " + rule);
}

}  // namespace

// Every ComputeRunner's pipelines on one Context, by shader, specialisation, bindings and
// push block size: llvmpipe compiles a pipeline in 0.1 to 0.5 s, more than a small run
// costs, and the compute path (compute_path.h) makes a runner per call.
struct ComputePipelineCache {
  explicit ComputePipelineCache(Context& /*context*/) {}

  std::shared_ptr<const CachedComputePipeline> get(Context& context, const GpuComputePass& desc,
                                                   uint32_t binding_count) {
    std::string key = desc.shader + "|" + std::to_string(binding_count) + "|" +
                      std::to_string(desc.push_constants.size());
    for (uint32_t word : desc.specialization) key += "|" + std::to_string(word);
    const std::lock_guard lock(mutex);
    std::shared_ptr<const CachedComputePipeline>& entry = entries[key];
    if (!entry) entry = createComputePassPipeline(context.device(), desc, binding_count);
    return entry;
  }

  std::mutex mutex;
  std::map<std::string, std::shared_ptr<const CachedComputePipeline>> entries;
};

uint32_t bindingCountOf(const GpuComputePass& pass) {
  uint32_t count = 0;
  for (const GpuComputeBuffer& b : pass.buffers) count = std::max(count, b.binding + 1);
  return count;
}

std::shared_ptr<const CachedComputePipeline> createComputePassPipeline(
    VkDevice device, const GpuComputePass& desc, uint32_t binding_count,
    VkPipelineCreateFlags flags) {
  auto made = std::make_shared<CachedComputePipeline>();
  const std::vector<VkShaderStageFlags> stages(binding_count, VK_SHADER_STAGE_COMPUTE_BIT);
  made->set_layout = createStorageBufferSetLayout(device, stages);
  made->layout = createPipelineLayout(device, made->set_layout.get(), VK_SHADER_STAGE_COMPUTE_BIT,
                                      uint32_t(desc.push_constants.size() * 4));
  const VkShaderModuleOwner module = createShaderModule(device, requireEmbeddedShader(desc.shader));
  std::vector<VkSpecializationMapEntry> entries;
  for (uint32_t i = 0; i < desc.specialization.size(); ++i) entries.push_back({i, i * 4u, 4});
  const VkSpecializationInfo specialization{uint32_t(entries.size()), entries.data(),
                                            desc.specialization.size() * 4,
                                            desc.specialization.data()};
  auto info = vkStruct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  info.stage = shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module.get());
  if (!entries.empty()) info.stage.pSpecializationInfo = &specialization;
  info.layout = made->layout.get();
  info.flags = flags;
  VkPipeline pipeline = VK_NULL_HANDLE;
  vkCheck(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
          "vkCreateComputePipelines (compute runner)");
  made->pipeline = VkPipelineOwner(device, pipeline);
  return made;
}

struct ComputeRunner::Impl {
  struct Pass {
    const GpuComputePass* desc = nullptr;
    std::shared_ptr<const CachedComputePipeline> compiled;  // shared through the Context
    StorageBufferSet sets[2];  // even and odd steps (the same bindings without ping-pong)
    VkBuffer indirect[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  };

  explicit Impl(Context& ctx) : context(ctx) {}

  Context& context;
  std::vector<GpuComputeProgram> programs;  // owned copy: passes point into it
  std::map<std::string, Buffer> buffers;
  std::vector<Pass> passes;
  VkQueryPoolOwner timestamps;
  uint32_t steps_done = 0;

  const Buffer& named(const std::string& name) const {
    auto found = buffers.find(name);
    if (found == buffers.end()) throw GpuError("compute runner: no buffer named '" + name + "'");
    return found->second;
  }

  Buffer& buffer(const GpuComputePass& pass, const std::string& name) {
    auto found = buffers.find(name);
    if (found == buffers.end()) fail(pass, "no buffer named '" + name + "'");
    return found->second;
  }

  void allocate() {
    std::map<std::string, uint64_t> sizes;
    std::map<std::string, const std::vector<uint32_t>*> initial;
    for (const GpuComputeProgram& program : programs) {
      for (const GpuComputePass& pass : program.passes) {
        for (const GpuComputeBuffer& b : pass.buffers) {
          if (b.initial_words.size() * 4 > b.size_bytes) {
            fail(pass, "buffer " + b.name + " has more initial words than size_bytes");
          }
          uint64_t& size = sizes[b.name];
          size = std::max<uint64_t>({size, b.size_bytes, 16});
          if (!b.initial_words.empty() && !initial.count(b.name))
            initial[b.name] = &b.initial_words;
          if (!b.alternate_with.empty())
            sizes[b.alternate_with] = std::max(sizes[b.alternate_with], size);
        }
      }
    }
    // A buffer named only by alternate_with gets the size of its partner.
    for (const GpuComputeProgram& program : programs) {
      for (const GpuComputePass& pass : program.passes) {
        for (const GpuComputeBuffer& b : pass.buffers) {
          if (!b.alternate_with.empty()) {
            const uint64_t size = std::max(sizes[b.name], sizes[b.alternate_with]);
            sizes[b.name] = sizes[b.alternate_with] = size;
          }
        }
      }
    }
    for (const auto& [name, size] : sizes) {
      Buffer buffer(context, (size + 3) / 4 * 4, kUsage);
      std::memset(buffer.data(), 0, buffer.sizeBytes());
      if (auto words = initial.find(name); words != initial.end()) {
        buffer.write(words->second->data(), words->second->size() * 4);
      }
      buffers.emplace(name, std::move(buffer));
    }
  }

  void build(const GpuComputePass& desc) {
    Pass pass;
    pass.desc = &desc;
    const VkDevice device = context.device();
    if (desc.repeats_per_step == 0) fail(desc, "repeats_per_step is 0");
    if (desc.step_index_word >= int32_t(desc.push_constants.size())) {
      fail(desc, "step_index_word is beyond the push block");
    }
    const uint32_t binding_count = bindingCountOf(desc);
    pass.compiled = context.attachment<ComputePipelineCache>().get(context, desc, binding_count);

    for (int parity = 0; parity < 2; ++parity) {
      if (binding_count > 0) {
        pass.sets[parity] =
            StorageBufferSet(device, pass.compiled->set_layout.get(), binding_count);
        // Bindings the pass leaves out get its first buffer, so every binding is valid.
        std::vector<VkBuffer> handles(binding_count, buffer(desc, desc.buffers[0].name).handle());
        for (const GpuComputeBuffer& b : desc.buffers) {
          const std::string& name =
              parity == 1 && !b.alternate_with.empty() ? b.alternate_with : b.name;
          handles[b.binding] = buffer(desc, name).handle();
        }
        pass.sets[parity].bind(device, handles);
      }
      if (!desc.indirect_buffer.empty()) {
        std::string name = desc.indirect_buffer;
        for (const GpuComputeBuffer& b : desc.buffers) {
          if (b.name == desc.indirect_buffer && parity == 1 && !b.alternate_with.empty()) {
            name = b.alternate_with;
          }
        }
        Buffer& indirect = buffer(desc, name);
        if (desc.indirect_offset_bytes + 12 > indirect.sizeBytes()) {
          fail(desc, "indirect_offset_bytes is beyond buffer " + name);
        }
        pass.indirect[parity] = indirect.handle();
      }
    }
    passes.push_back(std::move(pass));
  }

  void record(VkCommandBuffer cmd, uint32_t steps,
              const std::function<void(VkCommandBuffer)>* after) {
    const VkQueryPool pool = timestamps.get();
    if (pool) {
      vkCmdResetQueryPool(cmd, pool, 0, 2);
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool, 0);
    }
    auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT |
                            VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    for (uint32_t s = 0; s < steps; ++s) {
      const uint32_t step = steps_done + s;
      const int parity = int(step & 1u);
      for (Pass& pass : passes) {
        const GpuComputePass& desc = *pass.desc;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.compiled->pipeline.get());
        if (pass.sets[parity].set != VK_NULL_HANDLE) {
          vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pass.compiled->layout.get(),
                                  0, 1, &pass.sets[parity].set, 0, nullptr);
        }
        if (!desc.push_constants.empty()) {
          std::vector<uint32_t> push = desc.push_constants;
          if (desc.step_index_word >= 0) push[size_t(desc.step_index_word)] = step;
          vkCmdPushConstants(cmd, pass.compiled->layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                             uint32_t(push.size() * 4), push.data());
        }
        for (uint32_t r = 0; r < desc.repeats_per_step; ++r) {
          if (pass.indirect[parity] != VK_NULL_HANDLE) {
            vkCmdDispatchIndirect(cmd, pass.indirect[parity], desc.indirect_offset_bytes);
          } else {
            vkCmdDispatch(cmd, desc.groups_x, desc.groups_y, desc.groups_z);
          }
          vkCmdPipelineBarrier(
              cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
              VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1,
              &barrier, 0, nullptr, 0, nullptr);
        }
      }
    }
    if (after != nullptr && *after) {
      auto draw = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
      draw.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      draw.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT |
                           VK_ACCESS_INDEX_READ_BIT | VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT;
      vkCmdPipelineBarrier(
          cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
          VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
              VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
          0, 1, &draw, 0, nullptr, 0, nullptr);
      (*after)(cmd);
    }
    if (pool) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool, 1);
    auto host = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &host, 0, nullptr, 0, nullptr);
  }
};

ComputeRunner::ComputeRunner(Context& context, const std::vector<GpuComputeProgram>& programs)
    : impl_(std::make_unique<Impl>(context)) {
  context.requireFeatures(computeFeatures(), "compute runner");
  impl_->programs = programs;
  impl_->allocate();
  for (const GpuComputeProgram& program : impl_->programs) {
    for (const GpuComputePass& pass : program.passes) {
      if (pass.buffers.empty() && !pass.indirect_buffer.empty()) {
        fail(pass, "an indirect dispatch from a buffer the pass does not bind");
      }
      impl_->build(pass);
    }
  }
  if (context.features().timestamps) {
    auto query_info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    query_info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    query_info.queryCount = 2;
    VkQueryPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateQueryPool(context.device(), &query_info, nullptr, &pool), "vkCreateQueryPool");
    impl_->timestamps = VkQueryPoolOwner(context.device(), pool);
  }
}

ComputeRunner::~ComputeRunner() = default;

ComputeRunTiming ComputeRunner::run(uint32_t steps) { return run(steps, {}); }

ComputeRunTiming ComputeRunner::run(uint32_t steps,
                                    const std::function<void(VkCommandBuffer)>& after) {
  ComputeRunTiming timing;
  timing.steps = steps;
  timing.gpu_ns = std::numeric_limits<double>::quiet_NaN();
  if (steps == 0) return timing;
  timing.submit_to_fence_s =
      impl_->context.submitAndWait([&](VkCommandBuffer cmd) { impl_->record(cmd, steps, &after); });
  impl_->steps_done += steps;
  if (const VkQueryPool pool = impl_->timestamps.get()) {
    uint64_t ticks[2] = {0, 0};
    vkCheck(
        vkGetQueryPoolResults(impl_->context.device(), pool, 0, 2, sizeof(ticks), ticks,
                              sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults (compute runner)");
    timing.gpu_ns = double(ticks[1] - ticks[0]) * impl_->context.info().timestamp_period_ns;
  }
  return timing;
}

uint32_t ComputeRunner::dispatchesPerStep() const {
  uint32_t count = 0;
  for (const Impl::Pass& pass : impl_->passes) count += pass.desc->repeats_per_step;
  return count;
}

VkBuffer ComputeRunner::bufferHandle(const std::string& name) const {
  return impl_->named(name).handle();
}

uint32_t ComputeRunner::stepsDone() const { return impl_->steps_done; }

std::vector<uint32_t> ComputeRunner::read(const std::string& name) const {
  return read(name, 0, impl_->named(name).sizeBytes() / 4);
}

std::vector<uint32_t> ComputeRunner::read(const std::string& name, uint64_t first_word,
                                          uint64_t word_count) const {
  const Buffer& buffer = impl_->named(name);
  if ((first_word + word_count) * 4 > buffer.sizeBytes()) {
    throw GpuError("compute runner: reading past the end of buffer '" + name + "'");
  }
  std::vector<uint32_t> words(static_cast<size_t>(word_count));
  buffer.read(words.data(), words.size() * 4, static_cast<size_t>(first_word * 4));
  return words;
}

uint64_t ComputeRunner::residentBytes() const {
  uint64_t bytes = 0;
  for (const auto& [name, buffer] : impl_->buffers) bytes += buffer.sizeBytes();
  return bytes;
}

std::vector<std::string> ComputeRunner::bufferNames() const {
  std::vector<std::string> names;
  for (const auto& [name, buffer] : impl_->buffers) names.push_back(name);
  return names;
}

}  // namespace tb::gpu
