#include "core/gpu/compute_path.h"

#include <algorithm>
#include <functional>
#include <string>

#include "core/gpu/compute_runner.h"
#include "core/gpu/compute_tessellator.h"
#include "core/gpu/context.h"
#include "core/gpu/device_info.h"
#include "core/gpu/gpu_error.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/tess_pipelines.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

constexpr uint32_t kMaxTechniqueBuffers =  // bindings 1..7 (compute_surface.glsl)
    layout::kBindingComputeSurfaces - layout::kBindingFirstTechnique;
constexpr uint32_t kGroup = 64;                   // compute_surface.glsl's local_size_x
constexpr uint64_t kDrawCommandOffsetBytes = 16;  // compute_path_prepare.comp words 4..8
// Pipeline statistics the draw's query counts, in the order Vulkan returns them.
constexpr VkQueryPipelineStatisticFlags kDrawStatistics =
    VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT;

// SPIR-V opcodes and decorations the stride lookup reads.
constexpr uint32_t kOpTypeRuntimeArray = 29, kOpTypeStruct = 30, kOpTypePointer = 32,
                   kOpVariable = 59, kOpDecorate = 71;
constexpr uint32_t kDecorationArrayStride = 6, kDecorationBinding = 33;

// Bytes per patch of the surface struct: the ArrayStride of the runtime array in the
// block at set 0, binding `binding` of the compute shader (compute_surface.glsl's
// tb_surfaces), so the host needs no copy of each technique's struct layout.
uint32_t surfaceStrideBytes(std::span<const uint32_t> spirv, uint32_t binding,
                            const std::string& shader) {
  std::vector<uint32_t> stride_of, bound;  // by id
  std::vector<std::vector<uint32_t>> operands_of;
  operands_of.resize(spirv.size() > 3 ? spirv[3] : 0);
  stride_of.resize(operands_of.size(), 0);
  for (size_t i = 5; i < spirv.size();) {
    const uint32_t count = spirv[i] >> 16, op = spirv[i] & 0xffffu;
    if (count == 0 || i + count > spirv.size()) break;
    const uint32_t* w = &spirv[i];
    if (op == kOpDecorate && count >= 4 && w[2] == kDecorationArrayStride) stride_of[w[1]] = w[3];
    if (op == kOpDecorate && count >= 4 && w[2] == kDecorationBinding && w[3] == binding) {
      bound.push_back(w[1]);
    }
    if (op == kOpTypeRuntimeArray || op == kOpTypeStruct) {
      operands_of[w[1]].assign(w + 1, w + count);
    } else if (op == kOpTypePointer && count >= 4) {
      operands_of[w[1]] = {w[1], w[3]};
    } else if (op == kOpVariable && count >= 4) {
      operands_of[w[2]] = {w[2], w[1]};  // variable -> its pointer type
    }
    i += count;
  }
  auto operands = [&](uint32_t id) -> const std::vector<uint32_t>& {
    static const std::vector<uint32_t> kNone;
    return id < operands_of.size() ? operands_of[id] : kNone;
  };
  for (uint32_t variable : bound) {
    const auto& var = operands(variable);                                // (variable, pointer type)
    const auto& pointer = operands(var.size() >= 2 ? var[1] : 0);        // (pointer, pointee)
    const auto& block = operands(pointer.size() >= 2 ? pointer[1] : 0);  // (struct, members...)
    if (block.size() >= 2 && block[1] < stride_of.size() && stride_of[block[1]] > 0) {
      return stride_of[block[1]];
    }
  }
  throw GpuError("compute path: " + shader + " has no runtime array at set 0, binding " +
                 std::to_string(binding) + " (include shaders/common/compute_surface.glsl)");
}

GpuComputeBuffer namedBuffer(uint32_t binding, const std::string& name, uint64_t size_bytes) {
  GpuComputeBuffer b;
  b.binding = binding;
  b.name = name;
  b.size_bytes = std::max<uint64_t>(size_bytes, 16);
  return b;
}

void checkProgram(const GpuPatchProgram& program, size_t level_count) {
  const std::string name = program.evaluation_shader;
  if (program.compute_shader.empty()) {
    throw GpuError("compute path: program " + name + " names no compute shader");
  }
  if (program.displacement) {
    throw GpuError("compute path: program " + name +
                   " is displaced; the compute path does not displace yet (run it on the "
                   "hardware path)");
  }
  if (program.storage_buffers.size() > kMaxTechniqueBuffers) {
    throw GpuError("compute path: program " + name + " has " +
                   std::to_string(program.storage_buffers.size()) +
                   " storage buffers, over the compute path's 7");
  }
  if (level_count != program.patch_count) {
    throw GpuError("compute path: " + std::to_string(level_count) + " levels for " +
                   std::to_string(program.patch_count) + " patches");
  }
}

}  // namespace

