// acc.tesc's work for one patch on the compute path, shared by acc.comp and
// bezier_position.comp: the 16 control-point invocations' bodies (acc_point.glsl) in turn,
// then invocation 0's (acc_tangent_patches.glsl). Include after acc_surface.glsl with
// TB_SURFACE_BUILD.
#ifndef TB_ACC_COMPUTE_BUILD_GLSL
#define TB_ACC_COMPUTE_BUILD_GLSL

// What acc.tesc hands acc.tese.
struct TbAccSurface {
  vec3 b[16];
  vec3 tu[12];
  vec3 tv[12];
};

TbAccSurface tbBuildAcc() {
  vec3 b_out[16], tangent_next_out[16], tangent_prev_out[16], tu_out[12], tv_out[12];
  for (uint tb_point = 0u; tb_point < 16u; ++tb_point) {
    tangent_next_out[tb_point] = vec3(0.0);
    tangent_prev_out[tb_point] = vec3(0.0);
#define TB_INVOCATION tb_point
#include "acc_point.glsl"
#undef TB_INVOCATION
  }
#include "acc_tangent_patches.glsl"
  return TbAccSurface(b_out, tu_out, tv_out);
}

#endif
