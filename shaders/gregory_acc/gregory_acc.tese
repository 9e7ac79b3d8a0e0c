#version 460
// gregory_acc TES: the quad Gregory patch of Loop, Schaefer, Ni & Castaño 2009 at
// gl_TessCoord, position and analytic normal (gregory_surface.glsl,
// gregory_quad_evaluate.glsl: shared with the compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(quads, equal_spacing, ccw) in;
layout(location = 0) in vec3 control_point[];

#include "gregory_surface.glsl"

#define TB_TESS_COORD gl_TessCoord
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "gregory_quad_evaluate.glsl"
