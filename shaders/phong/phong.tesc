#version 460
// Phong tessellation (Boubekeur & Alexa 2008): one invocation reads the triangle's corners
// by index (canonical order, see techniques/phong/phong.cpp) and normalises the normals as
// phong.cpp's evaluateFloat does; the `edge` variant also reads seed 003's per-edge normals.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#include "float_order.glsl"

layout(vertices = 1) out;

layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer Normals { vec4 normals[]; };
// 15 words per patch: label -> corner (3), position (3), normal (3), edge-end normal (6).
layout(std430, set = 0, binding = 3) readonly buffer Records { uint records[]; };

layout(location = 0) patch out vec3 tb_phong_p[3];
layout(location = 3) patch out vec3 tb_phong_n[3];
layout(location = 6) patch out vec3 tb_phong_edge_n[6];
layout(location = 12) patch out uvec3 tb_phong_perm;

void main() {
  const uint base = tbPatchIndex() * 15u;
  for (uint i = 0u; i < 3u; ++i) {
    tb_phong_p[i] = positions[records[base + 3u + i]].xyz;
    tb_phong_n[i] = tbNormalize(normals[records[base + 6u + i]].xyz);
  }
  for (uint k = 0u; k < 6u; ++k) {
    tb_phong_edge_n[k] = tbNormalize(normals[records[base + 9u + k]].xyz);
  }
  tb_phong_perm = uvec3(records[base + 0u], records[base + 1u], records[base + 2u]);
  tbWriteHarnessLevels();
}
