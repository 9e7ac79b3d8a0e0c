#version 460
// `flat` TCS: loads the triangle's three corners (positions and normals by index) for the
// TES and writes the levels the harness asks for (patch_program_tcs.glsl).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"

layout(vertices = 1) out;

layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer Normals { vec4 normals[]; };
// 6 words per patch: position index (3), normal index (3), in the face's corner order.
layout(std430, set = 0, binding = 3) readonly buffer Corners { uint corners[]; };

layout(location = 0) patch out vec3 tb_flat_p[3];
layout(location = 3) patch out vec3 tb_flat_n[3];

void main() {
  const uint base = tbPatchIndex() * 6u;
  for (uint i = 0u; i < 3u; ++i) {
    tb_flat_p[i] = positions[corners[base + i]].xyz;
    tb_flat_n[i] = normals[corners[base + 3u + i]].xyz;
  }
  tbWriteHarnessLevels();
}
