#version 460
// Test program for the crack measure: the bilinear patch of test_bilinear.tese evaluated
// naively as a corner plus scaled differences, p0 + (p1 - p0) u. Two patches running a
// shared edge in opposite directions then compute p0 + (p1 - p0) t and p1 + (p0 - p1)(1 - t),
// which differ by an ulp at many t: the measure must see those cracks. `precise` keeps
// the operation order, so the CPU model (tests/measures/cracks_test.cpp) matches bitwise.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(quads, equal_spacing, ccw) in;
layout(location = 0) in vec3 corner[];

void main() {
  const float u = gl_TessCoord.x, v = gl_TessCoord.y;
  precise vec3 bottom = corner[0] + (corner[1] - corner[0]) * u;
  precise vec3 top = corner[3] + (corner[2] - corner[3]) * u;
  precise vec3 position = bottom + (top - bottom) * v;
  tbEmitVertex(position, vec3(0.0, 0.0, 1.0));
}
