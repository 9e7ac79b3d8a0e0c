// What acc.tese's main runs, shared with the compute path (acc.comp): the geometry patch at
// TB_TESS_COORD (gl_TessCoord there) in the variant's Bézier order (specialisation constant
// 0, shaders/common/bezier.glsl) and the normal from the tangent patches, from b_in, tu_in
// and tv_in; ends in tbEmitVertex. Defines the function TB_EVALUATE_FUNCTION names: main()
// in the TES; on the compute path the surface's evaluator, whose fields
// TB_EVALUATE_PROLOGUE unpacks (TB_EVALUATE_EPILOGUE, if any, ends it).
#ifndef TB_ACC_EVALUATE_GLSL
#define TB_ACC_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
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
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
