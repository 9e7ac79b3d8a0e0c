// Bicubic Bézier evaluation in the operation orders of techniques/common/bezier_eval.h
// (its CPU twin; keep the two in step). Every order-sensitive value is `precise`, so
// the compiler neither reassociates nor contracts it (docs/ARCHITECTURE.md §5 rule 2).
// lavapipe (Mesa 22.3.6) runs fma() on precise values as a separately rounded multiply
// and add; the CPU twin's fusedMulAdd(float) does the same (measured bit for bit).
//   order 0  asymmetric       FMA chain along u then v
//   order 1  symmetric_nofma  (B0 p0 + B1 p1) + (B3 p3 + B2 p2)
//   order 2  symmetric_fma    fma(B1, p1, B0 p0) + fma(B2, p2, B3 p3)
//   order 3  symmetric_edges  symmetric FMA on rows 0, 3 and the column, chain on rows 1, 2
//   order 4  symmetric_nofma written without `precise` (tbEvaluateBicubicImprecise): the
//            compiler may reassociate it, so it shows what `precise` buys
#ifndef TB_BEZIER_GLSL
#define TB_BEZIER_GLSL

const uint kTbBezierAsymmetric = 0u;
const uint kTbBezierSymmetricNoFma = 1u;
const uint kTbBezierSymmetricFma = 2u;
const uint kTbBezierSymmetricEdges = 3u;
const uint kTbBezierSymmetricNoFmaImprecise = 4u;

// B0..B3 at t, with s = 1 - t; basis(1 - t) is basis(t) reversed bit for bit.
vec4 tbCubicBasis(float t) {
  precise float s = 1.0 - t;
  precise float b0 = s * s * s;
  precise float b1 = 3.0 * s * s * t;
  precise float b2 = 3.0 * t * t * s;
  precise float b3 = t * t * t;
  return vec4(b0, b1, b2, b3);
}

vec3 tbQuadraticBasis(float t) {
  precise float s = 1.0 - t;
  precise float q0 = s * s;
  precise float q1 = 2.0 * s * t;
  precise float q2 = t * t;
  return vec3(q0, q1, q2);
}

// sum: 0 chain, 1 symmetric without FMA, 2 symmetric with FMA.
vec3 tbBezierSum4(vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec4 b, uint sum) {
  precise vec3 r;
  if (sum == 0u) {
    precise vec3 r0 = p0 * b.x;
    precise vec3 r1 = fma(p1, vec3(b.y), r0);
    precise vec3 r2 = fma(p2, vec3(b.z), r1);
    r = fma(p3, vec3(b.w), r2);
  } else if (sum == 1u) {
    r = (p0 * b.x + p1 * b.y) + (p3 * b.w + p2 * b.z);
  } else {
    precise vec3 lo = fma(p1, vec3(b.y), p0 * b.x);
    precise vec3 hi = fma(p2, vec3(b.z), p3 * b.w);
    r = lo + hi;
  }
  return r;
}

// p[i + 4 j]: i along u, j along v.
vec3 tbEvaluateBicubic(vec3 p[16], vec2 uv, uint order) {
  const vec4 bu = tbCubicBasis(uv.x);
  const vec4 bv = tbCubicBasis(uv.y);
  uint outer_rows = 2u, inner_rows = 2u, column = 2u;
  if (order == kTbBezierAsymmetric) {
    outer_rows = 0u; inner_rows = 0u; column = 0u;
  } else if (order == kTbBezierSymmetricNoFma) {
    outer_rows = 1u; inner_rows = 1u; column = 1u;
  } else if (order == kTbBezierSymmetricEdges) {
    inner_rows = 0u;
  }
  precise vec3 w0 = tbBezierSum4(p[0], p[1], p[2], p[3], bu, outer_rows);
  precise vec3 w1 = tbBezierSum4(p[4], p[5], p[6], p[7], bu, inner_rows);
  precise vec3 w2 = tbBezierSum4(p[8], p[9], p[10], p[11], bu, inner_rows);
  precise vec3 w3 = tbBezierSum4(p[12], p[13], p[14], p[15], bu, outer_rows);
  return tbBezierSum4(w0, w1, w2, w3, bv, column);
}

// Order 4: the symmetric sums of order 1 with no `precise` anywhere (basis included).
vec3 tbImpreciseSum4(vec3 p0, vec3 p1, vec3 p2, vec3 p3, vec4 b) {
  return (p0 * b.x + p1 * b.y) + (p3 * b.w + p2 * b.z);
}

vec3 tbEvaluateBicubicImprecise(vec3 p[16], vec2 uv) {
  const float su = 1.0 - uv.x, sv = 1.0 - uv.y;
  const vec4 bu = vec4(su * su * su, 3.0 * su * su * uv.x, 3.0 * uv.x * uv.x * su,
                       uv.x * uv.x * uv.x);
  const vec4 bv = vec4(sv * sv * sv, 3.0 * sv * sv * uv.y, 3.0 * uv.y * uv.y * sv,
                       uv.y * uv.y * uv.y);
  const vec3 w0 = tbImpreciseSum4(p[0], p[1], p[2], p[3], bu);
  const vec3 w1 = tbImpreciseSum4(p[4], p[5], p[6], p[7], bu);
  const vec3 w2 = tbImpreciseSum4(p[8], p[9], p[10], p[11], bu);
  const vec3 w3 = tbImpreciseSum4(p[12], p[13], p[14], p[15], bu);
  return tbImpreciseSum4(w0, w1, w2, w3, bv);
}

// Tangent-field patches: tu[i + 3 j] degree 2 in u and 3 in v; tv[i + 4 j] 3 x 2.
vec3 tbEvaluateTangentU(vec3 tu[12], vec2 uv) {
  const vec3 qu = tbQuadraticBasis(uv.x);
  const vec4 bv = tbCubicBasis(uv.y);
  precise vec3 result = vec3(0.0);
  for (int j = 0; j < 4; ++j) {
    precise vec3 row = tu[3 * j] * qu.x + tu[3 * j + 1] * qu.y + tu[3 * j + 2] * qu.z;
    result = j == 0 ? row * bv[0] : result + row * bv[j];
  }
  return result;
}

vec3 tbEvaluateTangentV(vec3 tv[12], vec2 uv) {
  const vec4 bu = tbCubicBasis(uv.x);
  const vec3 qv = tbQuadraticBasis(uv.y);
  precise vec3 result = vec3(0.0);
  for (int j = 0; j < 3; ++j) {
    precise vec3 row = tv[4 * j] * bu.x + tv[4 * j + 1] * bu.y + tv[4 * j + 2] * bu.z +
                       tv[4 * j + 3] * bu.w;
    result = j == 0 ? row * qv[0] : result + row * qv[j];
  }
  return result;
}

#endif
