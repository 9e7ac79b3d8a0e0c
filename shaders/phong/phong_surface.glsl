// Phong tessellation's (Boubekeur & Alexa 2008) declarations shared by phong.tesc,
// phong.tese and the compute path (phong.comp): define TB_SURFACE_BUILD for the TCS's
// buffers, TB_SURFACE_EVALUATE for the TES's switches. The stages' bodies are
// phong_build.glsl and phong_evaluate.glsl.
#ifndef TB_PHONG_SURFACE_GLSL
#define TB_PHONG_SURFACE_GLSL

#include "float_order.glsl"

#ifdef TB_SURFACE_BUILD
#include "phong_layout.h"
layout(std430, set = 0, binding = TB_PHONG_BINDING_POSITIONS) readonly buffer Positions {
  vec4 positions[];
};
layout(std430, set = 0, binding = TB_PHONG_BINDING_NORMALS) readonly buffer Normals {
  vec4 normals[];
};
// kTbPhongRecordWords per patch (phong_layout.h TbPhongRecord).
layout(std430, set = 0, binding = TB_PHONG_BINDING_RECORDS) readonly buffer Records {
  uint records[];
};
#endif

#ifdef TB_SURFACE_EVALUATE
layout(constant_id = 0) const uint kAlphaBits = 0x3f400000u;  // 0.75
layout(constant_id = 1) const uint kEdge = 0u;

const uint kEdgeEnds[6] = uint[6](0u, 1u, 0u, 2u, 1u, 2u);
#endif

#endif
