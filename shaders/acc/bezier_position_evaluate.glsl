// The body of bezier_position.tese's main, shared with its compute twin
// (bezier_position.comp): the geometry patch's position alone at TB_TESS_COORD
// (gl_TessCoord there) in the Bézier order of specialisation constant 0, from b_in, into
// TB_CLIP_POSITION (gl_Position there). Included inside a function, so the probe compiles to
// the same SPIR-V as before it was shared.
  vec3 b[16];
  for (int i = 0; i < 16; ++i) b[i] = b_in[i];
  TB_CLIP_POSITION = vec4((kOrder == kTbBezierSymmetricNoFmaImprecise ? tbEvaluateBicubicImprecise(b, TB_TESS_COORD.xy) : tbEvaluateBicubic(b, TB_TESS_COORD.xy, kOrder)), 1.0);
