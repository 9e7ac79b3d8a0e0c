// TCS helpers of the patch-program contract (see patch_program.glsl).
#ifndef TB_PATCH_PROGRAM_TCS_GLSL
#define TB_PATCH_PROGRAM_TCS_GLSL

#include "patch_program.glsl"

// Writes the levels the harness pushed, bit for bit. Call from one invocation.
// Later issues replace this with the tess-factor policies in shaders/common.
void tbWriteHarnessLevels() {
  gl_TessLevelOuter[0] = uintBitsToFloat(tb_push.outer_bits.x);
  gl_TessLevelOuter[1] = uintBitsToFloat(tb_push.outer_bits.y);
  gl_TessLevelOuter[2] = uintBitsToFloat(tb_push.outer_bits.z);
  gl_TessLevelOuter[3] = uintBitsToFloat(tb_push.outer_bits.w);
  gl_TessLevelInner[0] = uintBitsToFloat(tb_push.inner_bits.x);
  gl_TessLevelInner[1] = uintBitsToFloat(tb_push.inner_bits.y);
}

#endif
