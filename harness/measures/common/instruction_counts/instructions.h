// Instruction counts (docs/MEASURES.md).
//  (a) static: each shader stage after spirv-opt -O (SPIRV-Tools API), specialised for
//      the variant first, counted per category, as vector instructions and expanded to
//      the components of their result;
//  (b) exact scalar operations per vertex and per patch set-up, from
//      SurfacePatches::operationProfile (CountingScalar).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tb::measures {

// Instructions of a function body by category. Float arithmetic is split like
// OperationCounts (techniques/counting_scalar.h) so the two can be set side by side.
struct InstructionCounts {
  uint64_t add = 0;           // OpFAdd, OpFSub
  uint64_t mul = 0;           // OpFMul and the vector/matrix-times-scalar/vector/matrix products
  uint64_t div = 0;           // OpFDiv, OpFRem, OpFMod
  uint64_t sqrt = 0;          // GLSL.std.450 Sqrt, InverseSqrt
  uint64_t compare = 0;       // OpFOrd*, OpFUnord*
  uint64_t float_other = 0;   // OpDot, OpFNegate and the other GLSL.std.450 float functions
  uint64_t fma = 0;           // GLSL.std.450 Fma
  uint64_t load_store = 0;    // OpLoad, OpStore, OpCopyMemory, atomics
  uint64_t control_flow = 0;  // branches, switch, return, kill, calls
  uint64_t other = 0;         // integer, conversion, composite, access chain, phi, ...
  uint64_t floatArithmetic() const { return add + mul + div + sqrt + compare + float_other; }
  uint64_t total() const { return floatArithmetic() + fma + load_store + control_flow + other; }
};

// Counts the instructions in the module's function bodies (each instruction once, so a
// loop body counts once). Declarations, labels, variables, merge annotations and debug
// lines are not instructions that execute and are not counted. `scalar`: each
// instruction counts the components of its result (a vec3 add is 3; OpDot of two
// n-vectors is 2n - 1; a store counts the stored value's components).
InstructionCounts countSpirvInstructions(std::span<const uint32_t> words, bool scalar);

// Specialisation constants by constant_id: (id, 32-bit bit pattern), e.g. the harness's
// kTbCullPolicy (202) to count one culling policy's TCS.
using SpecConstantsById = std::vector<std::pair<uint32_t, uint32_t>>;

// spirv-opt -O (RegisterPerformancePasses, Vulkan 1.3), after setting specialisation
// constant i to specialization[i] (as 32-bit bit patterns), then those of `by_id`, and
// freezing the constants. Throws std::runtime_error with the optimiser's message on failure.
std::vector<uint32_t> optimizeSpirv(std::span<const uint32_t> words,
                                    const std::vector<uint32_t>& specialization,
                                    const SpecConstantsById& by_id = {});

struct StageInstructionCounts {
  std::string shader;        // embedded path, e.g. "phong/phong.tese"
  InstructionCounts vector;  // one per SPIR-V instruction
  InstructionCounts scalar;  // expanded to result components
};

// Optimises and counts one embedded shader (shaders/embedded_shaders.h). Throws
// std::runtime_error when the shader is not embedded or does not optimise.
StageInstructionCounts countEmbeddedShader(std::string_view embedded_path,
                                           const std::vector<uint32_t>& specialization,
                                           const SpecConstantsById& by_id = {});

// The same, optimised once per (shader, specialisation) for the life of the process: the
// counts depend on neither the asset nor the variant's patch data. Thread-safe; a shader
// that throws is not cached (the next call throws again).
StageInstructionCounts cachedEmbeddedShaderCounts(const std::string& embedded_path,
                                                  const std::vector<uint32_t>& specialization,
                                                  const SpecConstantsById& by_id = {});

}  // namespace tb::measures
