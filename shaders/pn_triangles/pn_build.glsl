// What pn.tesc's main runs, shared with the compute path (pn.comp): builds the 10 geometry
// control points and 6 normal coefficients from the triangle's vertices, read by index from
// storage buffers (techniques/pn_triangles/pn_build.h has the layout), into tb_pn_b,
// tb_pn_n and tb_pn_perm. Mirrors pn_eval.h computeControl operation for operation. Defines
// the function TB_BUILD_FUNCTION names (with its return type): void main() in the TCS,
// ending in TB_BUILD_EPILOGUE; on the compute path the surface's builder, whose locals
// TB_BUILD_PROLOGUE declares and whose return TB_BUILD_EPILOGUE is.
#ifndef TB_PN_BUILD_GLSL
#define TB_PN_BUILD_GLSL

TB_BUILD_FUNCTION {
#ifdef TB_BUILD_PROLOGUE
  TB_BUILD_PROLOGUE
#endif
  const uint base = tbPatchIndex() * kTbPnRecordWords;
  vec3 p[3], n[3];
  uint flags[3];
  for (uint i = 0u; i < 3u; ++i) {
    p[i] = positions[records[base + kTbPnPosition + i]].xyz;
    n[i] = tbNormalize(normals[records[base + kTbPnNormal + i]].xyz);
    flags[i] = records[base + kTbPnFlags + i];
  }
  tb_pn_perm = uvec3(records[base + 0u], records[base + 1u], records[base + 2u]);
  precise vec3 edge[6];
  for (uint e = 0u; e < 3u; ++e) {
    const uint a = kEdgeEnds[2u * e], b = kEdgeEnds[2u * e + 1u];
    // Seed 003: an edge uses geometry normals when both its vertices flag it.
    const bool flagged = ((flags[a] & flags[b]) & (1u << e)) != 0u;
    const float scale = uintBitsToFloat(records[base + kTbPnEdgeScale + e]);
    for (uint end = 0u; end < 2u; ++end) {
      const uint i = end == 0u ? a : b, j = end == 0u ? b : a;
      vec3 own = n[i];
      if (flagged) own = tbNormalize(normals[records[base + kTbPnGeometryNormal + i]].xyz);
      precise vec3 point = edgePoint(p[i], p[j], own, scale);
      if (kAen != 0u) {
        const vec3 other = tbNormalize(normals[records[base + kTbPnOtherNormal + 2u * e + end]].xyz);
        point = (point + edgePoint(p[i], p[j], other, scale)) * 0.5;
      }
      edge[2u * e + end] = point;
      tb_pn_b[3u + 2u * e + end] = point;
    }
    precise vec3 d = p[b] - p[a];
    precise vec3 sum = n[a] + n[b];
    precise float dd = tbDot(d, d);
    precise float v = 0.0;
    if (dd > 0.0) v = (2.0 * tbDot(d, sum)) / dd;
    tb_pn_n[3u + e] = tbNormalize(sum - d * v);
  }
  for (uint i = 0u; i < 3u; ++i) {
    tb_pn_b[i] = p[i];
    tb_pn_n[i] = n[i];
  }
  precise vec3 e_sum = ((((edge[0] + edge[1]) + edge[2]) + edge[3]) + edge[4]) + edge[5];
  precise vec3 mean_edge = e_sum * (1.0 / 6.0);
  precise vec3 mean_corner = ((p[0] + p[1]) + p[2]) * (1.0 / 3.0);
  tb_pn_b[9] = mean_edge + (mean_edge - mean_corner) * 0.5;
  TB_BUILD_EPILOGUE
}

#endif
