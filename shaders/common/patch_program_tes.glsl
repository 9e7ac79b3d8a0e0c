// TES helpers of the patch-program contract (see patch_program.glsl).
#ifndef TB_PATCH_PROGRAM_TES_GLSL
#define TB_PATCH_PROGRAM_TES_GLSL

#include "patch_program.glsl"

// 10 words per vertex: patch, gl_TessCoord bits (3), position (3), normal (3).
const uint kTbCaptureWords = 10u;

layout(std430, set = 0, binding = 0) buffer TbCapture {
  uint count;     // vertices written (atomic); may exceed capacity on overflow
  uint capacity;  // vertices that fit in words[]
  uint reserved0;
  uint reserved1;
  uint words[];
} tb_capture;

// Ends every technique's TES: sets gl_Position and, unless capture is off, appends
// (patch, gl_TessCoord, position, normal) to the capture buffer.
void tbEmitVertex(vec3 position, vec3 normal) {
  gl_Position = vec4(position, 1.0);
  if (tb_push.capture_enabled == 0u) return;
  const uint slot = atomicAdd(tb_capture.count, 1u);
  if (slot >= tb_capture.capacity) return;  // the host sees count > capacity
  const uint base = slot * kTbCaptureWords;
  tb_capture.words[base + 0u] = tbPatchIndex();
  tb_capture.words[base + 1u] = floatBitsToUint(gl_TessCoord.x);
  tb_capture.words[base + 2u] = floatBitsToUint(gl_TessCoord.y);
  tb_capture.words[base + 3u] = floatBitsToUint(gl_TessCoord.z);
  tb_capture.words[base + 4u] = floatBitsToUint(position.x);
  tb_capture.words[base + 5u] = floatBitsToUint(position.y);
  tb_capture.words[base + 6u] = floatBitsToUint(position.z);
  tb_capture.words[base + 7u] = floatBitsToUint(normal.x);
  tb_capture.words[base + 8u] = floatBitsToUint(normal.y);
  tb_capture.words[base + 9u] = floatBitsToUint(normal.z);
}

#endif
