// TCS helpers of the patch-program contract (see patch_program.glsl).
#ifndef TB_PATCH_PROGRAM_TCS_GLSL
#define TB_PATCH_PROGRAM_TCS_GLSL

#include "patch_program.glsl"

// One patch's levels as float bits, written by the CPU (runPatchProgram's per-patch
// levels; uniform levels are the same entry for every patch). 32 bytes per patch.
struct TbPatchLevels {
  uvec4 outer_bits;  // gl_TessLevelOuter[0..3]
  uvec4 inner_bits;  // gl_TessLevelInner[0..1] in .xy; .zw unused
};

layout(std430, set = 1, binding = 0) readonly buffer TbLevels {
  TbPatchLevels tb_patch_levels[];
};

// Writes the levels the harness gave this patch (tbPatchIndex()), bit for bit. Call from
// one invocation. A factor policy computed in the TCS (shaders/common/tess_factors.glsl,
// a later issue) takes this helper's place; this is the path whose levels the CPU twin
// writes.
void tbWriteHarnessLevels() {
  const TbPatchLevels levels = tb_patch_levels[tbPatchIndex()];
  gl_TessLevelOuter[0] = uintBitsToFloat(levels.outer_bits.x);
  gl_TessLevelOuter[1] = uintBitsToFloat(levels.outer_bits.y);
  gl_TessLevelOuter[2] = uintBitsToFloat(levels.outer_bits.z);
  gl_TessLevelOuter[3] = uintBitsToFloat(levels.outer_bits.w);
  gl_TessLevelInner[0] = uintBitsToFloat(levels.inner_bits.x);
  gl_TessLevelInner[1] = uintBitsToFloat(levels.inner_bits.y);
}

#endif
