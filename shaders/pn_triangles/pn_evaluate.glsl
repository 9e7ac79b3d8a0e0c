// What pn.tese's main runs, shared with the compute path (pn.comp): the cubic geometry
// patch and quadratic normal patch at TB_TESS_COORD (gl_TessCoord there), in pn_eval.h
// evaluateControl's order (corners, edges (0,1), (0,2), (1,2), centre), so both faces of a
// shared edge sum the same terms identically. Reads tb_pn_b, tb_pn_n and tb_pn_perm and
// ends in tbEmitVertex. Defines the function TB_EVALUATE_FUNCTION names: main() in the TES;
// on the compute path the surface's evaluator, whose fields TB_EVALUATE_PROLOGUE unpacks
// (TB_EVALUATE_EPILOGUE, if any, ends it).
#ifndef TB_PN_EVALUATE_GLSL
#define TB_PN_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
  const vec3 w = vec3(TB_TESS_COORD[tb_pn_perm.x], TB_TESS_COORD[tb_pn_perm.y],
                      TB_TESS_COORD[tb_pn_perm.z]);
  precise float aa = w.x * w.x, bb = w.y * w.y, cc = w.z * w.z;
  precise float ab = w.x * w.y, ac = w.x * w.z, bc = w.y * w.z;
  precise vec3 p = (tb_pn_b[0] * (aa * w.x) + tb_pn_b[1] * (bb * w.y)) + tb_pn_b[2] * (cc * w.z);
  p = p + (tb_pn_b[3] * w.x + tb_pn_b[4] * w.y) * (ab * 3.0);
  p = p + (tb_pn_b[5] * w.x + tb_pn_b[6] * w.z) * (ac * 3.0);
  p = p + (tb_pn_b[7] * w.y + tb_pn_b[8] * w.z) * (bc * 3.0);
  p = p + tb_pn_b[9] * ((ab * w.z) * 6.0);
  precise vec3 n = (tb_pn_n[0] * aa + tb_pn_n[1] * bb) + tb_pn_n[2] * cc;
  n = ((n + tb_pn_n[3] * ab) + tb_pn_n[4] * ac) + tb_pn_n[5] * bc;
  tbEmitVertex(p, tbNormalize(n));
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
