// TES helpers of the patch-program contract (see patch_program.glsl).
#ifndef TB_PATCH_PROGRAM_TES_GLSL
#define TB_PATCH_PROGRAM_TES_GLSL

#include "patch_program.glsl"
#ifdef TB_DISPLACEMENT
#include "displace.glsl"
#endif

// TbCapture (tb_capture) and kTbCaptureWords: the host shares them.
#include "layout/capture_layout.h"

// Harness specialisation constant (techniques use ids 0..M-1): which TES invocations are
// captured. 0: every one; 1: only those on a quad's edges; 2: only those on a triangle's
// edges (core/gpu/patch_program.h, boundary_only). Frozen at its default where shaders are
// counted (the instructions measure), so the test below folds away there.
layout(constant_id = 200) const uint kTbCaptureBoundary = 0u;

// True when gl_TessCoord lies on the patch boundary. The tessellator's coordinates are
// multiples of 2^-16, exactly 0 or 1 on an edge (quads: (u, v, 0); triangles: barycentric).
bool tbOnPatchBoundary() {
  const vec3 c = gl_TessCoord;
  if (kTbCaptureBoundary == 1u) return c.x == 0.0 || c.x == 1.0 || c.y == 0.0 || c.y == 1.0;
  return c.x == 0.0 || c.y == 0.0 || c.z == 0.0;
}

// Ends every technique's TES: sets gl_Position and, unless capture is off, appends
// (patch, gl_TessCoord, position, normal) to the capture buffer (with kTbCaptureBoundary,
// only on the patch boundary).
// In a "#displaced" build (TB_DISPLACEMENT), the position is first displaced by the map
// (displace.glsl); the normal stays the undisplaced surface's.
void tbEmitVertex(vec3 surface_position, vec3 normal) {
#ifdef TB_DISPLACEMENT
  const vec3 position = tbDisplace(surface_position);
#else
  const vec3 position = surface_position;
#endif
  gl_Position = vec4(position, 1.0);
  if (tb_push.capture_enabled == 0u) return;
  if (kTbCaptureBoundary != 0u && !tbOnPatchBoundary()) return;
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
