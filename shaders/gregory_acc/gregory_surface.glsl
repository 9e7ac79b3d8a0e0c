// gregory_acc's TES declarations shared by the quad and triangle TESs and the compute path
// (gregory_acc.comp, gregory_tri.comp): the variant switch, at() over the 20 or 15 control
// points (declare `control_point` first: the TES's input, the compute path's copy), the
// pieces of gregory_common.glsl and, with TB_GREGORY_TRIANGLE, the triangle's quartic net.
// Control point corner * 5 + slot, slots P, Ep, Em, Fp, Fm. The bodies are
// gregory_quad_evaluate.glsl and gregory_tri_evaluate.glsl.
#ifndef TB_GREGORY_SURFACE_GLSL
#define TB_GREGORY_SURFACE_GLSL

// 1: points on the domain boundary come from the shared cubic edge curve, evaluated
// symmetrically in its parameter (bitwise-equal from both patches, quad or triangle).
layout(constant_id = 0) const uint kSymmetricEdges = 1u;

vec3 at(uint corner, uint slot) { return control_point[corner * 5u + slot]; }

#include "gregory_common.glsl"

#ifdef TB_GREGORY_TRIANGLE
// b_ijk's index: rows of descending i, each by descending j (kQuarticNet's order).
int slot(int i, int j) { return (4 - i) * (5 - i) / 2 + (4 - i - j); }

const int kFactorial[5] = int[5](1, 1, 2, 6, 24);

vec3 nearEnd(vec3 p, vec3 e) {
  precise vec3 r = (p + e * 3.0) * 0.25;
  return r;
}

vec3 middle(vec3 a, vec3 b) {
  precise vec3 r = (a + b) * 0.5;
  return r;
}
#endif

#endif
