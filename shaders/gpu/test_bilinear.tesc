#version 460
// Test program for core/gpu/patch_program.h: copies the patch's four corners from
// storage buffer 1 (4 vec4 per patch) to the TES.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"

layout(vertices = 4) out;
layout(std430, set = 0, binding = 1) readonly buffer Corners { vec4 corners[]; };
layout(location = 0) out vec3 corner[];

void main() {
  corner[gl_InvocationID] = corners[tbPatchIndex() * 4u + uint(gl_InvocationID)].xyz;
  if (gl_InvocationID == 0) tbWriteHarnessLevels();
}
