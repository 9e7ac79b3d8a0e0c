// gregory_acc's triangle Gregory patch (Loop, Schaefer, Ni & Castaño 2009: cubic boundary
// curves shared with the neighbours, quartic interior with three rationally blended
// interior points) as functions the TCS/TES pair and the compute path (gregory_tri.comp,
// shaders/common/compute_surface.glsl) share. The build (define TB_SURFACE_BUILD before
// including) is the TCS's per-point stencil sum (gregory_stencil.glsl) for each of the 15
// points; tbEvaluateGregoryTriangle is the TES's: position and analytic normal, mirroring
// evaluateGregoryTriangle in techniques/gregory_acc/gregory_eval.h operation for operation
// (every value `precise`); keep the two in step.
// Control point corner * 5 + slot, slots P, Ep, Em, Fp, Fm (Fp/Fm: the quartic interior
// points of the corner next to its Ep / Em edge).
#ifndef TB_GREGORY_TRI_SURFACE_GLSL
#define TB_GREGORY_TRI_SURFACE_GLSL

#include "gregory_common.glsl"

// 1: points on the domain boundary come from the shared cubic edge curve, evaluated
// symmetrically in its parameter (bitwise-equal from both patches, quad or triangle).
layout(constant_id = 0) const uint kSymmetricEdges = 1u;

struct TbGregoryTriSurface {
  vec3 cp[15];
};

#ifdef TB_SURFACE_BUILD
#include "gregory_stencil.glsl"

TbGregoryTriSurface tbBuildGregoryTriangle(uint patch_index) {
  TbGregoryTriSurface s;
  for (uint i = 0u; i < 15u; ++i) s.cp[i] = tbGregoryControlPoint(patch_index, i, 15u);
  return s;
}
#endif

// b_ijk's index: rows of descending i, each by descending j (kQuarticNet's order).
int tbGregorySlot(int i, int j) { return (4 - i) * (5 - i) / 2 + (4 - i - j); }

const int kTbFactorial[5] = int[5](1, 1, 2, 6, 24);

vec3 tbGregoryNearEnd(vec3 p, vec3 e) {
  precise vec3 r = (p + e * 3.0) * 0.25;
  return r;
}

vec3 tbGregoryMiddle(vec3 a, vec3 b) {
  precise vec3 r = (a + b) * 0.5;
  return r;
}

#define TB_CP(corner, slot) s.cp[(corner) * 5u + (slot)]
void tbEvaluateGregoryTriangle(TbGregoryTriSurface s, vec3 tess_coord,
                               out vec3 surface_position, out vec3 normal) {
  const float u = tess_coord.x, v = tess_coord.y, w = tess_coord.z;
  vec3 b[15];
  b[tbGregorySlot(4, 0)] = TB_CP(0u, 0u);
  b[tbGregorySlot(0, 4)] = TB_CP(1u, 0u);
  b[tbGregorySlot(0, 0)] = TB_CP(2u, 0u);
  b[tbGregorySlot(3, 1)] = tbGregoryNearEnd(TB_CP(0u, 0u), TB_CP(0u, 1u));
  b[tbGregorySlot(2, 2)] = tbGregoryMiddle(TB_CP(0u, 1u), TB_CP(1u, 2u));
  b[tbGregorySlot(1, 3)] = tbGregoryNearEnd(TB_CP(1u, 0u), TB_CP(1u, 2u));
  b[tbGregorySlot(0, 3)] = tbGregoryNearEnd(TB_CP(1u, 0u), TB_CP(1u, 1u));
  b[tbGregorySlot(0, 2)] = tbGregoryMiddle(TB_CP(1u, 1u), TB_CP(2u, 2u));
  b[tbGregorySlot(0, 1)] = tbGregoryNearEnd(TB_CP(2u, 0u), TB_CP(2u, 2u));
  b[tbGregorySlot(1, 0)] = tbGregoryNearEnd(TB_CP(2u, 0u), TB_CP(2u, 1u));
  b[tbGregorySlot(2, 0)] = tbGregoryMiddle(TB_CP(2u, 1u), TB_CP(0u, 2u));
  b[tbGregorySlot(3, 0)] = tbGregoryNearEnd(TB_CP(0u, 0u), TB_CP(0u, 2u));
  vec3 q_a[3], q_c[3], q;
  blendFace(TB_CP(0u, 3u), TB_CP(0u, 4u), v, w, 1.0, 0.0, 0.0, 1.0, q, q_a[0], q_c[0]);
  b[tbGregorySlot(2, 1)] = q;
  blendFace(TB_CP(1u, 3u), TB_CP(1u, 4u), w, u, 0.0, -1.0, 1.0, -1.0, q, q_a[1], q_c[1]);
  b[tbGregorySlot(1, 2)] = q;
  blendFace(TB_CP(2u, 3u), TB_CP(2u, 4u), u, v, -1.0, 1.0, -1.0, 0.0, q, q_a[2], q_c[2]);
  b[tbGregorySlot(1, 1)] = q;

  precise float up[5], vp[5], wp[5];
  up[0] = 1.0; up[1] = u; up[2] = u * u; up[3] = u * u * u; up[4] = u * u * u * u;
  vp[0] = 1.0; vp[1] = v; vp[2] = v * v; vp[3] = v * v * v; vp[4] = v * v * v * v;
  wp[0] = 1.0; wp[1] = w; wp[2] = w * w; wp[3] = w * w * w; wp[4] = w * w * w * w;

  precise vec3 position = vec3(0.0);
  for (int i = 4; i >= 0; --i) {
    for (int j = 4 - i; j >= 0; --j) {
      const int k = 4 - i - j;
      precise float weight =
          float(24 / (kTbFactorial[i] * kTbFactorial[j] * kTbFactorial[k])) * ((up[i] * vp[j]) * wp[k]);
      position = position + b[tbGregorySlot(i, j)] * weight;
    }
  }
  precise vec3 tangent_a = vec3(0.0), tangent_c = vec3(0.0);
  for (int i = 3; i >= 0; --i) {
    for (int j = 3 - i; j >= 0; --j) {
      const int k = 3 - i - j;
      precise float weight =
          float(6 / (kTbFactorial[i] * kTbFactorial[j] * kTbFactorial[k])) * ((up[i] * vp[j]) * wp[k]);
      precise vec3 base = b[tbGregorySlot(i + 1, j)];
      precise vec3 da = (b[tbGregorySlot(i, j + 1)] - base) * weight;
      precise vec3 dc = (b[tbGregorySlot(i, j)] - base) * weight;  // b_{i,j,k+1}
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
      position = symmetricEdge(TB_CP(0u, 0u), TB_CP(0u, 1u), TB_CP(1u, 2u), TB_CP(1u, 0u), v);
    } else if (u == 0.0) {
      position = symmetricEdge(TB_CP(1u, 0u), TB_CP(1u, 1u), TB_CP(2u, 2u), TB_CP(2u, 0u), w);
    } else if (v == 0.0) {
      position = symmetricEdge(TB_CP(2u, 0u), TB_CP(2u, 1u), TB_CP(0u, 2u), TB_CP(0u, 0u), u);
    }
  }
  precise vec3 n = cross(tangent_a, tangent_c);
  precise float len = sqrt(dot(n, n));
  precise vec3 unit_normal = len > 0.0 ? n * (1.0 / len) : n;
  surface_position = position;
  normal = unit_normal;
}
#undef TB_CP

#endif
