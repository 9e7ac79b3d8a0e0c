#version 460
// ACC on the compute path: acc.tesc's and acc.tese's bodies (acc_point.glsl,
// acc_tangent_patches.glsl, acc_evaluate.glsl) run by shaders/common/compute_surface.glsl;
// one build invocation runs the 16 control-point invocations' work in turn, then
// invocation 0's.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#include "bezier.glsl"
#define TB_SURFACE_BUILD
#include "acc_surface.glsl"

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

void tbEvaluateAcc(TbAccSurface s, vec3 tb_tess_coord) {
  const vec3 b_in[16] = s.b, tu_in[12] = s.tu, tv_in[12] = s.tv;
#define TB_TESS_COORD tb_tess_coord
#include "acc_evaluate.glsl"
#undef TB_TESS_COORD
}

#define TB_SURFACE TbAccSurface
#define TB_BUILD_SURFACE() tbBuildAcc()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluateAcc(s, coord)
#include "compute_surface.glsl"
