#version 460
// ACC evaluation: the geometry patch in the variant's Bézier order and the normal from the
// tangent patches built by acc.tesc (acc_evaluate.glsl, shared with the compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "bezier.glsl"

layout(quads, equal_spacing, ccw) in;
#include "acc_surface.glsl"

layout(location = 0) in vec3 b_in[];
layout(location = 3) patch in vec3 tu_in[12];
layout(location = 15) patch in vec3 tv_in[12];

#define TB_TESS_COORD gl_TessCoord
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "acc_evaluate.glsl"
