#version 460
// The compute tessellator's count pass (kWrite = 0) and write pass (kWrite = 1), one
// invocation per patch: the D3D11/Vulkan tessellation pattern of each patch's levels, as
// core/tess's CPU model (bit-exact with lavapipe) generates it (common/tess_domains.glsl).
// The count pass stores each patch's point and index counts; tess_scan.comp turns them into
// offsets; the write pass stores the points (16.16 u, v) and indices (into the whole points
// buffer) at those offsets. Host side: core/gpu/compute_tessellator.h.
#extension GL_GOOGLE_include_directive : require

#include "layout/bindings.h"
#include "layout/tess_patch_record.h"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kWrite = 0;

// Per patch kTbTessPatchRecordWords words (layout/tess_patch_record.h TbTessPatchRecord).
layout(std430, set = 0, binding = TB_BINDING_TESS_PATCH_RECORDS) readonly buffer Patches {
  uint patch_words[];
};
// Per patch: points, index words (3 a triangle, 2 a line segment), culled (0/1), 0.
layout(std430, set = 0, binding = 1) buffer Counts { uvec4 counts[]; };
// Per patch: first point, first index word (exclusive prefix sums, tess_scan.comp).
layout(std430, set = 0, binding = 2) buffer Offsets { uvec2 offsets[]; };
// Totals over the batch and the error bits (core/gpu/compute_tessellator.h TessErrors).
layout(std430, set = 0, binding = 3) buffer Status {
  uint total_points;
  uint total_index_words;
  uint errors;
} status;
layout(std430, set = 0, binding = 4) buffer Points { uvec2 points[]; };  // 16.16 (u, v)
layout(std430, set = 0, binding = 5) buffer Indices { uint indices[]; };

layout(push_constant) uniform Params {
  uint patch_count;
  uint point_capacity;  // points the Points buffer holds
  uint index_capacity;  // words the Indices buffer holds
} params;

const uint kErrorBadCode = 1u;
const uint kErrorPointsOverflow = 2u;
const uint kErrorIndicesOverflow = 4u;
const uint kErrorCountMismatch = 8u;

uint g_point_base = 0u;
uint g_index_base = 0u;

#define TB_TESS_WRITE (kWrite != 0u)
void tbStorePoint(uint n, uint u, uint v) { points[g_point_base + n] = uvec2(u, v); }
void tbStoreIndex(uint k, uint i) { indices[g_index_base + k] = g_point_base + i; }
#include "tess_domains.glsl"

void main() {
  const uint p = gl_GlobalInvocationID.x;
  if (p >= params.patch_count) return;
  const uint code = patch_words[kTbTessPatchRecordWords * p + kTbTessPatchCode];
  const uint domain = code & 0xffu, spacing = code >> 8;
  if (domain > kTbDomainIsoline || spacing > kTbSpacingFractionalEven) {
    if (kWrite == 0u) {
      atomicOr(status.errors, kErrorBadCode);
      counts[p] = uvec4(0u, 0u, 1u, 0u);
    }
    return;
  }
  if (kWrite != 0u) {
    g_point_base = offsets[p].x;
    g_index_base = offsets[p].y;
    if (g_point_base + counts[p].x > params.point_capacity) {
      atomicOr(status.errors, kErrorPointsOverflow);
      return;
    }
    if (g_index_base + counts[p].y > params.index_capacity) {
      atomicOr(status.errors, kErrorIndicesOverflow);
      return;
    }
  }
  const uint w = kTbTessPatchRecordWords * p;
  const vec4 outer = uintBitsToFloat(
      uvec4(patch_words[w], patch_words[w + 1u], patch_words[w + 2u], patch_words[w + 3u]));
  const vec2 inner = uintBitsToFloat(uvec2(patch_words[w + kTbTessPatchInner],
                                                  patch_words[w + (kTbTessPatchInner + 1u)]));
  const uint flags = patch_words[w + kTbTessPatchFlags];
  g_tb_ccw = (flags & 1u) == 0u;
  g_tb_point_mode = (flags & 2u) != 0u;
  g_tb_rounding_up_control = (flags & 4u) != 0u;
  const bool drawn = tbTessellatePatch(domain, spacing, outer, inner);
  // The write pass must retrace the count pass (a driver that cut a loop short would not).
  const uint index_words = (domain == kTbDomainIsoline ? 2u : 3u) * g_tb_triangle_count;
  if (kWrite != 0u && (g_tb_point_count != counts[p].x || index_words != counts[p].y)) {
    atomicOr(status.errors, kErrorCountMismatch);
  }
  if (kWrite == 0u) counts[p] = uvec4(g_tb_point_count, index_words, drawn ? 0u : 1u, 0u);
}
