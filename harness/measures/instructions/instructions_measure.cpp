// The "instructions" measure: static SPIR-V counts per stage and exact scalar operation
// counts per vertex and per patch set-up, in one table with one set of columns.
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "harness/measures/common/instruction_counts/instructions.h"
#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "shaders/embedded_shaders.h"

namespace tb::measures {
namespace {

// Fewer instructions is better for every category; best case 0 (an empty stage).
const MetricTable<InstructionCounts>& countTable() {
  using C = InstructionCounts;
  constexpr results::Direction kLower = results::Direction::kLowerIsBetter;
  static const MetricTable<C> kTable{
      // add: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst); OpFAdd,
      //   OpFSub
      {"add", results::Unit::kCount, kLower, &C::add},
      // mul: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst); float
      //   multiplies
      {"mul", results::Unit::kCount, kLower, &C::mul},
      // div: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst); OpFDiv,
      //   OpFRem, OpFMod
      {"div", results::Unit::kCount, kLower, &C::div},
      // sqrt: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst); Sqrt,
      //   InverseSqrt
      {"sqrt", results::Unit::kCount, kLower, &C::sqrt},
      // compare: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   float comparisons
      {"compare", results::Unit::kCount, kLower, &C::compare},
      // float_other: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   OpDot, OpFNegate, other float functions
      {"float_other", results::Unit::kCount, kLower, &C::float_other},
      // float_arith: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   add + mul + div + sqrt + compare + float_other
      {"float_arith", results::Unit::kCount, kLower,
       [](const C& c) { return double(c.floatArithmetic()); }},
      // fma: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   GLSL.std.450 Fma
      {"fma", results::Unit::kCount, kLower, &C::fma},
      // load_store: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   loads, stores, atomics
      {"load_store", results::Unit::kCount, kLower, &C::load_store},
      // control_flow: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   branches, switch, return, kill, calls
      {"control_flow", results::Unit::kCount, kLower, &C::control_flow},
      // other: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst);
      //   integer, conversion, composite, access chain, phi
      {"other", results::Unit::kCount, kLower, &C::other},
      // total: count of SPIR-V instructions after spirv-opt -O; 0 (best), unbounded (worst); every
      //   category
      {"total", results::Unit::kCount, kLower, [](const C& c) { return double(c.total()); }},
  };
  return kTable;
}

InstructionCounts fromOperations(const techniques::OperationCounts& o) {
  InstructionCounts c;
  c.add = o.add;
  c.mul = o.mul;
  c.div = o.div;
  c.sqrt = o.sqrt;
  c.compare = o.compare;
  return c;
}

bool mixesDomains(const techniques::SurfacePatches& patches) {
  for (size_t p = 1; p < patches.patchCount(); ++p) {
    if (patches.patchDomain(p) != patches.patchDomain(0)) return true;
  }
  return false;
}

class InstructionsMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "instructions",
        .title = "Instruction counts",
        .description =
            "SPIR-V instructions per stage after spirv-opt -O (vector and scalar-expanded), and "
            "exact "
            "scalar operations per vertex and per patch set-up (counting scalar)",
        .metrics = countTable().specs(),
        .headline = {"total", "float_arith"},
        .notes =
            {"spirv_O rows: each stage specialised for the variant (its specialisation constants "
             "set "
             "and frozen), then spirv-opt -O (SPIRV-Tools performance passes, Vulkan 1.3); every "
             "instruction of a function body counted once, so a loop body counts once whatever its "
             "trip count; declarations, labels, variables and merge annotations are not counted",
             "expansion scalar: an instruction counts the components of its result (vec3 add = 3, "
             "a store the stored value's, dot of n-vectors 2n-1); float_other: dot, negate and "
             "GLSL.std.450 functions other than sqrt, inversesqrt and fma",
             "counting_scalar rows: SurfacePatches::operationProfile, the technique's evaluator "
             "run "
             "with CountingScalar in the shader's operation order; min and max over the asset's "
             "patches by per-vertex total (a regular and the worst irregular patch); they count "
             "arithmetic only, so fma, float_other, load_store, control_flow and other are 0",
             "x86 instructions per TES invocation on lavapipe are not in this table (they need "
             "valgrind): bench/callgrind_tes.sh TECHNIQUE ASSET gives the callgrind slope between "
             "two levels, tessellator and TES JIT code together",
             "summaries (report, table, advise) read the evaluation-stage rows: spirv_O, vector "
             "expansion, the .tese stages (the work per tessellated vertex)",
             "path: tessellator rows count the TCS and TES; compute rows the compute path's "
             "technique shader in its two passes, each built with the pass fixed "
             "(TB_COMPUTE_PASS): stage <shader>.comp#build runs once per patch (the TCS's work), "
             "<shader>.comp#evaluate once per domain point (the TES's, plus the 40-byte record "
             "write); the compute tessellator's kernels (gpu/tessellate.comp) are the same for "
             "every technique and not listed",
             "simulations: one spirv_O row pair per compute pass of each step program (program = "
             "the program's name), specialised for the variant; a loop over walls or tree nodes "
             "counts once; no counting_scalar rows"},
        .summary_scope = {{"source", "spirv_O"}, {"expansion", "vector"}, {"stage", "*.tese"}},
        .decision_inputs = {
            {.role = results::DecisionRole::kShaderCost,
             .label = "TCS + TES instructions",
             .column = "TCS + TES instructions (count; compute path: its build + evaluate passes)",
             .metrics = {"total"},
             .where = {{"expansion", "vector"}, {"source", "spirv_O"}},
             .any_of = {{{"stage", "*.tesc"}}, {{"stage", "*.tese"}}},
             .reduce = results::DecisionReduce::kSum},
            {.role = results::DecisionRole::kShaderCost,
             .label = "build + evaluate instructions",
             .metrics = {"total"},
             .where = {{"expansion", "vector"}, {"source", "spirv_O"}},
             .any_of = {{{"stage", "*#build"}}, {{"stage", "*#evaluate"}}},
             .reduce = results::DecisionReduce::kSum,
             .path = results::kComputePath},
            {.role = results::DecisionRole::kAdviceCost,
             .label = "instructions",
             .column = "total SPIR-V instructions of the domain (.tese) stage after spirv-opt -O, "
                       "per vector instruction (count)",
             .metrics = {"total"}}}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSurfaceOrSimulation}, VariantPolicy::kEveryVariant, {}};
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    if (input.patches == nullptr) {  // a simulation: its compute passes, no counting scalar
      staticRows(input, &result);
      return result;
    }
    if (mixesDomains(*input.patches)) {
      // Only records whose patches mix quads and triangles have a program key.
      result.notes.push_back(
          "program: the patch domain (quad or triangle) when the technique's patches mix them; "
          "spirv_O rows then count each domain's GPU program, counting_scalar min and max are "
          "taken per domain");
    }
    staticRows(input, &result);
    dynamicRows(*input.patches, &result);
    return result;
  }

 private:
  // One stage list per GPU program (its domain names it when there are several), or the
  // technique's embedded shaders when it has no program.
  struct ShaderSet {
    std::string program;  // "quad" or "triangle"; empty for a single program
    std::vector<std::string> shaders;
    std::vector<uint32_t> specialization;
    // Surfaces: "tessellator" (TCS + TES) or "compute" (the compute path's passes); empty for
    // simulations.
    std::string path;
  };

  static std::vector<ShaderSet> shaderSets(const MeasureInput& input) {
    std::vector<ShaderSet> sets;
    if (input.patches == nullptr) {
      // A simulation: one set per compute pass (its own specialisation), named by program.
      if (input.simulation == nullptr) return sets;
      for (const gpu::GpuComputeProgram& program : input.simulation->gpuPrograms()) {
        for (const gpu::GpuComputePass& pass : program.passes) {
          sets.push_back({program.name, {pass.shader}, pass.specialization});
        }
      }
      return sets;
    }
    const std::vector<gpu::GpuPatchProgram> programs = input.patches->gpuPrograms();
    for (const gpu::GpuPatchProgram& program : programs) {
      const techniques::PatchDomain domain = program.domain == tess::Domain::kQuad
                                                 ? techniques::PatchDomain::kQuad
                                                 : techniques::PatchDomain::kTriangle;
      const std::string name = programs.size() > 1 ? toString(domain) : "";
      sets.push_back({name,
                      {program.control_shader, program.evaluation_shader},
                      program.specialization,
                      "tessellator"});
      // The compute path's two passes, each its own build (shaders/CMakeLists.txt): "#build"
      // once per patch (the TCS's work), "#evaluate" once per domain point (the TES's).
      const std::string build = program.compute_shader + "#build";
      if (!program.compute_shader.empty() && !gpu::embeddedShader(build).empty()) {
        sets.push_back({name,
                        {build, program.compute_shader + "#evaluate"},
                        program.specialization,
                        "compute"});
      }
    }
    if (sets.empty()) {
      ShaderSet set;
      const std::string prefix = input.technique.info().id + "/";
      for (std::string_view path : gpu::embeddedShaderPaths()) {
        if (path.starts_with(prefix)) set.shaders.emplace_back(path);
      }
      if (!set.shaders.empty()) sets.push_back(std::move(set));
    }
    return sets;
  }

  static void staticRows(const MeasureInput& input, results::MeasureResult* result) {
    const std::vector<ShaderSet> sets = shaderSets(input);
    if (sets.empty()) {
      result->rows.push_back(results::unmeasuredRow({{"source", "spirv_O"}},
                                                    results::MeasureStatus::kSkipped,
                                                    "the technique has no shaders"));
      return;
    }
    for (const ShaderSet& set : sets) {
      for (const std::string& shader : set.shaders) {
        StageInstructionCounts counts;
        try {
          counts = cachedEmbeddedShaderCounts(shader, set.specialization);
        } catch (const std::exception& error) {
          std::map<std::string, std::string> keys{{"source", "spirv_O"}, {"stage", shader}};
          if (!set.program.empty()) keys["program"] = set.program;
          if (!set.path.empty()) keys["path"] = set.path;
          result->rows.push_back(results::unmeasuredRow(
              std::move(keys), results::MeasureStatus::kFailed, error.what()));
          continue;
        }
        for (bool scalar : {false, true}) {
          results::MetricRow row;
          row.keys["source"] = "spirv_O";
          if (!set.program.empty()) row.keys["program"] = set.program;
          row.keys["stage"] = shader;
          if (!set.path.empty()) row.keys["path"] = set.path;
          row.keys["expansion"] = scalar ? "scalar" : "vector";
          row.metrics = countTable().metrics(scalar ? counts.scalar : counts.vector);
          result->rows.push_back(std::move(row));
        }
      }
    }
  }

  // The cheapest and the costliest patch by per-vertex total, per patch domain (keyed by
  // the domain when the patches mix them).
  static void dynamicRows(const techniques::SurfacePatches& patches,
                          results::MeasureResult* result) {
    struct Extremes {
      std::optional<techniques::OperationProfile> least, most;
      size_t least_patch = 0, most_patch = 0;
    };
    std::map<techniques::PatchDomain, Extremes> by_domain;
    auto cost = [](const techniques::OperationProfile& p) {
      return std::make_pair(p.per_vertex.total(), p.per_patch_setup.total());
    };
    for (size_t p = 0; p < patches.patchCount(); ++p) {
      std::optional<techniques::OperationProfile> profile = patches.operationProfile(p);
      if (!profile) break;
      Extremes& e = by_domain[patches.patchDomain(p)];
      if (!e.least || cost(*profile) < cost(*e.least)) e.least = profile, e.least_patch = p;
      if (!e.most || cost(*profile) > cost(*e.most)) e.most = profile, e.most_patch = p;
    }
    if (by_domain.empty()) {
      result->rows.push_back(results::unmeasuredRow({{"source", "counting_scalar"}},
                                                    results::MeasureStatus::kSkipped,
                                                    "the technique does not count operations"));
      return;
    }
    for (const auto& [domain, e] : by_domain) {
      for (const auto& [which, profile, patch] :
           {std::tuple{"min", *e.least, e.least_patch}, std::tuple{"max", *e.most, e.most_patch}}) {
        for (bool per_vertex : {true, false}) {
          results::MetricRow row;
          row.keys["source"] = "counting_scalar";
          if (by_domain.size() > 1) row.keys["program"] = toString(domain);
          row.keys["stage"] = per_vertex ? "per_vertex" : "per_patch_setup";
          row.keys["patch"] = std::string(which) + " (patch " + std::to_string(patch) + ")";
          if (!profile.note.empty()) row.keys["note"] = profile.note;
          row.metrics = countTable().metrics(
              fromOperations(per_vertex ? profile.per_vertex : profile.per_patch_setup));
          result->rows.push_back(std::move(row));
        }
      }
    }
  }
};

TB_REGISTER_MEASURE(InstructionsMeasure);

}  // namespace
}  // namespace tb::measures
