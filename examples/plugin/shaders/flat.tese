#version 460
// `flat` TES: tbEvaluateFlatSurface (flat_surface.glsl, shared with flat.comp) at
// gl_TessCoord.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "flat_surface.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) patch in vec3 tb_flat_p[3];
layout(location = 3) patch in vec3 tb_flat_n[3];

void main() {
  vec3 position, normal;
  tbEvaluateFlatSurface(TbFlatSurface(tb_flat_p, tb_flat_n), gl_TessCoord, position, normal);
  tbEmitVertex(position, normal);
}
