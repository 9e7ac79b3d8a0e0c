#version 460
// ACC control points (acc_surface.glsl, shared with the compute path): one invocation per
// geometry control point (tbAccPoint), so any valence up to acc::kMaxValence works; the
// four corner-point invocations also compute their corner's limit tangents, and
// invocation 0 then builds the two tangent patches (tbAccTangentPatches).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#define TB_SURFACE_BUILD
#include "acc_surface.glsl"

layout(vertices = 16) out;

layout(location = 0) out vec3 b_out[];
// Limit tangents of the corner owning this point along its next and previous edge
// (written by the four corner-point invocations only; read by invocation 0).
layout(location = 1) out vec3 tangent_next_out[];
layout(location = 2) out vec3 tangent_prev_out[];
layout(location = 3) patch out vec3 tu_out[12];
layout(location = 15) patch out vec3 tv_out[12];

void main() {
  const uint j = uint(gl_InvocationID);
  vec3 point, tangent_next, tangent_prev;
  tbAccPoint(tbPatchIndex(), j, point, tangent_next, tangent_prev);
  b_out[gl_InvocationID] = point;
  tangent_next_out[gl_InvocationID] = tangent_next;
  tangent_prev_out[gl_InvocationID] = tangent_prev;
  barrier();
  if (j != 0u) return;
  tbWriteHarnessLevels();
  vec3 b[16], next[16], prev[16];
  for (int i = 0; i < 16; ++i) {
    b[i] = b_out[i];
    next[i] = tangent_next_out[i];
    prev[i] = tangent_prev_out[i];
  }
  vec3 tu[12], tv[12];
  tbAccTangentPatches(tbPatchIndex(), b, next, prev, tu, tv);
  tu_out = tu;
  tv_out = tv;
}
