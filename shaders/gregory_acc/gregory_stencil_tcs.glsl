// The gregory_acc TCS body shared by the quad (20 points) and triangle (15 points)
// programs: one invocation per Gregory control point (gregory_stencil.glsl, shared with the
// compute path). Define TB_GREGORY_POINTS before including.
#ifndef TB_GREGORY_STENCIL_TCS_GLSL
#define TB_GREGORY_STENCIL_TCS_GLSL

#include "patch_program_tcs.glsl"
#include "gregory_stencil.glsl"

layout(vertices = TB_GREGORY_POINTS) out;
layout(location = 0) out vec3 control_point[];

void main() {
  control_point[gl_InvocationID] = tbGregoryControlPoint(
      tbPatchIndex(), uint(gl_InvocationID), uint(TB_GREGORY_POINTS));
  if (gl_InvocationID == 0) tbWriteHarnessLevels();
}

#endif
