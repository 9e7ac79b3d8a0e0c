#version 460
// Counting probe, never drawn: the geometry patch's position alone, in the Bézier order
// of specialisation constant 0, so harness/measures/seed_figures_measure.cpp can set
// seed 000's four evaluation orders (60 / 105 / 75 / 69 instructions there) beside ours
// with nothing else in the stage. Same inputs and code as acc.tese; its compute twin is
// bezier_position.comp.
#extension GL_GOOGLE_include_directive : require
#include "bezier.glsl"

layout(quads, equal_spacing, ccw) in;
layout(constant_id = 0) const uint kOrder = 2u;

layout(location = 0) in vec3 b_in[];

#define TB_TESS_COORD gl_TessCoord
#define TB_CLIP_POSITION gl_Position
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "bezier_position_evaluate.glsl"
