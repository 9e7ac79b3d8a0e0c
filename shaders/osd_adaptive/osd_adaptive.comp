#version 460
// osd_adaptive on the compute path: osd_adaptive.tese's body (osd_adaptive_evaluate.glsl)
// run by shaders/common/compute_surface.glsl. The TCS hands the TES nothing but the base
// face, whose Far patches the body reads itself.
#extension GL_GOOGLE_include_directive : require
#include "compute_surface_stage.glsl"
#include "osd_adaptive_surface.glsl"

struct TbOsdSurface {
  uint face;
};

#define TB_EVALUATE_FUNCTION tbEvaluateOsd(vec3 tb_tess_coord)
#define TB_TESS_COORD tb_tess_coord
#include "osd_adaptive_evaluate.glsl"

#define TB_SURFACE TbOsdSurface
#define TB_BUILD_SURFACE() TbOsdSurface(tbPatchIndex())
#define TB_EVALUATE_SURFACE(s, coord) tbEvaluateOsd(coord)
#include "compute_surface.glsl"
