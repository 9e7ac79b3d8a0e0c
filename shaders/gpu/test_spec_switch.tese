#version 460
// Test program for the instruction measure: specialisation constant 0 switches a
// normalisation on, so a count made after freezing the constants differs per variant.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(quads, equal_spacing, ccw) in;
layout(constant_id = 0) const uint kNormalize = 0u;
layout(location = 0) in vec3 corner[];

void main() {
  const float u = gl_TessCoord.x, v = gl_TessCoord.y;
  vec3 position = mix(mix(corner[0], corner[1], u), mix(corner[3], corner[2], u), v);
  if (kNormalize != 0u) position = normalize(position);
  tbEmitVertex(position, vec3(0.0, 0.0, 1.0));
}
