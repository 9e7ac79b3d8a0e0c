// Phong tessellation (Boubekeur & Alexa 2008) as functions the TCS/TES pair and the compute
// path (phong.comp, shaders/common/compute_surface.glsl) share, so both run the same float
// operations: tbBuildPhongSurface is the TCS's work for one patch (define
// TB_SURFACE_BUILD before including, it reads the storage buffers), tbEvaluatePhongSurface
// the TES's at one domain point, in the operation order of techniques/phong/phong_eval.h
// evaluatePhongInOrder (default) or phong_edge_eval.h evaluatePhongEdge (kEdge, seed 003's
// per-edge extension).
#ifndef TB_PHONG_SURFACE_GLSL
#define TB_PHONG_SURFACE_GLSL

#include "float_order.glsl"

layout(constant_id = 0) const uint kAlphaBits = 0x3f400000u;  // 0.75
layout(constant_id = 1) const uint kEdge = 0u;

// What the TCS hands the TES: the corners in canonical order (techniques/phong/phong.cpp),
// normalised normals, the edge variant's per-edge-end normals and the canonical label ->
// gl_TessCoord component permutation.
struct TbPhongSurface {
  vec3 p[3];
  vec3 n[3];
  vec3 edge_n[6];
  uvec3 perm;
};

#ifdef TB_SURFACE_BUILD
layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer Normals { vec4 normals[]; };
// 15 words per patch: label -> corner (3), position (3), normal (3), edge-end normal (6).
layout(std430, set = 0, binding = 3) readonly buffer Records { uint records[]; };

// Reads patch `patch_index`'s triangle by index and normalises its normals as phong.cpp's
// evaluateFloat does.
TbPhongSurface tbBuildPhongSurface(uint patch_index) {
  const uint base = patch_index * 15u;
  TbPhongSurface s;
  for (uint i = 0u; i < 3u; ++i) {
    s.p[i] = positions[records[base + 3u + i]].xyz;
    s.n[i] = tbNormalize(normals[records[base + 6u + i]].xyz);
  }
  for (uint k = 0u; k < 6u; ++k) {
    s.edge_n[k] = tbNormalize(normals[records[base + 9u + k]].xyz);
  }
  s.perm = uvec3(records[base + 0u], records[base + 1u], records[base + 2u]);
  return s;
}
#endif

const uint kTbPhongEdgeEnds[6] = uint[6](0u, 1u, 0u, 2u, 1u, 2u);

// The surface at tess_coord (gl_TessCoord's bits): position before any displacement and
// the interpolated, normalised normal.
void tbEvaluatePhongSurface(TbPhongSurface s, vec3 tess_coord, out vec3 position,
                            out vec3 normal) {
  const float alpha = uintBitsToFloat(kAlphaBits);
  const float w[3] = float[3](tess_coord[s.perm.x], tess_coord[s.perm.y], tess_coord[s.perm.z]);
  precise vec3 flat_point = s.p[0] * w[0] + s.p[1] * w[1] + s.p[2] * w[2];
  precise vec3 normal_sum = s.n[0] * w[0] + s.n[1] * w[1] + s.n[2] * w[2];
  normal = tbNormalize(normal_sum);
  precise vec3 offset = vec3(0.0);
  if (kEdge == 0u) {
    // Boubekeur & Alexa eq. 3-4, written as p - α Σ w_i ((p - p_i)·n_i) n_i.
    for (uint i = 0u; i < 3u; ++i) {
      precise float height = tbDot(flat_point - s.p[i], s.n[i]);
      offset = offset + s.n[i] * (w[i] * height);
    }
  } else {
    precise float denominator = (w[0] * w[1] + w[0] * w[2]) + w[1] * w[2];
    if (!(denominator > 0.0)) {
      position = flat_point;
      return;
    }
    for (uint e = 0u; e < 3u; ++e) {
      const uint i = kTbPhongEdgeEnds[2u * e], j = kTbPhongEdgeEnds[2u * e + 1u];
      precise float sum = w[i] + w[j];
      if (!(sum > 0.0)) continue;
      precise float ti = w[i] / sum, tj = w[j] / sum;
      precise vec3 q = s.p[i] * ti + s.p[j] * tj;
      const vec3 ni = s.edge_n[2u * e], nj = s.edge_n[2u * e + 1u];
      precise vec3 edge_offset = ni * (ti * tbDot(q - s.p[i], ni)) +
                                 nj * (tj * tbDot(q - s.p[j], nj));
      offset = offset + edge_offset * ((w[i] * w[j]) / denominator);
    }
  }
  precise vec3 result = flat_point - offset * alpha;
  position = result;
}

#endif
