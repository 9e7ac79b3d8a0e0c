// The "isa" measure: what real GPU compilers make of every pipeline the suite builds. Each
// technique × variant's pipelines (isa_pipelines.h) are compiled by RADV's null device for
// five AMD generations (one worker process per family, common/isa/isa_compilers.h) and,
// when the run's device exposes VK_KHR_pipeline_executable_properties, by that device's
// own driver; one row per pipeline executable as the driver names it.
#include <exception>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpu/pipeline_executables.h"
#include "harness/measures/common/instruction_counts/instructions.h"
#include "harness/measures/common/isa/isa_assembly.h"
#include "harness/measures/common/isa/isa_compilers.h"
#include "harness/measures/isa/isa_pipelines.h"
#include "harness/measures/isa/isa_statistics.h"
#include "harness/measures/measure.h"

namespace tb::measures {
namespace {

using Keys = std::map<std::string, std::string>;

// The harness's specialisation constants (shaders/common/patch_program.glsl, displace.glsl).
constexpr uint32_t kFactorPolicyId = 201, kCullPolicyId = 202;
constexpr uint32_t kDisplaceKindId = 203, kDisplaceSamplingId = 204, kDisplaceTriangleId = 205;
constexpr VkShaderStageFlags kPatchProgramStages = VK_SHADER_STAGE_VERTEX_BIT |
                                                   VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
                                                   VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;

// The file the executable's assembly goes to under the run folder's isa/.
std::string assemblyFileName(const MeasureInput& input, const isa::NamedPipeline& pipeline,
                             const std::string& family, const std::string& executable) {
  std::string program = pipeline.pipeline;
  if (!pipeline.program.empty()) program += "-" + pipeline.program;
  return isa::safeFileName(input.technique.info().id + "--" + input.variant.name + "--" + program +
                           "--" + family + "--" + executable) +
         ".s";
}

void keepAssemblyOf(const MeasureInput& input, const isa::NamedPipeline& pipeline,
                    const std::string& family, const std::string& driver,
                    const gpu::PipelineExecutable& executable) {
  for (const gpu::ExecutableRepresentation& ir : executable.representations) {
    if (ir.name != "Assembly" || ir.text.empty()) continue;
    const std::string header = "; " + input.technique.info().id + "/" + input.variant.name + " " +
                               pipeline.pipeline + " (" + pipeline.shaders + ")\n; " + family +
                               ", " + driver + ": " + executable.name + "\n";
    isa::keepAssembly(assemblyFileName(input, pipeline, family, executable.name), header + ir.text);
  }
}

Keys pipelineKeys(const isa::NamedPipeline& pipeline, const std::string& family) {
  Keys keys{{"pipeline", pipeline.pipeline}, {"family", family}};
  if (!pipeline.program.empty()) keys["program"] = pipeline.program;
  return keys;
}

// The SPIR-V instructions (after spirv-opt -O, vector total) of the stages `stages` of the
// pipeline, each specialised as the pipeline builds it; nullopt when a stage is not known.
std::optional<double> spirvInstructions(const isa::NamedPipeline& pipeline,
                                        VkShaderStageFlags stages) {
  const isa::PipelineRequest& r = pipeline.request;
  double total = 0;
  auto add = [&](const std::string& shader, const std::vector<uint32_t>& specialization,
                 const SpecConstantsById& by_id) {
    total += double(cachedEmbeddedShaderCounts(shader, specialization, by_id).vector.total());
  };
  try {
    if (r.kind == isa::PipelineRequest::Kind::kComputePass) {
      if (stages != VK_SHADER_STAGE_COMPUTE_BIT) return std::nullopt;
      add(r.pass.shader, r.pass.specialization, {});
      return total;
    }
    if (stages & ~VkShaderStageFlags(kPatchProgramStages)) return std::nullopt;
    if (stages & VK_SHADER_STAGE_VERTEX_BIT) add("gpu/tess_patch.vert", {}, {});
    SpecConstantsById tcs;
    if (r.build.factor_policy != 0) tcs.push_back({kFactorPolicyId, r.build.factor_policy});
    if (r.build.cull_policy != 0) tcs.push_back({kCullPolicyId, r.build.cull_policy});
    if (stages & VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT) {
      add(r.program.control_shader, r.program.specialization, tcs);
    }
    if (stages & VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT) {
      SpecConstantsById tes;
      if (r.program.displacement) {
        tes = {{kDisplaceKindId, r.program.displacement->kind},
               {kDisplaceSamplingId, r.program.displacement->sampling},
               {kDisplaceTriangleId, r.program.domain == tess::Domain::kTriangle ? 1u : 0u}};
      }
      add(r.program.evaluation_shader, r.program.specialization, tes);
    }
  } catch (const std::exception&) {
    return std::nullopt;  // the instructions measure reports the failure itself
  }
  return total;
}

void addOutcome(const MeasureInput& input, const isa::NamedPipeline& pipeline, Keys keys,
                const isa::CompileOutcome& outcome, const std::string& family,
                results::MeasureResult* result) {
  if (!outcome.error.empty()) {
    result->rows.push_back(
        results::unmeasuredRow(std::move(keys), results::MeasureStatus::kFailed, outcome.error));
    return;
  }
  for (const gpu::PipelineExecutable& executable : outcome.executables) {
    keepAssemblyOf(input, pipeline, family, keys["driver"], executable);
    const std::optional<double> spirv = spirvInstructions(pipeline, executable.stages);
    for (results::MetricRow& row : isa::executableRows(keys, executable, spirv)) {
      result->rows.push_back(std::move(row));
    }
  }
}

// The RADV null device's rows for one family.
void familyRows(const MeasureInput& input, const std::vector<isa::NamedPipeline>& pipelines,
                const std::string& family, results::MeasureResult* result) {
  for (const isa::NamedPipeline& pipeline : pipelines) {
    const isa::FamilyCompile compiled = isa::compileOn(family, pipeline.request);
    Keys keys = pipelineKeys(pipeline, family);
    if (!compiled.outcome) {
      result->rows.push_back(results::unmeasuredRow(
          std::move(keys), results::MeasureStatus::kSkipped, compiled.unavailable));
      continue;
    }
    keys["driver"] = compiled.driver;
    addOutcome(input, pipeline, std::move(keys), *compiled.outcome, family, result);
  }
}

// The run's own device, compiled in this process.
void deviceRows(const MeasureInput& input, const std::vector<isa::NamedPipeline>& pipelines,
                results::MeasureResult* result) {
  std::string unavailable;
  if (input.gpu == nullptr) {
    unavailable = "no Vulkan device (" + input.gpu_unavailable + ")";
  } else if (!input.gpu->features().pipeline_executable_info) {
    unavailable = input.gpu->info().device_name + " has no VK_KHR_pipeline_executable_properties";
  }
  if (!unavailable.empty()) {
    result->rows.push_back(results::unmeasuredRow({{"family", "device"}},
                                                  results::MeasureStatus::kSkipped, unavailable));
    return;
  }
  const gpu::DeviceInfo& info = input.gpu->info();
  for (const isa::NamedPipeline& pipeline : pipelines) {
    Keys keys = pipelineKeys(pipeline, "device");
    keys["device"] = info.device_name;
    keys["driver"] = info.driver_name + " " + info.driver_info;
    isa::CompileOutcome outcome;
    try {
      const isa::PipelineRequest& r = pipeline.request;
      outcome.executables =
          r.kind == isa::PipelineRequest::Kind::kPatchProgram
              ? gpu::patchProgramExecutables(input.gpu->device(), r.program, r.build, true)
              : gpu::computePassExecutables(input.gpu->device(), r.pass, true);
    } catch (const std::exception& error) {
      outcome.error = error.what();
    }
    addOutcome(input, pipeline, std::move(keys), outcome, "device", result);
  }
}

// Pipelines named once: a simulation repeats a pass (the same shader, the same
// specialisation) within a step; a name reused for another build gets "#2", "#3".
std::vector<isa::NamedPipeline> distinct(std::vector<isa::NamedPipeline> pipelines) {
  std::vector<isa::NamedPipeline> out;
  std::set<std::string> seen;
  std::map<std::string, int> uses;
  for (isa::NamedPipeline& p : pipelines) {
    const std::string key = p.pipeline + "|" + p.program + "|" + isa::toLine(p.request);
    if (!seen.insert(key).second) continue;
    if (const int n = ++uses[p.pipeline + "|" + p.program]; n > 1) {
      p.pipeline += "#" + std::to_string(n);
    }
    out.push_back(std::move(p));
  }
  return out;
}

// report.md's "On real GPU compilers" tables: per technique (default variant, the harness's
// levels), the evaluation shader's and the control stage's executable on each family, with
// the SPIR-V count of the stages it runs beside them.
std::vector<results::ComparisonSpec> comparisons() {
  std::vector<results::ComparisonSpec> specs;
  const std::pair<const char*, const char*> kStages[] = {
      {"tess_evaluation",
       "evaluation shader (the TES; from navi10 an NGG primitive shader, on navi21 and gfx1100 "
       "with culling code)"},
      {"*tess_control",
       "control stage (the TCS; merged with the vertex shader from vega10, one executable)"}};
  for (const auto& [stages, stage_title] : kStages) {
    specs.push_back(
        {.title = "Machine instructions / VGPRs / subgroups per SIMD (higher is better) of the " +
                  std::string(stage_title) +
                  " on each AMD family; the SPIR-V instructions of "
                  "its stages beside them",
         .where = {{"pipeline", "tessellator"}, {"stages", stages}},
         .column_key = "family",
         .metric = "instructions",
         .extra_columns = {{"SPIR-V", "spirv_instructions"}},
         .facets = {},
         .ignore_keys = {"executable", "stages", "driver", "device"},
         .cell_metrics = {"vgprs", "subgroups_per_simd"}});
  }
  return specs;
}

class IsaMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "isa",
        .title = "On real GPU compilers",
        .description =
            "what the driver's compiler makes of each pipeline: registers, spills, occupancy, "
            "machine instructions and ACO's latency and throughput estimates per executable, "
            "for five AMD generations (RADV's null device) and the run's own device",
        .metrics = isa::statisticSpecs(),
        .headline = {"instructions", "vgprs", "subgroups_per_simd", "inverse_throughput"},
        .notes =
            {"RADV null device: VK_ICD_FILENAMES names the radeon ICD and RADV_FORCE_FAMILY the "
             "family (polaris10 GCN4, vega10 GCN5, navi10 RDNA1, navi21 RDNA2, gfx1100 RDNA3; "
             "--suite full adds raven and gfx1103_r1); ACO compiles each pipeline with "
             "VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR and nothing is executed; one worker "
             "process per family (tessbench-isa-worker), each distinct pipeline compiled once "
             "per family per run",
             "executables follow the hardware: polaris10 runs the vertex, tessellation-control "
             "and evaluation shaders apart; vega10 and later merge vertex + tessellation "
             "control into one (the HS); from navi10 the evaluation shader runs as an NGG "
             "primitive shader (navi21 and gfx1100 add NGG culling code)",
             "latency and inverse_throughput are ACO's static estimates (aco_statistics.cpp): "
             "one wave's cycles alone, and a wave64's busy cycles on a SIMD; subgroups_per_simd "
             "is modelled from the registers and ignores the tessellation stages' LDS; the null "
             "device's GFX11 tables are partly placeholders; figures move between Mesa versions "
             "(the driver key names it)",
             "pipeline: tessellator (the harness's levels, integer spacing), compute_build and "
             "compute_evaluate (the compute path's passes, as the instructions measure counts "
             "them), simulations' <program>/<shader> per compute pass; --suite full adds "
             "factor_policy (kTbFactorPolicy = 1: the TCS computes its levels), cull_policy "
             "(kTbCullPolicy = 1: the TCS culls by the policy its parameters name), "
             "cull_policy/<policy> (each policy fixed at compile time) and displaced (the "
             "#displaced TES, a scalar map, watertight sampling)",
             "measured once per technique × variant (the default variant in the default suite, "
             "every variant in --suite full: a compile costs 0.1 to 0.5 s per family), on its "
             "first supported input of the run "
             "(the pipelines do not depend on the asset); each executable's assembly is "
             "written to the run folder's isa/ (technique--variant--pipeline--family--"
             "executable.s); family device: the run's own Vulkan device, when it exposes "
             "VK_KHR_pipeline_executable_properties (its statistics by its own names; those "
             "this table does not know are rows keyed by statistic, figure in statistic_value)"},
        .summary_scope = {{"family", "navi21"}, {"pipeline", "tessellator"}},
        .comparisons = comparisons(),
        .shader_db = {.group_key = "family",
                      .ignore_keys = {"driver", "device"},
                      .metrics = {"instructions", "vgprs", "sgprs", "spilled_vgprs",
                                  "spilled_sgprs", "subgroups_per_simd", "latency",
                                  "inverse_throughput", "code_size"}},
    };
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    // A compile costs 0.1 to 0.5 s per family (ACO on the null device): the default suite
    // compiles the default variants' pipelines of the harness's levels and the compute path,
    // the full suite every variant's every build.
    MeasureRequirements r{{MeasureNeed::kSurfaceOrSimulation, MeasureNeed::kGpu},
                          VariantPolicy::kEveryVariantInFullSuite,
                          {}};
    r.first_input_only = true;
    return r;
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    const bool full = input.suite == SuiteMode::kFull;
    std::vector<isa::NamedPipeline> pipelines;
    if (input.patches != nullptr) {
      pipelines = isa::surfacePipelines(*input.patches, full);
    } else if (input.simulation != nullptr) {
      pipelines = isa::simulationPipelines(*input.simulation);
    }
    pipelines = distinct(std::move(pipelines));
    for (isa::NamedPipeline& p : pipelines) {
      p.request.representations = true;
      isa::attachPluginShaders(&p.request);
    }
    if (pipelines.empty()) {
      result.rows.push_back(results::unmeasuredRow({}, results::MeasureStatus::kSkipped,
                                                   "the technique builds no GPU pipeline"));
      return result;
    }
    for (const isa::Family& family : full ? isa::fullSuiteFamilies() : isa::defaultFamilies()) {
      familyRows(input, pipelines, std::string(family.name), &result);
    }
    deviceRows(input, pipelines, &result);
    return result;
  }
};

TB_REGISTER_MEASURE(IsaMeasure);

}  // namespace
}  // namespace tb::measures
