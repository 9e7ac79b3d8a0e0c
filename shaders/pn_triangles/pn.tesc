#version 460
// Curved PN triangles' TCS: one invocation builds the patch's TbPnSurface (pn_surface.glsl,
// shared with the compute path) and hands it to the TES.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#define TB_SURFACE_BUILD
#include "pn_surface.glsl"

layout(vertices = 1) out;

layout(location = 0) patch out vec3 tb_pn_b[10];
layout(location = 10) patch out vec3 tb_pn_n[6];
layout(location = 16) patch out uvec3 tb_pn_perm;

void main() {
  const TbPnSurface s = tbBuildPnSurface(tbPatchIndex());
  tb_pn_b = s.b;
  tb_pn_n = s.n;
  tb_pn_perm = s.perm;
  tbWriteHarnessLevels();
}
