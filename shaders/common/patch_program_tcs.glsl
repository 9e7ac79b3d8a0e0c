// TCS helpers of the patch-program contract (see patch_program.glsl).
#ifndef TB_PATCH_PROGRAM_TCS_GLSL
#define TB_PATCH_PROGRAM_TCS_GLSL

#include "patch_program.glsl"
#include "tess_factors.glsl"

// Harness specialisation constant: 0, the levels come from the harness (set 1, binding 0);
// 1, the TCS computes them with the factor policy of tess_factors.glsl (set 1, bindings
// 1..3). Frozen at 0 where shaders are counted (the instructions measure).
layout(constant_id = 201) const uint kTbFactorPolicy = 0u;

// One patch's levels as float bits, written by the CPU (runPatchProgram's per-patch
// levels; uniform levels are the same entry for every patch). 32 bytes per patch.
struct TbPatchLevels {
  uvec4 outer_bits;  // gl_TessLevelOuter[0..3]
  uvec4 inner_bits;  // gl_TessLevelInner[0..1] in .xy; .zw unused
};

layout(std430, set = 1, binding = 0) readonly buffer TbLevels {
  TbPatchLevels tb_patch_levels[];
};

// Writes this patch's levels (tbPatchIndex()): the harness's, bit for bit, or with
// kTbFactorPolicy those of the factor policy (tess_factors.glsl). Call from one invocation.
void tbWriteHarnessLevels() {
  if (kTbFactorPolicy != 0u) {
    tbWritePolicyLevels(tbPatchIndex());
    return;
  }
  const TbPatchLevels levels = tb_patch_levels[tbPatchIndex()];
  gl_TessLevelOuter[0] = uintBitsToFloat(levels.outer_bits.x);
  gl_TessLevelOuter[1] = uintBitsToFloat(levels.outer_bits.y);
  gl_TessLevelOuter[2] = uintBitsToFloat(levels.outer_bits.z);
  gl_TessLevelOuter[3] = uintBitsToFloat(levels.outer_bits.w);
  gl_TessLevelInner[0] = uintBitsToFloat(levels.inner_bits.x);
  gl_TessLevelInner[1] = uintBitsToFloat(levels.inner_bits.y);
}

#endif
