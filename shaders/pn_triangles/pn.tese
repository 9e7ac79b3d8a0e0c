#version 460
// Curved PN triangles' TES: tbEvaluatePnSurface (pn_surface.glsl, shared with the compute
// path) at gl_TessCoord.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "pn_surface.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) patch in vec3 tb_pn_b[10];
layout(location = 10) patch in vec3 tb_pn_n[6];
layout(location = 16) patch in uvec3 tb_pn_perm;

void main() {
  vec3 position, normal;
  tbEvaluatePnSurface(TbPnSurface(tb_pn_b, tb_pn_n, tb_pn_perm), gl_TessCoord, position, normal);
  tbEmitVertex(position, normal);
}
