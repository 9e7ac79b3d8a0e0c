#version 460
// Test program for the ISA measure (tests/measures/isa_test.cpp): a bicubic Bézier patch
// whose 16 control points the TES reads from storage buffer 1, in three builds chosen by
// specialisation constant 0 (kMode). 0, the twin: the patch evaluated once. 1, more work:
// a second patch (the next 16 points) evaluated too, at (v, 1 - u), the two averaged (its
// own loads: the same points would be loaded once and hide the second evaluation's work). 2, many live values: 32
// vec4 loads summed, then each used again after the sum is known, so all 32 are live at once
// (no scheduler can shorten that without reloading them).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(quads, equal_spacing, ccw) in;
layout(constant_id = 0) const uint kMode = 0u;
layout(std430, set = 0, binding = 1) readonly buffer Corners { vec4 corners[]; };
layout(location = 0) in vec3 corner[];

vec4 bernstein(float t) {
  const float s = 1.0 - t;
  return vec4(s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t);
}

vec3 bicubic(uint base, vec2 uv) {
  const vec4 bu = bernstein(uv.x), bv = bernstein(uv.y);
  vec3 p = vec3(0.0);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) p += corners[base + uint(j * 4 + i)].xyz * (bu[i] * bv[j]);
  }
  return p;
}

void main() {
  const vec2 uv = gl_TessCoord.xy;
  const uint base = tbPatchIndex() * 16u;
  vec3 position = bicubic(base, uv);
  if (kMode == 1u) position = 0.5 * (position + bicubic(base + 16u, vec2(uv.y, 1.0 - uv.x)));
  if (kMode == 2u) {
    vec4 held[32];
    for (int i = 0; i < 32; ++i) held[i] = corners[base + uint(i)] * (uv.x + float(i));
    vec4 total = vec4(0.0);
    for (int i = 0; i < 32; ++i) total += held[i];
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 32; ++i) sum = sum * total + held[31 - i] * held[i];
    position += sum.xyz;
  }
  tbEmitVertex(position, vec3(0.0, 0.0, 1.0));
}
