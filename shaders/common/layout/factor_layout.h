// The factor policy's blocks (tess_factors.glsl; host: harness/lod/factor_policy.cpp).
#ifndef TB_LAYOUT_FACTOR_H
#define TB_LAYOUT_FACTOR_H

#include "bindings.h"
#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

struct TbFactorCorner {
  vec4 position;  // xyz: welded control-mesh position, world units
  vec4 normal;    // xyz: the welded position's unit normal (the same on both sides of a seam)
};

struct TbFactorPatch {
  TbFactorCorner corner[4];  // triangles use 3
  vec4 edge_sphere[4];       // error_bound, per outer edge: xyz centre, w radius (world)
  vec4 edge_m;               // error_bound, per outer edge: sup|C''| / 8 (world)
  vec4 patch_sphere;         // error_bound: around the patch's hull
  vec4 inner_ab;             // error_bound, x: (M_uu + M_uv) / 8, y: (M_vv + M_uv) / 8 (world)
  vec4 pad;
};

TB_READONLY_BUFFER(TbFactorPatches, TB_HARNESS_SET, TB_BINDING_FACTOR_PATCHES) {
  TB_RUNTIME_ARRAY(TbFactorPatch, tb_factor_patches);
};

TB_READONLY_BUFFER(TbFactorParamsBlock, TB_HARNESS_SET, TB_BINDING_FACTOR_PARAMS) {
  mat4 view_projection;      // world -> Vulkan clip space, column-major
  vec4 eye;                  // xyz: camera position, world units
  float viewport_height_px;  // H, also lp2_edge's R
  float projection_y_scale;  // |P[1][1]|
  float target;              // the policy's parameter (see kTbPolicy*)
  float pixel_scale;         // sphere_diameter: H / (2 target)
  float min_scale;           // s_min of the silhouette and roundness reductions, (0, 1]
  float roundness_span;      // roundness: 1 - cos(angle at which an edge counts as round)
  uint policy;
  uint flags;
  uint reduction;
  uint spacing;
  uint domain;  // 0 triangle, 1 quad (tess::Domain)
  uint pad0;
  float error_scale;   // error_bound: world error per unit of clip w (target / f_px)
  float near_w;        // error_bound: the near plane's clip w
  float hull_w_scale;  // error_bound: |row 3 of view_projection, xyz|
  float pad1;
  // error_bound's projection stretch, per screen axis x, y: |row r of view_projection, xyz|,
  // 1 / |P[r][r]| (view x / w per clip x / w) and tan(fov / 2) (the view's edge).
  float row_length_x, inv_scale_x, tan_half_x, pad2;
  float row_length_y, inv_scale_y, tan_half_y, pad3;
  vec4 side_length;  // error_bound: |xyz| of the view's side planes w + x, w - x, w + y, w - y
  // error_bound only: the tessellator's transition extents for this domain and spacing
  // (harness/lod/transition_extents.h: [edge][axis][o - 1][n - 1], then each level's longest
  // edge segment).
  TB_RUNTIME_ARRAY(float, tb_transition);
}
TB_INSTANCE(tb_factor);

// The levels the TCS wrote (float bits, the TbPatchLevels layout), per patch.
TB_WRITEONLY_BUFFER(TbFactorOut, TB_HARNESS_SET, TB_BINDING_FACTOR_OUT) {
  TB_RUNTIME_ARRAY(uvec4, tb_factor_out);  // 2 per patch: outer[0..3], inner[0..1]
};

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
static_assert(sizeof(TbFactorCorner) == 32);
static_assert(sizeof(TbFactorPatch) == 256 && offsetof(TbFactorPatch, edge_sphere) == 128);
static_assert(offsetof(TbFactorPatch, edge_m) == 192 && offsetof(TbFactorPatch, pad) == 240);
static_assert(offsetof(TbFactorParamsBlock, eye) == 64 &&
              offsetof(TbFactorParamsBlock, policy) == 104);
static_assert(offsetof(TbFactorParamsBlock, error_scale) == 128);
static_assert(offsetof(TbFactorParamsBlock, row_length_x) == 144);
static_assert(offsetof(TbFactorParamsBlock, side_length) == 176);
static_assert(sizeof(TbFactorParamsBlock) == 192);      // tb_transition starts here
inline constexpr size_t kTbFactorOutWordsPerPatch = 8;  // 2 uvec4 of tb_factor_out
}  // namespace tb::gpu::layout
#endif

#endif
