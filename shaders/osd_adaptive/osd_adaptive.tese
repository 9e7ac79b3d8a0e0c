#version 460
// osd_adaptive TES: OpenSubdiv Far's feature-adaptive patches of one base face at
// gl_TessCoord (osd_adaptive_surface.glsl, osd_adaptive_evaluate.glsl: shared with the
// compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"

layout(quads, equal_spacing, ccw) in;

#include "osd_adaptive_surface.glsl"

#define TB_TESS_COORD gl_TessCoord
#define TB_EVALUATE_FUNCTION main()  // the body is main's
#include "osd_adaptive_evaluate.glsl"
