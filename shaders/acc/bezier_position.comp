#version 460
// The compute twin of bezier_position.tese (the counting probe): acc.tesc's build
// (acc_point.glsl, acc_tangent_patches.glsl) and the probe's body
// (bezier_position_evaluate.glsl), run by shaders/common/compute_surface.glsl. It emits the
// position alone (normal 0), bit for bit acc.tese's position in the same Bézier order.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#include "bezier.glsl"
#define TB_SURFACE_BUILD
#include "acc_surface.glsl"
#include "acc_compute_build.glsl"

#define TB_EVALUATE_FUNCTION tbEvaluateBezierPosition(TbAccSurface s, vec3 tb_tess_coord)
#define TB_EVALUATE_PROLOGUE \
  const vec3 b_in[16] = s.b; \
  vec4 tb_clip_position;
#define TB_EVALUATE_EPILOGUE tbEmitVertex(tb_clip_position.xyz, vec3(0.0));
#define TB_TESS_COORD tb_tess_coord
#define TB_CLIP_POSITION tb_clip_position
#include "bezier_position_evaluate.glsl"

#define TB_SURFACE TbAccSurface
#define TB_BUILD_SURFACE() tbBuildAcc()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluateBezierPosition(s, coord)
#include "compute_surface.glsl"
