#version 460
// osd_adaptive TCS: nothing per control point. The TES reads the base face's Far patches
// from the storage buffers itself (a base face holds several patches of different kinds),
// so this stage only writes the harness's levels.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"

layout(vertices = 1) out;

void main() {
  if (gl_InvocationID == 0) tbWriteHarnessLevels();
}
