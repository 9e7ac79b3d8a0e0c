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
#include "acc_compute_build.glsl"

#define TB_EVALUATE_FUNCTION tbEvaluateAcc(TbAccSurface s, vec3 tb_tess_coord)
#define TB_EVALUATE_PROLOGUE const vec3 b_in[16] = s.b, tu_in[12] = s.tu, tv_in[12] = s.tv;
#define TB_TESS_COORD tb_tess_coord
#include "acc_evaluate.glsl"

#define TB_SURFACE TbAccSurface
#define TB_BUILD_SURFACE() tbBuildAcc()
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluateAcc(s, coord)
#include "compute_surface.glsl"
