#version 460
// Phong tessellation's TES: tbEvaluatePhongSurface (phong_surface.glsl, shared with the
// compute path) at gl_TessCoord.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "phong_surface.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) patch in vec3 tb_phong_p[3];
layout(location = 3) patch in vec3 tb_phong_n[3];
layout(location = 6) patch in vec3 tb_phong_edge_n[6];
layout(location = 12) patch in uvec3 tb_phong_perm;

void main() {
  const TbPhongSurface s = TbPhongSurface(tb_phong_p, tb_phong_n, tb_phong_edge_n, tb_phong_perm);
  vec3 position, normal;
  tbEvaluatePhongSurface(s, gl_TessCoord, position, normal);
  tbEmitVertex(position, normal);
}
