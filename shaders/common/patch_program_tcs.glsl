// TCS helpers of the patch-program contract (see patch_program.glsl).
#ifndef TB_PATCH_PROGRAM_TCS_GLSL
#define TB_PATCH_PROGRAM_TCS_GLSL

#include "patch_program.glsl"
#include "tess_factors.glsl"
#include "cull.glsl"

// Harness specialisation constant: 0, the levels come from the harness (set 1, binding 0);
// 1, the TCS computes them with the factor policy of tess_factors.glsl (set 1, bindings
// 1..3). Frozen at 0 where shaders are counted (the instructions measure).
layout(constant_id = 201) const uint kTbFactorPolicy = 0u;
// kTbCullPolicy (constant_id 202), the culling switch, is declared in cull.glsl.

#include "layout/levels_layout.h"

// Writes this patch's levels (tbPatchIndex()): the harness's, bit for bit, or with
// kTbFactorPolicy those of the factor policy (tess_factors.glsl); with kTbCullPolicy, outer
// levels 0 when the culling policy (cull.glsl) culls the patch. With either, the levels
// also go to the read-back buffer. Call from one invocation.
void tbWriteHarnessLevels() {
  const uint patch_index = tbPatchIndex();
  float outer[4];
  float inner[2];
  if (kTbFactorPolicy != 0u) {
    tbPolicyLevels(patch_index, outer, inner);
  } else {
    const TbPatchLevels levels = tb_patch_levels[patch_index];
    outer = float[4](uintBitsToFloat(levels.outer_bits.x), uintBitsToFloat(levels.outer_bits.y),
                     uintBitsToFloat(levels.outer_bits.z), uintBitsToFloat(levels.outer_bits.w));
    inner = float[2](uintBitsToFloat(levels.inner_bits.x), uintBitsToFloat(levels.inner_bits.y));
  }
  if (kTbCullPolicy != 0u && tbCullPatch(patch_index)) outer = float[4](0.0, 0.0, 0.0, 0.0);
  gl_TessLevelOuter[0] = outer[0];
  gl_TessLevelOuter[1] = outer[1];
  gl_TessLevelOuter[2] = outer[2];
  gl_TessLevelOuter[3] = outer[3];
  gl_TessLevelInner[0] = inner[0];
  gl_TessLevelInner[1] = inner[1];
  if (kTbFactorPolicy != 0u || kTbCullPolicy != 0u) tbWriteBackLevels(patch_index, outer, inner);
}

#endif
