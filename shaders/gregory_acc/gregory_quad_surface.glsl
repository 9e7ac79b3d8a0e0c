// gregory_acc's quad Gregory patch (Loop, Schaefer, Ni & Castaño 2009) as functions the
// TCS/TES pair and the compute path (gregory_acc.comp, shaders/common/compute_surface.glsl)
// share, so both run the same float operations. The build (define TB_SURFACE_BUILD before
// including) is the TCS's per-point stencil sum (gregory_stencil.glsl) for each of the 20
// points; tbEvaluateGregoryQuad is the TES's: position and analytic normal, mirroring
// techniques/gregory_acc/gregory_eval.h operation for operation (every value `precise`, so
// NIR neither reassociates nor contracts); keep the two in step.
// Control point corner * 5 + slot, slots P, Ep, Em, Fp, Fm.
#ifndef TB_GREGORY_QUAD_SURFACE_GLSL
#define TB_GREGORY_QUAD_SURFACE_GLSL

#include "gregory_common.glsl"

// 1: points on the domain boundary come from the shared edge curve, evaluated
// symmetrically in its parameter (bitwise-equal from both patches).
layout(constant_id = 0) const uint kSymmetricEdges = 1u;

struct TbGregoryQuadSurface {
  vec3 cp[20];
};

#ifdef TB_SURFACE_BUILD
#include "gregory_stencil.glsl"

TbGregoryQuadSurface tbBuildGregoryQuad(uint patch_index) {
  TbGregoryQuadSurface s;
  for (uint i = 0u; i < 20u; ++i) s.cp[i] = tbGregoryControlPoint(patch_index, i, 20u);
  return s;
}
#endif

#define TB_CP(corner, slot) s.cp[(corner) * 5u + (slot)]
void tbEvaluateGregoryQuad(TbGregoryQuadSurface s, vec3 tess_coord, out vec3 surface_position,
                           out vec3 normal) {
  const float u = tess_coord.x, v = tess_coord.y;
  precise float iu = 1.0 - u, iv = 1.0 - v;
  vec3 q[4][4];
  vec3 q_u[4][4], q_v[4][4];
  q[0][0] = TB_CP(0u, 0u); q[0][1] = TB_CP(0u, 1u); q[0][2] = TB_CP(1u, 2u); q[0][3] = TB_CP(1u, 0u);
  q[3][0] = TB_CP(3u, 0u); q[3][1] = TB_CP(3u, 2u); q[3][2] = TB_CP(2u, 1u); q[3][3] = TB_CP(2u, 0u);
  q[1][0] = TB_CP(0u, 2u);
  q[1][3] = TB_CP(1u, 1u);
  q[2][0] = TB_CP(3u, 1u);
  q[2][3] = TB_CP(2u, 2u);
  blendFace(TB_CP(0u, 3u), TB_CP(0u, 4u), u, v, 1.0, 0.0, 0.0, 1.0, q[1][1], q_u[1][1], q_v[1][1]);
  blendFace(TB_CP(1u, 3u), TB_CP(1u, 4u), v, iu, 0.0, -1.0, 1.0, 0.0, q[1][2], q_u[1][2], q_v[1][2]);
  blendFace(TB_CP(2u, 3u), TB_CP(2u, 4u), iu, iv, -1.0, 0.0, 0.0, -1.0, q[2][2], q_u[2][2],
            q_v[2][2]);
  blendFace(TB_CP(3u, 3u), TB_CP(3u, 4u), iv, u, 0.0, 1.0, -1.0, 0.0, q[2][1], q_u[2][1], q_v[2][1]);

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
      position = symmetricEdge(TB_CP(0u, 0u), TB_CP(0u, 1u), TB_CP(1u, 2u), TB_CP(1u, 0u), u);
    } else if (u == 1.0) {
      position = symmetricEdge(TB_CP(1u, 0u), TB_CP(1u, 1u), TB_CP(2u, 2u), TB_CP(2u, 0u), v);
    } else if (v == 1.0) {
      position = symmetricEdge(TB_CP(3u, 0u), TB_CP(3u, 2u), TB_CP(2u, 1u), TB_CP(2u, 0u), u);
    } else if (u == 0.0) {
      position = symmetricEdge(TB_CP(0u, 0u), TB_CP(0u, 2u), TB_CP(3u, 1u), TB_CP(3u, 0u), v);
    }
  }
  precise vec3 n = cross(tangent_u, tangent_v);
  precise float len = sqrt(dot(n, n));
  precise vec3 unit_normal = len > 0.0 ? n * (1.0 / len) : n;
  surface_position = position;
  normal = unit_normal;
}
#undef TB_CP

#endif