// The draw's pipeline, made once per Context (llvmpipe compiles a pipeline in about 0.1 s):
// vertex pulling from the records, triangle lists, zero attachments under rasterizer
// discard, so the draw is counted and nothing is written.
struct ComputePathDrawPipeline {
  explicit ComputePathDrawPipeline(Context& context) {
    const VkDevice device = context.device();
    const VkShaderStageFlags stages[] = {VK_SHADER_STAGE_VERTEX_BIT};
    set_layout = createStorageBufferSetLayout(device, stages);
    layout = createPipelineLayout(device, set_layout.get(), 0, 0);
    const VkShaderModuleOwner vertex =
        createShaderModule(device, requireEmbeddedShader("gpu/compute_path_draw.vert"));
    const VkPipelineShaderStageCreateInfo shader_stages[] = {
        shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex.get())};
    const auto rendering =
        vkStruct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
    GraphicsPipelineBase base(shader_stages, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, layout.get(),
                              &rendering);
    base.raster.rasterizerDiscardEnable = VK_TRUE;
    pipeline = base.create(device, "vkCreateGraphicsPipelines (compute path draw)");
  }

  VkDescriptorSetLayoutOwner set_layout;
  VkPipelineLayoutOwner layout;
  VkPipelineOwner pipeline;
};

struct ComputePath::Impl {
  Impl(Context& ctx, const GpuPatchProgram& prog) : context(ctx), program(prog) {}

  Context& context;
  GpuPatchProgram program;
  uint64_t point_capacity = 0, index_capacity = 0;
  std::unique_ptr<ComputeRunner> runner;
  bool draw = false;
  bool statistics = false;
  const ComputePathDrawPipeline* draw_pipeline = nullptr;  // the Context's
  StorageBufferSet draw_set;
  VkQueryPoolOwner queries;
  double submit_to_fence_s = 0;

  std::vector<GpuComputePass> surfacePasses(const ComputePathOptions& options) const {
    const std::span<const uint32_t> spirv = requireEmbeddedShader(program.compute_shader);
    const uint32_t stride =
        surfaceStrideBytes(spirv, layout::kBindingComputeSurfaces, program.compute_shader);
    std::vector<GpuComputeBuffer> buffers;
    for (size_t b = 0; b < program.storage_buffers.size(); ++b) {
      const uint32_t binding = layout::kBindingFirstTechnique + uint32_t(b);
      GpuComputeBuffer buffer = namedBuffer(binding, "technique_" + std::to_string(binding),
                                            4 * program.storage_buffers[b].size());
      buffer.initial_words = program.storage_buffers[b];
      buffers.push_back(std::move(buffer));
    }
    using namespace layout;
    buffers.push_back(
        namedBuffer(kBindingComputeSurfaces, "surfaces", uint64_t(stride) * program.patch_count));
    buffers.push_back(namedBuffer(kBindingComputeTessOffsets, "offsets", 0));
    buffers.push_back(namedBuffer(kBindingComputeTessStatus, "status", 16));
    buffers.push_back(namedBuffer(kBindingComputeTessPoints, "points", 0));
    buffers.push_back(
        namedBuffer(kBindingComputeVertices, "vertices", 4 * kCaptureRecordWords * point_capacity));
    GpuComputePass build;
    build.shader = program.compute_shader;
    build.buffers = buffers;
    build.specialization = program.specialization;
    build.push_constants = {0, program.patch_count, options.control};
    build.groups_x = std::max<uint32_t>(1, (program.patch_count + kGroup - 1) / kGroup);
    GpuComputePass evaluate = build;
    evaluate.push_constants[0] = 1;
    evaluate.indirect_buffer = "indirect";  // the prepare pass's dispatch (words 0..2)
    return {build, evaluate};
  }

  void buildDraw() {
    const VkDevice device = context.device();
    draw_pipeline = &context.attachment<ComputePathDrawPipeline>();
    draw_set = StorageBufferSet(device, draw_pipeline->set_layout.get(), 1);
    const VkBuffer vertices[] = {runner->bufferHandle("vertices")};
    draw_set.bind(device, vertices);
    if (!statistics) return;
    auto info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    info.queryCount = 1;
    info.pipelineStatistics = kDrawStatistics;
    VkQueryPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateQueryPool(device, &info, nullptr, &pool), "vkCreateQueryPool (compute path)");
    queries = VkQueryPoolOwner(device, pool);
  }

  void recordDraw(VkCommandBuffer cmd) const {
    const VkQueryPool pool = queries.get();
    if (pool) vkCmdResetQueryPool(cmd, pool, 0, 1);
    beginDiscardRendering(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_pipeline->pipeline.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_pipeline->layout.get(), 0, 1,
                            &draw_set.set, 0, nullptr);
    vkCmdBindIndexBuffer(cmd, runner->bufferHandle("indices"), 0, VK_INDEX_TYPE_UINT32);
    if (pool) vkCmdBeginQuery(cmd, pool, 0, 0);
    vkCmdDrawIndexedIndirect(cmd, runner->bufferHandle("indirect"), kDrawCommandOffsetBytes, 1, 0);
    if (pool) vkCmdEndQuery(cmd, pool, 0);
    vkCmdEndRendering(cmd);
  }
};

