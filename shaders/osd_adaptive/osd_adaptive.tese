#version 460
// osd_adaptive TES: tbEvaluateOsdSurface (osd_adaptive_surface.glsl, shared with the
// compute path) at gl_TessCoord for this base face.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "osd_adaptive_surface.glsl"

layout(quads, equal_spacing, ccw) in;

void main() {
  vec3 position, normal;
  tbEvaluateOsdSurface(tbBuildOsdSurface(tbPatchIndex()), gl_TessCoord, position, normal);
  tbEmitVertex(position, normal);
}
