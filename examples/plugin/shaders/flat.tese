#version 460
// `flat` TES: linear interpolation at gl_TessCoord, in the operation order of
// flat_technique.cpp evaluateLinear (the float twin the crack measure compares against).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "float_order.glsl"

layout(triangles, equal_spacing, ccw) in;

layout(location = 0) patch in vec3 tb_flat_p[3];
layout(location = 3) patch in vec3 tb_flat_n[3];

void main() {
  const vec3 w = gl_TessCoord;
  precise vec3 position = tb_flat_p[0] * w.x + tb_flat_p[1] * w.y + tb_flat_p[2] * w.z;
  precise vec3 normal_sum = tb_flat_n[0] * w.x + tb_flat_n[1] * w.y + tb_flat_n[2] * w.z;
  tbEmitVertex(position, tbNormalize(normal_sum));
}
