#version 460
// ACC evaluation: the geometry patch in the variant's Bézier order (specialisation
// constant 0, shaders/common/bezier.glsl) and the normal from the tangent patches
// built by acc.tesc (the geometry derivatives in the no_tangent variant).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tes.glsl"
#include "bezier.glsl"

layout(quads, equal_spacing, ccw) in;
layout(constant_id = 0) const uint kOrder = 2u;
layout(constant_id = 1) const uint kTangentPatches = 1u;

layout(location = 0) in vec3 b_in[];
layout(location = 3) patch in vec3 tu_in[12];
layout(location = 15) patch in vec3 tv_in[12];

void main() {
  vec3 b[16];
  for (int i = 0; i < 16; ++i) b[i] = b_in[i];
  vec3 tu[12], tv[12];
  for (int i = 0; i < 12; ++i) {
    tu[i] = tu_in[i];
    tv[i] = tv_in[i];
  }
  const vec2 uv = gl_TessCoord.xy;
  const vec3 position = (kOrder == kTbBezierSymmetricNoFmaImprecise ? tbEvaluateBicubicImprecise(b, uv) : tbEvaluateBicubic(b, uv, kOrder));
  const vec3 normal = normalize(cross(tbEvaluateTangentU(tu, uv), tbEvaluateTangentV(tv, uv)));
  tbEmitVertex(position, normal);
}
