// What gregory_tri.tese's main runs, shared with the compute path (gregory_tri.comp): the
// triangle Gregory patch at TB_TESS_COORD (gl_TessCoord there), position and analytic
// normal, from the 15 points at() reads (gregory_surface.glsl). Mirrors
// evaluateGregoryTriangle in techniques/gregory_acc/gregory_eval.h operation for operation
// (every value `precise`); ends in tbEmitVertex. Defines the function TB_EVALUATE_FUNCTION
// names: main() in the TES; on the compute path the surface's evaluator, whose fields
// TB_EVALUATE_PROLOGUE unpacks (TB_EVALUATE_EPILOGUE, if any, ends it).
#ifndef TB_GREGORY_TRI_EVALUATE_GLSL
#define TB_GREGORY_TRI_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
  const float u = TB_TESS_COORD.x, v = TB_TESS_COORD.y, w = TB_TESS_COORD.z;
  vec3 b[15];
  b[slot(4, 0)] = at(0u, 0u);
  b[slot(0, 4)] = at(1u, 0u);
  b[slot(0, 0)] = at(2u, 0u);
  b[slot(3, 1)] = nearEnd(at(0u, 0u), at(0u, 1u));
  b[slot(2, 2)] = middle(at(0u, 1u), at(1u, 2u));
  b[slot(1, 3)] = nearEnd(at(1u, 0u), at(1u, 2u));
  b[slot(0, 3)] = nearEnd(at(1u, 0u), at(1u, 1u));
  b[slot(0, 2)] = middle(at(1u, 1u), at(2u, 2u));
  b[slot(0, 1)] = nearEnd(at(2u, 0u), at(2u, 2u));
  b[slot(1, 0)] = nearEnd(at(2u, 0u), at(2u, 1u));
  b[slot(2, 0)] = middle(at(2u, 1u), at(0u, 2u));
  b[slot(3, 0)] = nearEnd(at(0u, 0u), at(0u, 2u));
  vec3 q_a[3], q_c[3], q;
  blendFace(at(0u, 3u), at(0u, 4u), v, w, 1.0, 0.0, 0.0, 1.0, q, q_a[0], q_c[0]);
  b[slot(2, 1)] = q;
  blendFace(at(1u, 3u), at(1u, 4u), w, u, 0.0, -1.0, 1.0, -1.0, q, q_a[1], q_c[1]);
  b[slot(1, 2)] = q;
  blendFace(at(2u, 3u), at(2u, 4u), u, v, -1.0, 1.0, -1.0, 0.0, q, q_a[2], q_c[2]);
  b[slot(1, 1)] = q;

  precise float up[5], vp[5], wp[5];
  up[0] = 1.0; up[1] = u; up[2] = u * u; up[3] = u * u * u; up[4] = u * u * u * u;
  vp[0] = 1.0; vp[1] = v; vp[2] = v * v; vp[3] = v * v * v; vp[4] = v * v * v * v;
  wp[0] = 1.0; wp[1] = w; wp[2] = w * w; wp[3] = w * w * w; wp[4] = w * w * w * w;

  precise vec3 position = vec3(0.0);
  for (int i = 4; i >= 0; --i) {
    for (int j = 4 - i; j >= 0; --j) {
      const int k = 4 - i - j;
      precise float weight =
          float(24 / (kFactorial[i] * kFactorial[j] * kFactorial[k])) * ((up[i] * vp[j]) * wp[k]);
      position = position + b[slot(i, j)] * weight;
    }
  }
  precise vec3 tangent_a = vec3(0.0), tangent_c = vec3(0.0);
  for (int i = 3; i >= 0; --i) {
    for (int j = 3 - i; j >= 0; --j) {
      const int k = 3 - i - j;
      precise float weight =
          float(6 / (kFactorial[i] * kFactorial[j] * kFactorial[k])) * ((up[i] * vp[j]) * wp[k]);
      precise vec3 base = b[slot(i + 1, j)];
      precise vec3 da = (b[slot(i, j + 1)] - base) * weight;
      precise vec3 dc = (b[slot(i, j)] - base) * weight;  // b_{i,j,k+1}
      tangent_a = tangent_a + da;
      tangent_c = tangent_c + dc;
    }
  }
  tangent_a = tangent_a * 4.0;
  tangent_c = tangent_c * 4.0;
  // The blended interior points' own derivatives, b211, b121, b112, weight 12 u^i v^j w^k.
  precise float interior_weight[3];
  interior_weight[0] = 12.0 * ((up[2] * vp[1]) * wp[1]);
  interior_weight[1] = 12.0 * ((up[1] * vp[2]) * wp[1]);
  interior_weight[2] = 12.0 * ((up[1] * vp[1]) * wp[2]);
  for (int c = 0; c < 3; ++c) {
    tangent_a = tangent_a + q_a[c] * interior_weight[c];
    tangent_c = tangent_c + q_c[c] * interior_weight[c];
  }
  if (kSymmetricEdges != 0u) {
    if (w == 0.0) {
      position = symmetricEdge(at(0u, 0u), at(0u, 1u), at(1u, 2u), at(1u, 0u), v);
    } else if (u == 0.0) {
      position = symmetricEdge(at(1u, 0u), at(1u, 1u), at(2u, 2u), at(2u, 0u), w);
    } else if (v == 0.0) {
      position = symmetricEdge(at(2u, 0u), at(2u, 1u), at(0u, 2u), at(0u, 0u), u);
    }
  }
  precise vec3 n = cross(tangent_a, tangent_c);
  precise float len = sqrt(dot(n, n));
  precise vec3 normal = len > 0.0 ? n * (1.0 / len) : n;
  tbEmitVertex(position, normal);
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
