#version 460
// Counting probe, never drawn: the geometry patch's position alone, in the Bézier order
// of specialisation constant 0, so harness/measures/seed_figures_measure.cpp can set
// seed 000's four evaluation orders (60 / 105 / 75 / 69 instructions there) beside ours
// with nothing else in the stage. Same inputs and code as acc.tese.
#extension GL_GOOGLE_include_directive : require
#include "bezier.glsl"

layout(quads, equal_spacing, ccw) in;
layout(constant_id = 0) const uint kOrder = 2u;

layout(location = 0) in vec3 b_in[];

void main() {
  vec3 b[16];
  for (int i = 0; i < 16; ++i) b[i] = b_in[i];
  gl_Position = vec4((kOrder == kTbBezierSymmetricNoFmaImprecise ? tbEvaluateBicubicImprecise(b, gl_TessCoord.xy) : tbEvaluateBicubic(b, gl_TessCoord.xy, kOrder)), 1.0);
}
