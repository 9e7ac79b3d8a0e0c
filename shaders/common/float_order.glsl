// Vector helpers with a fixed float operation order, matching core/mesh/vec.h (dot,
// normalize) so CPU float models reproduce shaders bit for bit. `precise` keeps NIR from
// reassociating or contracting them (docs/ARCHITECTURE.md §5 rule 2).
#ifndef TB_FLOAT_ORDER_GLSL
#define TB_FLOAT_ORDER_GLSL

// Left to right: a.x * b.x + a.y * b.y + a.z * b.z.
float tbDot(vec3 a, vec3 b) {
  precise float d = a.x * b.x + a.y * b.y + a.z * b.z;
  return d;
}

// v * (1 / |v|); a zero vector stays zero (vec.h normalize).
vec3 tbNormalize(vec3 v) {
  precise float len = sqrt(tbDot(v, v));
  if (!(len > 0.0)) return v;
  precise float inv = 1.0 / len;
  precise vec3 n = v * inv;
  return n;
}

#endif
