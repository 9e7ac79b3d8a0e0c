#version 460
// ACC control points (acc_surface.glsl, acc_point.glsl, acc_tangent_patches.glsl: shared
// with the compute path). One invocation per geometry control point reads its corner
// vertex's 1-ring from the storage buffers, so any valence up to acc::kMaxValence works; the
// four corner-point invocations also compute their corner's limit tangents, and invocation
// 0 then builds the two tangent patches from the geometry points and those tangents.
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

#define TB_INVOCATION gl_InvocationID
void main() {
#include "acc_point.glsl"
  barrier();
  if (j != 0u) return;
  tbWriteHarnessLevels();
#include "acc_tangent_patches.glsl"
}
