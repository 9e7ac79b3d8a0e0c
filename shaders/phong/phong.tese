#version 460
// Phong tessellation at gl_TessCoord (phong_evaluate.glsl, shared with the compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#define TB_SURFACE_EVALUATE
#include "phong_surface.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) patch in vec3 tb_phong_p[3];
layout(location = 3) patch in vec3 tb_phong_n[3];
layout(location = 6) patch in vec3 tb_phong_edge_n[6];
layout(location = 12) patch in uvec3 tb_phong_perm;

#define TB_TESS_COORD gl_TessCoord
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "phong_evaluate.glsl"
