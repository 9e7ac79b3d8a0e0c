#version 460
// One Jacobi iteration (jacobi, jacobi_chebyshev): every vertex gathers the corrections of
// its springs from the old positions (seed 003's compute version: vertex-centred, one
// dispatch per iteration) and moves by omega / n_v times their sum. With kChebyshev the
// result is blended with the iterate before the previous one by Wang's weight for this
// iteration (SIGGRAPH Asia 2015): x_{k+1} = x_{k-1} + w_k (y - x_{k-1}), written over
// x_{k-1}. Operation order: techniques/mass_spring/spring_solvers.h (gather()).
#extension GL_GOOGLE_include_directive : require
#include "springs.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kChebyshev = 0;
// 1: seed 003's shared-memory tiling: the workgroup's 64 consecutive vertices are copied to
// shared memory once, and a gather reads a neighbour inside the tile from there (the same
// values, so the result is bitwise the untiled one).
layout(constant_id = 1) const uint kTiled = 1;
shared vec3 tile[64];

#include "mass_spring_layout.h"  // Spring, End, Binding, Blast
layout(std430, set = 0, binding = 0) readonly buffer PositionsIn { vec4 x_in[]; };
// Plain Jacobi: the output. Chebyshev: x_{k-1} in, x_{k+1} out (each thread its own vertex).
layout(std430, set = 0, binding = 1) buffer PositionsOut { vec4 x_out[]; };
layout(std430, set = 0, binding = 2) readonly buffer Anchors { vec4 anchors[]; };
layout(std430, set = 0, binding = 3) readonly buffer EndStart { uint end_start[]; };
layout(std430, set = 0, binding = 4) readonly buffer Ends { End ends[]; };
layout(std430, set = 0, binding = 5) readonly buffer Scale { float vertex_scale[]; };
layout(std430, set = 0, binding = 6) readonly buffer Weights { float chebyshev_weight[]; };

layout(push_constant) uniform Params {
  uint vertex_count;
  uint weight_count;  // entries of chebyshev_weight; later iterations take the last
  uint iteration;     // 0-based, written by the runner each step (step_index_word)
} params;

vec3 positionIn(uint o) {
  const uint base = gl_WorkGroupID.x * 64u;
  if (kTiled != 0u && o >= base && o < base + 64u) return tile[o - base];
  return x_in[o].xyz;
}

void main() {
  const uint v = gl_GlobalInvocationID.x;
  if (kTiled != 0u) {
    if (v < params.vertex_count) tile[gl_LocalInvocationID.x] = x_in[v].xyz;
    barrier();
  }
  if (v >= params.vertex_count) return;
  const vec3 self = x_in[v].xyz;
  precise float sx = 0.0, sy = 0.0, sz = 0.0;
  for (uint e = end_start[v]; e < end_start[v + 1u]; ++e) {
    const End end = ends[e];
    const vec3 other = (end.other & kAnchorBit) != 0u ? anchors[end.other & ~kAnchorBit].xyz
                                                       : positionIn(end.other);
    const vec3 c = springCorrection(self, other, end.rest, end.weight);
    sx = sx + c.x;
    sy = sy + c.y;
    sz = sz + c.z;
  }
  const float s = vertex_scale[v];
  precise vec3 y = vec3(self.x + s * sx, self.y + s * sy, self.z + s * sz);
  if (kChebyshev != 0u) {
    const float w = chebyshev_weight[min(params.iteration, params.weight_count - 1u)];
    const vec3 p = x_out[v].xyz;
    precise vec3 next = vec3(p.x + w * (y.x - p.x), p.y + w * (y.y - p.y), p.z + w * (y.z - p.z));
    x_out[v] = vec4(next, 0.0);
  } else {
    x_out[v] = vec4(y, 0.0);
  }
}
