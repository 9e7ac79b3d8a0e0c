// The body of acc.tese's main, shared with the compute path (acc.comp): the geometry patch
// at TB_TESS_COORD (gl_TessCoord there) in the variant's Bézier order (specialisation
// constant 0, shaders/common/bezier.glsl) and the normal from the tangent patches, from
// b_in, tu_in and tv_in; ends in tbEmitVertex. Included inside a function.
  vec3 b[16];
  for (int i = 0; i < 16; ++i) b[i] = b_in[i];
  vec3 tu[12], tv[12];
  for (int i = 0; i < 12; ++i) {
    tu[i] = tu_in[i];
    tv[i] = tv_in[i];
  }
  const vec2 uv = TB_TESS_COORD.xy;
  const vec3 position = (kOrder == kTbBezierSymmetricNoFmaImprecise ? tbEvaluateBicubicImprecise(b, uv) : tbEvaluateBicubic(b, uv, kOrder));
  const vec3 normal = normalize(cross(tbEvaluateTangentU(tu, uv), tbEvaluateTangentV(tv, uv)));
  tbEmitVertex(position, normal);
