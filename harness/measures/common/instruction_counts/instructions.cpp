#include "harness/measures/common/instruction_counts/instructions.h"

#include <map>
#include <mutex>
#include <spirv-tools/optimizer.hpp>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "shaders/embedded_shaders.h"

#define SPV_ENABLE_UTILITY_CODE
#include <glslang/SPIRV/GLSL.std.450.h>

#include <glslang/SPIRV/spirv.hpp>

namespace tb::measures {
namespace {

constexpr size_t kHeaderWords = 5;  // magic, version, generator, bound, schema

struct ModuleTables {
  std::unordered_map<uint32_t, uint32_t> type_components;  // type id -> scalar components
  std::unordered_map<uint32_t, uint32_t> value_type;       // result id -> type id
  uint32_t glsl_std_450 = UINT32_MAX;                      // OpExtInstImport id
};

uint32_t componentsOfValue(const ModuleTables& t, uint32_t value) {
  const auto type = t.value_type.find(value);
  if (type == t.value_type.end()) return 1;
  const auto components = t.type_components.find(type->second);
  return components == t.type_components.end() ? 1 : components->second;
}

// Instructions that declare or annotate rather than execute.
bool isNotExecuted(spv::Op op) {
  switch (op) {
    case spv::OpFunction:
    case spv::OpFunctionParameter:
    case spv::OpFunctionEnd:
    case spv::OpLabel:
    case spv::OpVariable:
    case spv::OpLine:
    case spv::OpNoLine:
    case spv::OpNop:
    case spv::OpSelectionMerge:
    case spv::OpLoopMerge:
      return true;
    default:
      return false;
  }
}

uint64_t* categoryOf(spv::Op op, const uint32_t* inst, const ModuleTables& t,
                     InstructionCounts* c) {
  switch (op) {
    case spv::OpFAdd:
    case spv::OpFSub:
      return &c->add;
    case spv::OpFMul:
    case spv::OpVectorTimesScalar:
    case spv::OpMatrixTimesScalar:
    case spv::OpVectorTimesMatrix:
    case spv::OpMatrixTimesVector:
    case spv::OpMatrixTimesMatrix:
    case spv::OpOuterProduct:
      return &c->mul;
    case spv::OpFDiv:
    case spv::OpFRem:
    case spv::OpFMod:
      return &c->div;
    case spv::OpDot:
    case spv::OpFNegate:
      return &c->float_other;
    case spv::OpLoad:
    case spv::OpStore:
    case spv::OpCopyMemory:
    case spv::OpAtomicLoad:
    case spv::OpAtomicStore:
    case spv::OpAtomicExchange:
    case spv::OpAtomicCompareExchange:
    case spv::OpAtomicIIncrement:
    case spv::OpAtomicIDecrement:
    case spv::OpAtomicIAdd:
    case spv::OpAtomicISub:
    case spv::OpAtomicSMin:
    case spv::OpAtomicUMin:
    case spv::OpAtomicSMax:
    case spv::OpAtomicUMax:
    case spv::OpAtomicAnd:
    case spv::OpAtomicOr:
    case spv::OpAtomicXor:
      return &c->load_store;
    case spv::OpBranch:
    case spv::OpBranchConditional:
    case spv::OpSwitch:
    case spv::OpReturn:
    case spv::OpReturnValue:
    case spv::OpKill:
    case spv::OpTerminateInvocation:
    case spv::OpUnreachable:
    case spv::OpFunctionCall:
      return &c->control_flow;
    case spv::OpExtInst:
      if (inst[3] == t.glsl_std_450) {
        switch (inst[4]) {
          case GLSLstd450Fma:
            return &c->fma;
          case GLSLstd450Sqrt:
          case GLSLstd450InverseSqrt:
            return &c->sqrt;
          default:
            return &c->float_other;
        }
      }
      return &c->other;
    default:
      if (op >= spv::OpFOrdEqual && op <= spv::OpFUnordGreaterThanEqual) return &c->compare;
      return &c->other;
  }
}

}  // namespace

InstructionCounts countSpirvInstructions(std::span<const uint32_t> words, bool scalar) {
  if (words.size() < kHeaderWords || words[0] != spv::MagicNumber) {
    throw std::runtime_error("instructions: not a SPIR-V module");
  }
  ModuleTables t;
  InstructionCounts counts;
  bool in_function = false;
  for (size_t at = kHeaderWords; at < words.size();) {
    const uint32_t word_count = words[at] >> 16;
    const auto op = spv::Op(words[at] & 0xffffu);
    if (word_count == 0 || at + word_count > words.size()) {
      throw std::runtime_error("instructions: truncated SPIR-V instruction");
    }
    const uint32_t* inst = &words[at];
    at += word_count;

    bool has_result = false, has_type = false;
    spv::HasResultAndType(op, &has_result, &has_type);
    if (has_result && has_type && word_count >= 3) t.value_type[inst[2]] = inst[1];
    switch (op) {
      case spv::OpExtInstImport:
        if (std::string(reinterpret_cast<const char*>(&inst[2])) == "GLSL.std.450") {
          t.glsl_std_450 = inst[1];
        }
        continue;
      case spv::OpTypeBool:
      case spv::OpTypeInt:
      case spv::OpTypeFloat:
        t.type_components[inst[1]] = 1;
        continue;
      case spv::OpTypeVector:
      case spv::OpTypeMatrix:
        t.type_components[inst[1]] = t.type_components[inst[2]] * inst[3];
        continue;
      case spv::OpFunction:
        in_function = true;
        continue;
      case spv::OpFunctionEnd:
        in_function = false;
        continue;
      default:
        break;
    }
    if (!in_function || isNotExecuted(op)) continue;
    uint64_t weight = 1;
    if (scalar) {
      if (op == spv::OpStore) {
        weight = componentsOfValue(t, inst[2]);
      } else if (op == spv::OpDot) {
        weight = 2 * componentsOfValue(t, inst[3]) - 1;
      } else if (has_type) {
        const auto components = t.type_components.find(inst[1]);
        if (components != t.type_components.end()) weight = components->second;
      }
    }
    *categoryOf(op, inst, t, &counts) += weight;
  }
  return counts;
}

std::vector<uint32_t> optimizeSpirv(std::span<const uint32_t> words,
                                    const std::vector<uint32_t>& specialization,
                                    const SpecConstantsById& by_id) {
  spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_3);
  std::string messages;
  optimizer.SetMessageConsumer([&messages](spv_message_level_t level, const char*,
                                           const spv_position_t&, const char* message) {
    if (level <= SPV_MSG_ERROR) messages += std::string(message) + "; ";
  });
  if (!specialization.empty() || !by_id.empty()) {
    std::unordered_map<uint32_t, std::vector<uint32_t>> values;
    for (uint32_t i = 0; i < specialization.size(); ++i) values[i] = {specialization[i]};
    for (const auto& [id, value] : by_id) values[id] = {value};
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values));
  }
  // Freezing turns OpSpecConstant into OpConstant but leaves the OpSpecConstantOp built on
  // them (e.g. `kSwitch != 0u`); fold those too, so dead variant branches go away.
  optimizer.RegisterPass(spvtools::CreateFreezeSpecConstantValuePass());
  optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
  optimizer.RegisterPerformancePasses();
  std::vector<uint32_t> out;
  if (!optimizer.Run(words.data(), words.size(), &out)) {
    throw std::runtime_error("instructions: spirv-opt -O failed: " + messages);
  }
  return out;
}

