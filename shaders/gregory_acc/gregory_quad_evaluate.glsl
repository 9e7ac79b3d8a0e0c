// What gregory_acc.tese's main runs, shared with the compute path (gregory_acc.comp): the
// quad Gregory patch at TB_TESS_COORD (gl_TessCoord there), position and analytic normal,
// from the 20 points at() reads (gregory_surface.glsl). Mirrors techniques/gregory_acc/
// gregory_eval.h operation for operation (every value `precise`); ends in tbEmitVertex.
// Defines the function TB_EVALUATE_FUNCTION names: main() in the TES; on the compute path
// the surface's evaluator, whose fields TB_EVALUATE_PROLOGUE unpacks (TB_EVALUATE_EPILOGUE,
// if any, ends it).
#ifndef TB_GREGORY_QUAD_EVALUATE_GLSL
#define TB_GREGORY_QUAD_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
  const float u = TB_TESS_COORD.x, v = TB_TESS_COORD.y;
  precise float iu = 1.0 - u, iv = 1.0 - v;
  vec3 q[4][4];
  vec3 q_u[4][4], q_v[4][4];
  q[0][0] = at(0u, 0u); q[0][1] = at(0u, 1u); q[0][2] = at(1u, 2u); q[0][3] = at(1u, 0u);
  q[3][0] = at(3u, 0u); q[3][1] = at(3u, 2u); q[3][2] = at(2u, 1u); q[3][3] = at(2u, 0u);
  q[1][0] = at(0u, 2u);
  q[1][3] = at(1u, 1u);
  q[2][0] = at(3u, 1u);
  q[2][3] = at(2u, 2u);
  blendFace(at(0u, 3u), at(0u, 4u), u, v, 1.0, 0.0, 0.0, 1.0, q[1][1], q_u[1][1], q_v[1][1]);
  blendFace(at(1u, 3u), at(1u, 4u), v, iu, 0.0, -1.0, 1.0, 0.0, q[1][2], q_u[1][2], q_v[1][2]);
  blendFace(at(2u, 3u), at(2u, 4u), iu, iv, -1.0, 0.0, 0.0, -1.0, q[2][2], q_u[2][2],
            q_v[2][2]);
  blendFace(at(3u, 3u), at(3u, 4u), iv, u, 0.0, 1.0, -1.0, 0.0, q[2][1], q_u[2][1], q_v[2][1]);

  float bu[4], du[4], bv[4], dv[4];
  bernstein3(u, bu, du);
  bernstein3(v, bv, dv);
  precise vec3 position = vec3(0.0), tangent_u = vec3(0.0), tangent_v = vec3(0.0);
  for (int j = 0; j < 4; ++j) {
    precise vec3 row = vec3(0.0), row_u = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
      row = row + q[j][i] * bu[i];
      row_u = row_u + q[j][i] * du[i];
    }
    position = position + row * bv[j];
    tangent_u = tangent_u + row_u * bv[j];
    tangent_v = tangent_v + row * dv[j];
  }
  for (int j = 1; j < 3; ++j) {
    for (int i = 1; i < 3; ++i) {
      precise float w = bu[i] * bv[j];
      tangent_u = tangent_u + q_u[j][i] * w;
      tangent_v = tangent_v + q_v[j][i] * w;
    }
  }
  if (kSymmetricEdges != 0u) {
    if (v == 0.0) {
      position = symmetricEdge(at(0u, 0u), at(0u, 1u), at(1u, 2u), at(1u, 0u), u);
    } else if (u == 1.0) {
      position = symmetricEdge(at(1u, 0u), at(1u, 1u), at(2u, 2u), at(2u, 0u), v);
    } else if (v == 1.0) {
      position = symmetricEdge(at(3u, 0u), at(3u, 2u), at(2u, 1u), at(2u, 0u), u);
    } else if (u == 0.0) {
      position = symmetricEdge(at(0u, 0u), at(0u, 2u), at(3u, 1u), at(3u, 0u), v);
    }
  }
  precise vec3 n = cross(tangent_u, tangent_v);
  precise float len = sqrt(dot(n, n));
  precise vec3 normal = len > 0.0 ? n * (1.0 / len) : n;
  tbEmitVertex(position, normal);
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
