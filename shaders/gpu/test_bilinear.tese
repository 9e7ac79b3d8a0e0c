#version 460
// Test program for core/gpu/patch_program.h: bilinear interpolation of the corners,
// scaled by specialisation constant 0 (as float bits), so the variant switch is tested too.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(quads, equal_spacing, ccw) in;
layout(constant_id = 0) const uint kScaleBits = 0x3f800000u;  // 1.0
layout(location = 0) in vec3 corner[];

void main() {
  const float u = gl_TessCoord.x, v = gl_TessCoord.y;
  precise vec3 bottom = corner[0] * (1.0 - u) + corner[1] * u;
  precise vec3 top = corner[3] * (1.0 - u) + corner[2] * u;
  precise vec3 position = (bottom * (1.0 - v) + top * v) * uintBitsToFloat(kScaleBits);
  tbEmitVertex(position, vec3(0.0, 0.0, 1.0));
}