StageInstructionCounts countEmbeddedShader(std::string_view embedded_path,
                                           const std::vector<uint32_t>& specialization,
                                           const SpecConstantsById& by_id) {
  const std::span<const uint32_t> words = gpu::embeddedShader(embedded_path);
  if (words.empty()) {
    throw std::runtime_error("instructions: shader " + std::string(embedded_path) +
                             " is not embedded");
  }
  const std::vector<uint32_t> optimized = optimizeSpirv(words, specialization, by_id);
  return {std::string(embedded_path), countSpirvInstructions(optimized, false),
          countSpirvInstructions(optimized, true)};
}

StageInstructionCounts cachedEmbeddedShaderCounts(const std::string& embedded_path,
                                                  const std::vector<uint32_t>& specialization,
                                                  const SpecConstantsById& by_id) {
  static std::mutex mutex;
  static std::map<std::tuple<std::string, std::vector<uint32_t>, SpecConstantsById>,
                  StageInstructionCounts>
      cache;
  const auto key = std::make_tuple(embedded_path, specialization, by_id);
  {
    const std::lock_guard lock(mutex);
    if (auto found = cache.find(key); found != cache.end()) return found->second;
  }
  // Optimised outside the lock, so two threads count different shaders at once; a shader
  // counted twice by a race gives the same counts.
  StageInstructionCounts counts = countEmbeddedShader(embedded_path, specialization, by_id);
  const std::lock_guard lock(mutex);
  return cache.emplace(key, std::move(counts)).first->second;
}

}  // namespace tb::measures
