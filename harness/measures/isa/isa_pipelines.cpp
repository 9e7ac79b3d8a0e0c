#include "harness/measures/isa/isa_pipelines.h"

#include <algorithm>
#include <memory>
#include <utility>

#include "core/gpu/compute_runner.h"
#include "harness/lod/cull_policy.h"
#include "shaders/common/layout/bindings.h"
#include "shaders/embedded_shaders.h"

namespace tb::measures::isa {
namespace {

constexpr uint32_t kCullPolicyFixed = 100;     // kTbCullPolicyFixed in shaders/common/cull.glsl
constexpr uint32_t kComputePathPushWords = 3;  // pass, patch count, control (compute_path.cpp)

// The program with its buffers' contents dropped: only their count shapes the layout.
gpu::GpuPatchProgram shapeOf(const gpu::GpuPatchProgram& program) {
  gpu::GpuPatchProgram shape;
  shape.control_shader = program.control_shader;
  shape.evaluation_shader = program.evaluation_shader;
  shape.compute_shader = program.compute_shader;
  shape.domain = program.domain;
  shape.input_vertices_per_patch = program.input_vertices_per_patch;
  shape.storage_buffers.resize(program.storage_buffers.size());
  shape.specialization = program.specialization;
  return shape;
}

NamedPipeline tessBuild(std::string name, const gpu::GpuPatchProgram& shape,
                        const std::string& program, gpu::ProgramBuild build) {
  NamedPipeline p{
      std::move(name), program, shape.control_shader + " + " + shape.evaluation_shader, {}};
  p.request.program = shape;
  p.request.build = build;
  return p;
}

// The compute path's pass `which` ("build" or "evaluate"), as the instructions measure
// counts it: the embedded "<shader>#<which>" build, its buffers at the compute path's
// bindings.
NamedPipeline computeBuild(const gpu::GpuPatchProgram& shape, const std::string& program,
                           const std::string& which) {
  NamedPipeline p{"compute_" + which, program, shape.compute_shader + "#" + which, {}};
  p.request.kind = PipelineRequest::Kind::kComputePass;
  p.request.pass.shader = shape.compute_shader + "#" + which;
  p.request.pass.specialization = shape.specialization;
  p.request.pass.push_constants.assign(kComputePathPushWords, 0u);
  const uint32_t bindings = std::max<uint32_t>(
      gpu::layout::kBindingComputeVertices + 1,
      gpu::layout::kBindingFirstTechnique + uint32_t(shape.storage_buffers.size()));
  for (uint32_t b = 0; b < bindings; ++b) p.request.pass.buffers.push_back({.binding = b});
  return p;
}

}  // namespace

std::vector<NamedPipeline> surfacePipelines(const techniques::SurfacePatches& patches, bool full) {
  std::vector<NamedPipeline> out;
  const std::vector<gpu::GpuPatchProgram> programs = patches.gpuPrograms();
  for (const gpu::GpuPatchProgram& source : programs) {
    const gpu::GpuPatchProgram shape = shapeOf(source);
    const std::string program =
        programs.size() > 1 ? (shape.domain == tess::Domain::kQuad ? "quad" : "triangle") : "";
    const tess::Spacing spacing = tess::Spacing::kInteger;
    out.push_back(tessBuild("tessellator", shape, program, {spacing, 0, 0, 0}));
    if (full) {
      out.push_back(tessBuild("factor_policy", shape, program, {spacing, 0, 1, 0}));
      out.push_back(tessBuild("cull_policy", shape, program, {spacing, 0, 0, 1}));
      for (const lod::CullPolicy policy : lod::allCullPolicies()) {
        if (policy == lod::CullPolicy::kNone) continue;
        out.push_back(tessBuild("cull_policy/" + std::string(lod::cullPolicyName(policy)), shape,
                                program, {spacing, 0, 0, kCullPolicyFixed + uint32_t(policy)}));
      }
    }
    if (full && !gpu::embeddedShader(shape.evaluation_shader + "#displaced").empty()) {
      gpu::GpuPatchProgram displaced = shape;
      displaced.evaluation_shader += "#displaced";
      auto map = std::make_shared<gpu::GpuDisplacement>();
      map->kind = 1;      // a scalar map
      map->sampling = 1;  // watertight
      displaced.displacement = std::move(map);
      out.push_back(tessBuild("displaced", displaced, program, {spacing, 0, 0, 0}));
    }
    if (!shape.compute_shader.empty() &&
        !gpu::embeddedShader(shape.compute_shader + "#build").empty()) {
      out.push_back(computeBuild(shape, program, "build"));
      out.push_back(computeBuild(shape, program, "evaluate"));
    }
  }
  return out;
}

std::vector<NamedPipeline> simulationPipelines(const techniques::Simulation& simulation) {
  std::vector<NamedPipeline> out;
  for (const gpu::GpuComputeProgram& program : simulation.gpuPrograms()) {
    for (const gpu::GpuComputePass& pass : program.passes) {
      NamedPipeline p{program.name + "/" + pass.shader, "", pass.shader, {}};
      p.request.kind = PipelineRequest::Kind::kComputePass;
      p.request.pass.shader = pass.shader;
      p.request.pass.specialization = pass.specialization;
      p.request.pass.push_constants.assign(pass.push_constants.size(), 0u);
      for (uint32_t b = 0; b < gpu::bindingCountOf(pass); ++b) {
        p.request.pass.buffers.push_back({.binding = b});
      }
      out.push_back(std::move(p));
    }
  }
  return out;
}

}  // namespace tb::measures::isa
