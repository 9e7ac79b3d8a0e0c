#include "harness/measures/common/isa/isa_request.h"

#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <stdexcept>
#include <utility>

#include "core/gpu/compute_runner.h"
#include "shaders/embedded_shaders.h"

namespace tb::measures::isa {
namespace {

using nlohmann::json;

json programJson(const PipelineRequest& r) {
  const gpu::GpuPatchProgram& p = r.program;
  json j{{"control", p.control_shader},
         {"evaluation", p.evaluation_shader},
         {"domain", int(p.domain)},
         {"vertices_per_patch", p.input_vertices_per_patch},
         {"storage_buffers", p.storage_buffers.size()},
         {"specialization", p.specialization},
         {"spacing", int(r.build.spacing)},
         {"boundary", r.build.boundary},
         {"factor_policy", r.build.factor_policy},
         {"cull_policy", r.build.cull_policy}};
  if (p.displacement) {
    j["displacement"] = {{"kind", p.displacement->kind}, {"sampling", p.displacement->sampling}};
  }
  return j;
}

void readProgram(const json& j, PipelineRequest* r) {
  gpu::GpuPatchProgram& p = r->program;
  p.control_shader = j.at("control").get<std::string>();
  p.evaluation_shader = j.at("evaluation").get<std::string>();
  p.domain = tess::Domain(j.at("domain").get<int>());
  p.input_vertices_per_patch = j.at("vertices_per_patch").get<uint32_t>();
  p.storage_buffers.resize(j.at("storage_buffers").get<size_t>());
  p.specialization = j.at("specialization").get<std::vector<uint32_t>>();
  r->build.spacing = tess::Spacing(j.at("spacing").get<int>());
  r->build.boundary = j.at("boundary").get<uint32_t>();
  r->build.factor_policy = j.at("factor_policy").get<uint32_t>();
  r->build.cull_policy = j.at("cull_policy").get<uint32_t>();
  if (j.contains("displacement")) {
    auto displacement = std::make_shared<gpu::GpuDisplacement>();
    displacement->kind = j["displacement"].at("kind").get<uint32_t>();
    displacement->sampling = j["displacement"].at("sampling").get<uint32_t>();
    displacement->channels = displacement->kind == 2 ? 4 : 1;
    p.displacement = std::move(displacement);
  }
}

}  // namespace

void attachPluginShaders(PipelineRequest* request) {
  const std::vector<std::string> stages =
      request->kind == PipelineRequest::Kind::kPatchProgram
          ? std::vector<std::string>{request->program.control_shader,
                                     request->program.evaluation_shader}
          : std::vector<std::string>{request->pass.shader};
  for (const std::string& stage : stages) {
    if (!gpu::isRegisteredShader(stage)) continue;
    const std::span<const uint32_t> words = gpu::embeddedShader(stage);
    request->plugin_shaders.push_back({stage, {words.begin(), words.end()}});
  }
}

std::string toLine(const PipelineRequest& request) {
  json j{{"representations", request.representations}};
  if (!request.plugin_shaders.empty()) j["plugin_shaders"] = request.plugin_shaders;
  if (request.kind == PipelineRequest::Kind::kPatchProgram) {
    j["patch_program"] = programJson(request);
  } else {
    const gpu::GpuComputePass& pass = request.pass;
    j["compute_pass"] = {{"shader", pass.shader},
                         {"bindings", gpu::bindingCountOf(pass)},
                         {"push_words", pass.push_constants.size()},
                         {"specialization", pass.specialization}};
  }
  return j.dump();
}

PipelineRequest requestFromLine(const std::string& line) {
  PipelineRequest r;
  try {
    const json j = json::parse(line);
    r.representations = j.at("representations").get<bool>();
    if (j.contains("plugin_shaders")) {
      r.plugin_shaders =
          j["plugin_shaders"].get<std::vector<std::pair<std::string, std::vector<uint32_t>>>>();
    }
    if (j.contains("patch_program")) {
      readProgram(j["patch_program"], &r);
      return r;
    }
    const json& c = j.at("compute_pass");
    r.kind = PipelineRequest::Kind::kComputePass;
    r.pass.shader = c.at("shader").get<std::string>();
    const uint32_t bindings = c.at("bindings").get<uint32_t>();
    for (uint32_t b = 0; b < bindings; ++b) r.pass.buffers.push_back({.binding = b});
    r.pass.push_constants.assign(c.at("push_words").get<size_t>(), 0u);
    r.pass.specialization = c.at("specialization").get<std::vector<uint32_t>>();
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string("ISA request: ") + e.what());
  }
  return r;
}

std::string toLine(const CompileOutcome& outcome) {
  json executables = json::array();
  for (const gpu::PipelineExecutable& e : outcome.executables) {
    json statistics = json::array();
    for (const gpu::ExecutableStatistic& s : e.statistics) {
      statistics.push_back({s.name, s.description, s.value, s.is_float});
    }
    json representations = json::array();
    for (const gpu::ExecutableRepresentation& ir : e.representations) {
      representations.push_back({ir.name, ir.text});
    }
    executables.push_back({{"name", e.name},
                           {"description", e.description},
                           {"stages", e.stages},
                           {"subgroup_size", e.subgroup_size},
                           {"statistics", statistics},
                           {"representations", representations}});
  }
  return json{{"executables", executables}, {"error", outcome.error}}.dump();
}

CompileOutcome outcomeFromLine(const std::string& line) {
  CompileOutcome outcome;
  try {
    const json j = json::parse(line);
    outcome.error = j.at("error").get<std::string>();
    for (const json& e : j.at("executables")) {
      gpu::PipelineExecutable x;
      x.name = e.at("name").get<std::string>();
      x.description = e.at("description").get<std::string>();
      x.stages = e.at("stages").get<uint32_t>();
      x.subgroup_size = e.at("subgroup_size").get<uint32_t>();
      for (const json& s : e.at("statistics")) {
        x.statistics.push_back({s.at(0).get<std::string>(), s.at(1).get<std::string>(),
                                s.at(2).get<double>(), s.at(3).get<bool>()});
      }
      for (const json& ir : e.at("representations")) {
        x.representations.push_back({ir.at(0).get<std::string>(), ir.at(1).get<std::string>()});
      }
      outcome.executables.push_back(std::move(x));
    }
  } catch (const json::exception& e) {
    outcome.executables.clear();
    outcome.error = std::string("the ISA worker's answer is malformed: ") + e.what();
  }
  return outcome;
}

std::string toLine(const WorkerHello& hello) {
  return json{{"device", hello.device}, {"driver", hello.driver}, {"error", hello.error}}.dump();
}

WorkerHello helloFromLine(const std::string& line) {
  WorkerHello hello;
  try {
    const json j = json::parse(line);
    hello.device = j.at("device").get<std::string>();
    hello.driver = j.at("driver").get<std::string>();
    hello.error = j.at("error").get<std::string>();
  } catch (const json::exception& e) {
    hello.error = std::string("the ISA worker's first line is malformed: ") + e.what();
  }
  return hello;
}

}  // namespace tb::measures::isa
