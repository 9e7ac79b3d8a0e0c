#version 460
// gregory_acc TES for triangles: the triangle Gregory patch of Loop, Schaefer, Ni & Castaño
// 2009 (cubic boundary curves shared with the neighbours, quartic interior with three
// rationally blended interior points) at gl_TessCoord, position and analytic normal
// (gregory_surface.glsl, gregory_tri_evaluate.glsl: shared with the compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(triangles, equal_spacing, ccw) in;
layout(location = 0) in vec3 control_point[];

#define TB_GREGORY_TRIANGLE
#include "gregory_surface.glsl"

#define TB_TESS_COORD gl_TessCoord
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "gregory_tri_evaluate.glsl"
