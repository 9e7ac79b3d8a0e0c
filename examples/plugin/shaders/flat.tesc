#version 460
// `flat` TCS: builds the patch's TbFlatSurface (flat_surface.glsl, shared with flat.comp) for
// the TES and writes the levels the harness asks for (patch_program_tcs.glsl).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#define TB_SURFACE_BUILD
#include "flat_surface.glsl"

layout(vertices = 1) out;

layout(location = 0) patch out vec3 tb_flat_p[3];
layout(location = 3) patch out vec3 tb_flat_n[3];

void main() {
  const TbFlatSurface s = tbBuildFlatSurface(tbPatchIndex());
  tb_flat_p = s.p;
  tb_flat_n = s.n;
  tbWriteHarnessLevels();
}
