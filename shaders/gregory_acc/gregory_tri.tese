#version 460
// gregory_acc TES for triangles: tbEvaluateGregoryTriangle (gregory_tri_surface.glsl,
// shared with the compute path) at gl_TessCoord.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "gregory_tri_surface.glsl"

layout(triangles, equal_spacing, ccw) in;
layout(location = 0) in vec3 control_point[];

void main() {
  TbGregoryTriSurface s;
  for (int i = 0; i < 15; ++i) s.cp[i] = control_point[i];
  vec3 position, normal;
  tbEvaluateGregoryTriangle(s, gl_TessCoord, position, normal);
  tbEmitVertex(position, normal);
}
