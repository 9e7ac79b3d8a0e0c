// The culling policy's blocks (cull.glsl; host: harness/lod/cull_policy_words.cpp).
#ifndef TB_LAYOUT_CULL_H
#define TB_LAYOUT_CULL_H

#include "bindings.h"
#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

const uint kTbCullHullPoints = 20u;  // hull[] capacity per patch

TB_READONLY_BUFFER(TbCullParamsBlock, TB_HARNESS_SET, TB_BINDING_CULL_PARAMS) {
  vec4 planes[6];       // world-space frustum planes, unit xyz: inside when xyz . p + w >= 0
  vec4 eye;             // xyz: camera position, world units
  float global_margin;  // frustum_lp2_global's margin, world units
  uint policy;
  uint pad0;
  uint pad1;
  vec4 chord_factors;  // tangent_plane's chord margin: quad K2, K3, triangle K2, K3
}
TB_INSTANCE(tb_cull);

struct TbCullPatch {
  vec4 corner_position[4];  // xyz: welded corner position; w: frustum_lp2_exact's margin
  vec4 corner_normal[4];    // xyz: the welded position's unit normal
  vec4 cone;                // xyz: unit axis; w: sin of the half angle, > 1 when there is no cone
  uvec4 header;             // x: corners (3 or 4), y: hull points, z: displacement bound bits
  // x: first coefficient in tb_cull_tangent_planes, y: coefficients (0: none, use the cone),
  // z: max |n_k| bits, w: max |w_k| bits
  uvec4 tangent;
  vec4 tangent_chord;            // x: the net's reach R from O, y: G1 G2, z: G2^2 (chord margin)
  vec4 hull[kTbCullHullPoints];  // xyz
};

TB_READONLY_BUFFER(TbCullPatches, TB_HARNESS_SET, TB_BINDING_CULL_PATCHES) {
  TB_RUNTIME_ARRAY(TbCullPatch, tb_cull_patches);
};

// {n_k, w_k}: world units squared and cubed.
TB_READONLY_BUFFER(TbCullTangentPlanes, TB_HARNESS_SET, TB_BINDING_CULL_TANGENT_PLANES) {
  TB_RUNTIME_ARRAY(vec4, tb_cull_tangent_planes);
};

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
static_assert(sizeof(TbCullParamsBlock) == 144 && offsetof(TbCullParamsBlock, eye) == 96);
static_assert(offsetof(TbCullParamsBlock, policy) == 116);
static_assert(offsetof(TbCullParamsBlock, chord_factors) == 128);
static_assert(sizeof(TbCullPatch) == 512 && offsetof(TbCullPatch, cone) == 128);
static_assert(offsetof(TbCullPatch, header) == 144 && offsetof(TbCullPatch, hull) == 192);
}  // namespace tb::gpu::layout
#endif

#endif
