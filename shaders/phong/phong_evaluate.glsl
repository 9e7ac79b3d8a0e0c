// What phong.tese's main runs, shared with the compute path (phong.comp): Phong
// tessellation at TB_TESS_COORD (gl_TessCoord there), in the operation order of
// techniques/phong/phong_eval.h evaluatePhongInOrder (default) or phong_edge_eval.h
// evaluatePhongEdge (kEdge, seed 003's per-edge extension). Reads tb_phong_p, tb_phong_n,
// tb_phong_edge_n and tb_phong_perm (phong_surface.glsl) and ends in tbEmitVertex. Defines
// the function TB_EVALUATE_FUNCTION names: main() in the TES; on the compute path the
// surface's evaluator, whose fields TB_EVALUATE_PROLOGUE unpacks (TB_EVALUATE_EPILOGUE, if
// any, ends it).
#ifndef TB_PHONG_EVALUATE_GLSL
#define TB_PHONG_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
  const float alpha = uintBitsToFloat(kAlphaBits);
  const float w[3] = float[3](TB_TESS_COORD[tb_phong_perm.x], TB_TESS_COORD[tb_phong_perm.y],
                              TB_TESS_COORD[tb_phong_perm.z]);
  precise vec3 flat_point =
      tb_phong_p[0] * w[0] + tb_phong_p[1] * w[1] + tb_phong_p[2] * w[2];
  precise vec3 normal_sum = tb_phong_n[0] * w[0] + tb_phong_n[1] * w[1] + tb_phong_n[2] * w[2];
  const vec3 normal = tbNormalize(normal_sum);
  precise vec3 offset = vec3(0.0);
  if (kEdge == 0u) {
    // Boubekeur & Alexa eq. 3-4, written as p - α Σ w_i ((p - p_i)·n_i) n_i.
    for (uint i = 0u; i < 3u; ++i) {
      precise float height = tbDot(flat_point - tb_phong_p[i], tb_phong_n[i]);
      offset = offset + tb_phong_n[i] * (w[i] * height);
    }
  } else {
    precise float denominator = (w[0] * w[1] + w[0] * w[2]) + w[1] * w[2];
    if (!(denominator > 0.0)) {
      tbEmitVertex(flat_point, normal);
      return;
    }
    for (uint e = 0u; e < 3u; ++e) {
      const uint i = kEdgeEnds[2u * e], j = kEdgeEnds[2u * e + 1u];
      precise float sum = w[i] + w[j];
      if (!(sum > 0.0)) continue;
      precise float ti = w[i] / sum, tj = w[j] / sum;
      precise vec3 q = tb_phong_p[i] * ti + tb_phong_p[j] * tj;
      const vec3 ni = tb_phong_edge_n[2u * e], nj = tb_phong_edge_n[2u * e + 1u];
      precise vec3 edge_offset = ni * (ti * tbDot(q - tb_phong_p[i], ni)) +
                                 nj * (tj * tbDot(q - tb_phong_p[j], nj));
      offset = offset + edge_offset * ((w[i] * w[j]) / denominator);
    }
  }
  precise vec3 position = flat_point - offset * alpha;
  tbEmitVertex(position, normal);
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
