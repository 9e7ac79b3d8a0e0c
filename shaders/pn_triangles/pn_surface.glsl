// Curved PN triangles' (Vlachos et al. 2001) declarations shared by pn.tesc, pn.tese and the
// compute path (pn.comp): define TB_SURFACE_BUILD for the TCS's switches, buffers and edge
// points. The stages' bodies are pn_build.glsl and pn_evaluate.glsl.
#ifndef TB_PN_SURFACE_GLSL
#define TB_PN_SURFACE_GLSL

#include "float_order.glsl"

#ifdef TB_SURFACE_BUILD
layout(constant_id = 0) const uint kAen = 0u;       // PN-AEN: average own and neighbour points
layout(constant_id = 1) const uint kUseScale = 0u;  // per-edge scale of w_ij (boundary, rounding)

#include "pn_layout.h"
layout(std430, set = 0, binding = TB_PN_BINDING_POSITIONS) readonly buffer Positions {
  vec4 positions[];
};
layout(std430, set = 0, binding = TB_PN_BINDING_NORMALS) readonly buffer Normals {
  vec4 normals[];
};
// kTbPnRecordWords per patch (pn_layout.h TbPnRecord).
layout(std430, set = 0, binding = TB_PN_BINDING_RECORDS) readonly buffer Records {
  uint records[];
};

const uint kEdgeEnds[6] = uint[6](0u, 1u, 0u, 2u, 1u, 2u);

vec3 edgePoint(vec3 pi, vec3 pj, vec3 ni, float scale) {
  precise float w = tbDot(pj - pi, ni);
  if (kUseScale != 0u) w = w * scale;
  precise vec3 point = ((pi * 2.0 + pj) - ni * w) * (1.0 / 3.0);
  return point;
}
#endif

#endif
