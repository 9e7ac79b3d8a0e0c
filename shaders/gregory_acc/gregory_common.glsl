// Pieces of the gregory_acc TES shared by the quad and triangle patches: the symmetric
// cubic edge curve (bitwise equal from both patches of an edge, whatever their domain)
// and the rational face-point blend. Mirrors techniques/gregory_acc/gregory_eval.h.
#ifndef TB_GREGORY_COMMON_GLSL
#define TB_GREGORY_COMMON_GLSL

vec3 halfEdge(vec3 p, vec3 e, float x, float y) {
  precise float x2 = x * x;
  precise vec3 r = p * (x2 * x) + e * ((3.0 * x2) * y);
  return r;
}

vec3 symmetricEdge(vec3 a, vec3 ea, vec3 eb, vec3 b, float t) {
  precise float s = 1.0 - t;
  precise vec3 ha = halfEdge(a, ea, s, t);
  precise vec3 hb = halfEdge(b, eb, t, s);
  precise vec3 r = ha + hb;
  return r;
}

void bernstein3(float t, out float b[4], out float d[4]) {
  precise float s = 1.0 - t;
  precise float b0 = s * s * s, b1 = 3.0 * s * s * t, b2 = 3.0 * s * t * t, b3 = t * t * t;
  precise float d0 = -3.0 * s * s, d1 = 3.0 * s * (s - 2.0 * t), d2 = 3.0 * t * (2.0 * s - t),
                d3 = 3.0 * t * t;
  b = float[4](b0, b1, b2, b3);
  d = float[4](d0, d1, d2, d3);
}

// (a Fp + b Fm) / (a + b) and its derivatives (Loop et al. 2009 eq. 2).
void blendFace(vec3 fp, vec3 fm, float a, float b, float a_u, float b_u, float a_v, float b_v,
               out vec3 q, out vec3 q_u, out vec3 q_v) {
  precise float sum = a + b;
  if (sum == 0.0) {
    precise vec3 mid = (fp + fm) * 0.5;
    q = mid;
    q_u = vec3(0.0);
    q_v = vec3(0.0);
    return;
  }
  precise float inv = 1.0 / sum;
  precise vec3 blended = (fp * a + fm * b) * inv;
  precise vec3 diff = (fp - fm) * (inv * inv);
  precise vec3 du = diff * (a_u * b - b_u * a);
  precise vec3 dv = diff * (a_v * b - b_v * a);
  q = blended;
  q_u = du;
  q_v = dv;
}

#endif
