// What bezier_position.tese's main runs, shared with its compute twin
// (bezier_position.comp): the geometry patch's position alone at TB_TESS_COORD
// (gl_TessCoord there) in the Bézier order of specialisation constant 0, from b_in, into
// TB_CLIP_POSITION (gl_Position there). Defines the function TB_EVALUATE_FUNCTION names:
// main() in the TES; on the compute path the surface's evaluator, whose fields
// TB_EVALUATE_PROLOGUE unpacks (TB_EVALUATE_EPILOGUE, if any, ends it).
#ifndef TB_BEZIER_POSITION_EVALUATE_GLSL
#define TB_BEZIER_POSITION_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
  vec3 b[16];
  for (int i = 0; i < 16; ++i) b[i] = b_in[i];
  TB_CLIP_POSITION = vec4((kOrder == kTbBezierSymmetricNoFmaImprecise ? tbEvaluateBicubicImprecise(b, TB_TESS_COORD.xy) : tbEvaluateBicubic(b, TB_TESS_COORD.xy, kOrder)), 1.0);
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
