#version 460
// Phong tessellation's TCS: one invocation builds the patch's TbPhongSurface
// (phong_surface.glsl, shared with the compute path) and hands it to the TES.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#define TB_SURFACE_BUILD
#include "phong_surface.glsl"

layout(vertices = 1) out;

layout(location = 0) patch out vec3 tb_phong_p[3];
layout(location = 3) patch out vec3 tb_phong_n[3];
layout(location = 6) patch out vec3 tb_phong_edge_n[6];
layout(location = 12) patch out uvec3 tb_phong_perm;

void main() {
  const TbPhongSurface s = tbBuildPhongSurface(tbPatchIndex());
  tb_phong_p = s.p;
  tb_phong_n = s.n;
  tb_phong_edge_n = s.edge_n;
  tb_phong_perm = s.perm;
  tbWriteHarnessLevels();
}
