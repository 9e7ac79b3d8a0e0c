// Shared by pn.tesc / pn.tese: float arithmetic in the order of
// techniques/pn_triangles/pn_eval.h (every order-sensitive value is `precise`, so
// NIR neither reassociates nor contracts it; DESIGN.md watertightness rule 2).
#ifndef TB_PN_COMMON_GLSL
#define TB_PN_COMMON_GLSL

// Left to right, as pn_eval.h dotInOrder.
float tbDot(vec3 a, vec3 b) {
  precise float d = a.x * b.x + a.y * b.y + a.z * b.z;
  return d;
}

// v * (1 / |v|); zero stays zero (pn_eval.h normalizeInOrder).
vec3 tbNormalize(vec3 v) {
  precise float len = sqrt(tbDot(v, v));
  if (!(len > 0.0)) return v;
  precise float inv = 1.0 / len;
  precise vec3 n = v * inv;
  return n;
}

#endif
