// Curved PN triangles (Vlachos et al. 2001) as functions the TCS/TES pair and the compute
// path (pn.comp, shaders/common/compute_surface.glsl) share, so both run the same float
// operations. tbBuildPnSurface (define TB_SURFACE_BUILD before including; it reads the
// storage buffers, techniques/pn_triangles/pn_build.h has the layout) is the TCS's work:
// the 10 geometry control points and 6 normal coefficients, mirroring pn_eval.h
// computeControl operation for operation. tbEvaluatePnSurface is the TES's: the cubic
// geometry and quadratic normal patches in pn_eval.h evaluateControl's order (corners,
// edges (0,1), (0,2), (1,2), centre), so both faces of a shared edge sum the same terms.
#ifndef TB_PN_SURFACE_GLSL
#define TB_PN_SURFACE_GLSL

#include "float_order.glsl"

layout(constant_id = 0) const uint kAen = 0u;       // PN-AEN: average own and neighbour points
layout(constant_id = 1) const uint kUseScale = 0u;  // per-edge scale of w_ij (boundary, rounding)

struct TbPnSurface {
  vec3 b[10];  // corners 0..2, edge e end k at 3 + 2e + k, centre 9
  vec3 n[6];   // corner normals 0..2, edge normals 3..5
  uvec3 perm;  // canonical label -> gl_TessCoord component
};

#ifdef TB_SURFACE_BUILD
layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer Normals { vec4 normals[]; };
// 24 words per patch, see techniques/common/triangle_records.h TriangleRecordWord.
layout(std430, set = 0, binding = 3) readonly buffer Records { uint records[]; };

const uint kTbPnEdgeEnds[6] = uint[6](0u, 1u, 0u, 2u, 1u, 2u);

vec3 tbPnEdgePoint(vec3 pi, vec3 pj, vec3 ni, float scale) {
  precise float w = tbDot(pj - pi, ni);
  if (kUseScale != 0u) w = w * scale;
  precise vec3 point = ((pi * 2.0 + pj) - ni * w) * (1.0 / 3.0);
  return point;
}

TbPnSurface tbBuildPnSurface(uint patch_index) {
  const uint base = patch_index * 24u;
  TbPnSurface s;
  vec3 p[3], n[3];
  uint flags[3];
  for (uint i = 0u; i < 3u; ++i) {
    p[i] = positions[records[base + 3u + i]].xyz;
    n[i] = tbNormalize(normals[records[base + 6u + i]].xyz);
    flags[i] = records[base + 12u + i];
  }
  s.perm = uvec3(records[base + 0u], records[base + 1u], records[base + 2u]);
  precise vec3 edge[6];
  for (uint e = 0u; e < 3u; ++e) {
    const uint a = kTbPnEdgeEnds[2u * e], b = kTbPnEdgeEnds[2u * e + 1u];
    // Seed 003: an edge uses geometry normals when both its vertices flag it.
    const bool flagged = ((flags[a] & flags[b]) & (1u << e)) != 0u;
    const float scale = uintBitsToFloat(records[base + 21u + e]);
    for (uint end = 0u; end < 2u; ++end) {
      const uint i = end == 0u ? a : b, j = end == 0u ? b : a;
      vec3 own = n[i];
      if (flagged) own = tbNormalize(normals[records[base + 9u + i]].xyz);
      precise vec3 point = tbPnEdgePoint(p[i], p[j], own, scale);
      if (kAen != 0u) {
        const vec3 other = tbNormalize(normals[records[base + 15u + 2u * e + end]].xyz);
        point = (point + tbPnEdgePoint(p[i], p[j], other, scale)) * 0.5;
      }
      edge[2u * e + end] = point;
      s.b[3u + 2u * e + end] = point;
    }
    precise vec3 d = p[b] - p[a];
    precise vec3 sum = n[a] + n[b];
    precise float dd = tbDot(d, d);
    precise float v = 0.0;
    if (dd > 0.0) v = (2.0 * tbDot(d, sum)) / dd;
    s.n[3u + e] = tbNormalize(sum - d * v);
  }
  for (uint i = 0u; i < 3u; ++i) {
    s.b[i] = p[i];
    s.n[i] = n[i];
  }
  precise vec3 e_sum = ((((edge[0] + edge[1]) + edge[2]) + edge[3]) + edge[4]) + edge[5];
  precise vec3 mean_edge = e_sum * (1.0 / 6.0);
  precise vec3 mean_corner = ((p[0] + p[1]) + p[2]) * (1.0 / 3.0);
  s.b[9] = mean_edge + (mean_edge - mean_corner) * 0.5;
  return s;
}
#endif

void tbEvaluatePnSurface(TbPnSurface s, vec3 tess_coord, out vec3 position, out vec3 normal) {
  const vec3 w = vec3(tess_coord[s.perm.x], tess_coord[s.perm.y], tess_coord[s.perm.z]);
  precise float aa = w.x * w.x, bb = w.y * w.y, cc = w.z * w.z;
  precise float ab = w.x * w.y, ac = w.x * w.z, bc = w.y * w.z;
  precise vec3 p = (s.b[0] * (aa * w.x) + s.b[1] * (bb * w.y)) + s.b[2] * (cc * w.z);
  p = p + (s.b[3] * w.x + s.b[4] * w.y) * (ab * 3.0);
  p = p + (s.b[5] * w.x + s.b[6] * w.z) * (ac * 3.0);
  p = p + (s.b[7] * w.y + s.b[8] * w.z) * (bc * 3.0);
  p = p + s.b[9] * ((ab * w.z) * 6.0);
  precise vec3 n = (s.n[0] * aa + s.n[1] * bb) + s.n[2] * cc;
  n = ((n + s.n[3] * ab) + s.n[4] * ac) + s.n[5] * bc;
  position = p;
  normal = tbNormalize(n);
}

#endif
