// The "instructions" measure: static SPIR-V counts per stage and exact scalar operation
// counts per vertex and per patch set-up, in one table with one set of columns.
#include <exception>
#include <map>
#include <mutex>

#include "harness/measures/instructions.h"
#include "harness/measures/measure.h"
#include "shaders/embedded_shaders.h"

namespace tb {
namespace {

std::vector<Metric> countMetrics(const InstructionCounts& c) {
  return {
      {"add", double(c.add), "count"},
      {"mul", double(c.mul), "count"},
      {"div", double(c.div), "count"},
      {"sqrt", double(c.sqrt), "count"},
      {"compare", double(c.compare), "count"},
      {"float_other", double(c.float_other), "count"},
      {"float_arith", double(c.floatArithmetic()), "count"},
      {"fma", double(c.fma), "count"},
      {"load_store", double(c.load_store), "count"},
      {"control_flow", double(c.control_flow), "count"},
      {"other", double(c.other), "count"},
      {"total", double(c.total()), "count"},
  };
}

InstructionCounts fromOperations(const OperationCounts& o) {
  InstructionCounts c;
  c.add = o.add;
  c.mul = o.mul;
  c.div = o.div;
  c.sqrt = o.sqrt;
  c.compare = o.compare;
  return c;
}

// Static counts depend only on the shader and its specialisation, not on the asset:
// optimise each once per run.
StageInstructionCounts cachedStageCounts(const std::string& shader,
                                         const std::vector<uint32_t>& specialization) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, std::vector<uint32_t>>, StageInstructionCounts> cache;
  const std::lock_guard lock(mutex);
  const auto key = std::make_pair(shader, specialization);
  auto found = cache.find(key);
  if (found == cache.end()) {
    found = cache.emplace(key, countEmbeddedShader(shader, specialization)).first;
  }
  return found->second;
}

class InstructionsMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        "instructions", "Instruction counts",
        "SPIR-V instructions per stage after spirv-opt -O (vector and scalar-expanded), and exact "
        "scalar operations per vertex and per patch set-up (counting scalar)"};
    return kInfo;
  }
  bool appliesTo(const Technique& technique) const override {
    return technique.info().family == TechniqueFamily::kSurface;
  }
  bool dependsOnVariant() const override { return true; }

  MeasureResult run(const MeasureInput& input) const override {
    MeasureResult result;
    result.measure = info().id;
    result.notes = {
        "spirv_O rows: each stage specialised for the variant (its specialisation constants set "
        "and frozen), then spirv-opt -O (SPIRV-Tools performance passes, Vulkan 1.3); every "
        "instruction of a function body counted once, so a loop body counts once whatever its "
        "trip count; declarations, labels, variables and merge annotations are not counted",
        "expansion scalar: an instruction counts the components of its result (vec3 add = 3, "
        "a store the stored value's, dot of n-vectors 2n-1); float_other: dot, negate and "
        "GLSL.std.450 functions other than sqrt, inversesqrt and fma",
        "counting_scalar rows: SurfacePatches::operationProfile, the technique's evaluator run "
        "with CountingScalar in the shader's operation order; min and max over the asset's "
        "patches by per-vertex total (a regular and the worst irregular patch); they count "
        "arithmetic only, so fma, float_other, load_store, control_flow and other are 0",
        "x86 instructions per TES invocation on lavapipe are not in this table (they need "
        "valgrind): bench/callgrind_tes.sh TECHNIQUE ASSET gives the callgrind slope between "
        "two levels, tessellator and TES JIT code together"};
    staticRows(input, &result);
    dynamicRows(*input.patches, &result);
    return result;
  }

 private:
  static void staticRows(const MeasureInput& input, MeasureResult* result) {
    std::vector<std::string> shaders;
    std::vector<uint32_t> specialization;
    if (const auto program = input.patches->gpuProgram()) {
      shaders = {program->control_shader, program->evaluation_shader};
      specialization = program->specialization;
    } else {
      const std::string prefix = input.technique.info().id + "/";
      for (std::string_view path : gpu::embeddedShaderPaths()) {
        if (path.starts_with(prefix)) shaders.emplace_back(path);
      }
    }
    if (shaders.empty()) {
      MetricRow row;
      row.keys["source"] = "spirv_O";
      row.keys["note"] = "skipped: the technique has no shaders";
      result->rows.push_back(std::move(row));
      return;
    }
    for (const std::string& shader : shaders) {
      StageInstructionCounts counts;
      try {
        counts = cachedStageCounts(shader, specialization);
      } catch (const std::exception& error) {
        MetricRow row;
        row.keys["source"] = "spirv_O";
        row.keys["stage"] = shader;
        row.keys["note"] = std::string("failed: ") + error.what();
        result->rows.push_back(std::move(row));
        continue;
      }
      for (bool scalar : {false, true}) {
        MetricRow row;
        row.keys["source"] = "spirv_O";
        row.keys["stage"] = shader;
        row.keys["expansion"] = scalar ? "scalar" : "vector";
        row.metrics = countMetrics(scalar ? counts.scalar : counts.vector);
        result->rows.push_back(std::move(row));
      }
    }
  }

  static void dynamicRows(const SurfacePatches& patches, MeasureResult* result) {
    std::optional<OperationProfile> least, most;
    size_t least_patch = 0, most_patch = 0;
    auto cost = [](const OperationProfile& p) {
      return std::make_pair(p.per_vertex.total(), p.per_patch_setup.total());
    };
    for (size_t p = 0; p < patches.patchCount(); ++p) {
      std::optional<OperationProfile> profile = patches.operationProfile(p);
      if (!profile) break;
      if (!least || cost(*profile) < cost(*least)) least = profile, least_patch = p;
      if (!most || cost(*profile) > cost(*most)) most = profile, most_patch = p;
    }
    if (!least) {
      MetricRow row;
      row.keys["source"] = "counting_scalar";
      row.keys["note"] = "skipped: the technique does not count operations";
      result->rows.push_back(std::move(row));
      return;
    }
    for (const auto& [which, profile, patch] :
         {std::tuple{"min", *least, least_patch}, std::tuple{"max", *most, most_patch}}) {
      for (bool per_vertex : {true, false}) {
        MetricRow row;
        row.keys["source"] = "counting_scalar";
        row.keys["stage"] = per_vertex ? "per_vertex" : "per_patch_setup";
        row.keys["patch"] = std::string(which) + " (patch " + std::to_string(patch) + ")";
        if (!profile.note.empty()) row.keys["note"] = profile.note;
        row.metrics =
            countMetrics(fromOperations(per_vertex ? profile.per_vertex : profile.per_patch_setup));
        result->rows.push_back(std::move(row));
      }
    }
  }
};

TB_REGISTER_MEASURE(InstructionsMeasure);

}  // namespace
}  // namespace tb