ComputePath::ComputePath(Context& context, const GpuPatchProgram& program,
                         std::span<const tess::Levels> patch_levels,
                         const ComputePathOptions& options)
    : impl_(std::make_unique<Impl>(context, program)) {
  checkProgram(program, patch_levels.size());
  std::vector<TessPatch> patches(patch_levels.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    patches[p].domain = program.domain;
    patches[p].spacing = options.spacing;
    patches[p].levels = patch_levels[p];
  }
  ComputeTessellationPasses tess = describeTessellationPasses(context, patches);
  impl_->point_capacity = tess.point_capacity;
  impl_->index_capacity = tess.index_capacity;
  GpuComputePass prepare;
  prepare.shader = "gpu/compute_path_prepare.comp";
  prepare.buffers = {namedBuffer(0, "status", 16), namedBuffer(1, "indirect", 64)};
  std::vector<GpuComputePass> passes = std::move(tess.passes);
  passes.push_back(prepare);
  if (program.patch_count > 0) {
    for (GpuComputePass& pass : impl_->surfacePasses(options)) passes.push_back(std::move(pass));
  }
  impl_->runner = std::make_unique<ComputeRunner>(
      context, std::vector<GpuComputeProgram>{{"compute_path", std::move(passes)}});
  const DeviceFeatures& features = context.features();
  impl_->draw = options.draw && program.domain != tess::Domain::kIsoline;
  impl_->statistics = features.pipeline_statistics_query;
  if (impl_->draw) {
    DeviceFeatures wanted;
    wanted.dynamic_rendering = true;
    context.requireFeatures(wanted, "compute path draw");
    impl_->buildDraw();
  }
}

ComputePath::~ComputePath() = default;

double ComputePath::run() {
  Impl& impl = *impl_;
  std::function<void(VkCommandBuffer)> draw;
  if (impl.draw) draw = [&impl](VkCommandBuffer cmd) { impl.recordDraw(cmd); };
  impl.submit_to_fence_s = impl.runner->run(1, draw).submit_to_fence_s;
  return impl.submit_to_fence_s;
}

ComputePathResult ComputePath::read() const {
  const Impl& impl = *impl_;
  const std::vector<uint32_t> status = impl.runner->read("status");
  if (status[2] != 0) {
    throw GpuError("compute path: the tessellator raised error bits " + std::to_string(status[2]));
  }
  ComputePathResult out;
  out.points = status[0];
  out.index_words = status[1];
  out.vertex_buffer_bytes = 4 * kCaptureRecordWords * std::max<uint64_t>(impl.point_capacity, 4);
  out.index_buffer_bytes = 4 * std::max<uint64_t>(impl.index_capacity, 4);
  out.submit_to_fence_s = impl.submit_to_fence_s;
  if (impl.program.patch_count > 0 && out.points > 0) {
    const std::vector<uint32_t> words =
        impl.runner->read("vertices", 0, uint64_t(kCaptureRecordWords) * out.points);
    appendCaptureRecords(words, impl.program.patch_ids, &out.vertices);
    sortUniqueVertices(&out.vertices);
  }
  if (const VkQueryPool pool = impl.queries.get(); pool && impl.draw) {
    uint64_t values[2] = {0, 0};
    vkCheck(
        vkGetQueryPoolResults(impl.context.device(), pool, 0, 1, sizeof(values), values,
                              sizeof(values), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults (compute path)");
    out.draw_counted = true;
    out.drawn_triangles = values[0];
    out.drawn_vertices = values[1];
  }
  return out;
}

ComputePathResult runComputePath(Context& context, const GpuPatchProgram& program,
                                 std::span<const tess::Levels> patch_levels,
                                 const ComputePathOptions& options) {
  ComputePath path(context, program, patch_levels, options);
  path.run();
  return path.read();
}

ComputePathResult runComputePath(Context& context, const GpuPatchProgram& program,
                                 const tess::Levels& levels, const ComputePathOptions& options) {
  const std::vector<tess::Levels> patch_levels(program.patch_count, levels);
  return runComputePath(context, program, patch_levels, options);
}

}  // namespace tb::gpu
