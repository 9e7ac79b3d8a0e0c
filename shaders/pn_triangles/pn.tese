#version 460
// Curved PN triangles at gl_TessCoord (pn_evaluate.glsl, shared with the compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "pn_surface.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) patch in vec3 tb_pn_b[10];
layout(location = 10) patch in vec3 tb_pn_n[6];
layout(location = 16) patch in uvec3 tb_pn_perm;

#define TB_TESS_COORD gl_TessCoord
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "pn_evaluate.glsl"
