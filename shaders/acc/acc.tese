#version 460
// ACC evaluation: tbEvaluateAcc (acc_surface.glsl, shared with the compute path) at
// gl_TessCoord, from the points and tangent patches acc.tesc built.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "acc_surface.glsl"

layout(quads, equal_spacing, ccw) in;

layout(location = 0) in vec3 b_in[];
layout(location = 3) patch in vec3 tu_in[12];
layout(location = 15) patch in vec3 tv_in[12];

void main() {
  TbAccSurface s;
  for (int i = 0; i < 16; ++i) s.b[i] = b_in[i];
  s.tu = tu_in;
  s.tv = tv_in;
  vec3 position, normal;
  tbEvaluateAcc(s, gl_TessCoord, position, normal);
  tbEmitVertex(position, normal);
}
