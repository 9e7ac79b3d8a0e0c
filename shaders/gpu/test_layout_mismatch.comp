#version 460
// LayoutSelfTest's control: TbCullParamsBlock (layout/cull_layout.h) with one field added on
// the GLSL side only; the test's SPIR-V comparison must reject it.
layout(local_size_x = 1) in;

layout(std430, set = 0, binding = 4) buffer TbCullParamsBlock {
  vec4 planes[6];
  vec4 eye;
  float global_margin;
  float glsl_only_field;  // the mismatch
  uint policy;
  uint pad0;
  uint pad1;
  vec4 chord_factors;
} tb_cull;

void main() { tb_cull.policy = uint(tb_cull.global_margin + tb_cull.glsl_only_field); }
