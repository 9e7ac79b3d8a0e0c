// View-dependent tessellation-factor policies, computed in every technique's TCS when the
// harness turns them on (kTbFactorPolicy != 0, see patch_program_tcs.glsl). The CPU twin is
// harness/measures/factor_policy.{h,cpp}: same operations in the same order, in float, so
// the levels a TCS writes are bitwise the twin's (tests/measures/factor_policy_gpu_test.cpp).
//
//   set 1, binding 1   per patch: 4 corners (welded position and shared unit normal) and
//                      error_bound's bounds and hull spheres (harness/lod/error_bound.h)
//   set 1, binding 2   the policy and the view (TbFactorParams)
//   set 1, binding 3   the levels the TCS wrote, per patch (read back by the harness)
//
// One factor per patch edge, from the edge's two end corners only (docs/ARCHITECTURE.md §5,
// rule 3): the corners are taken in an order both patches of a shared edge agree on (the
// lexicographically smaller position first), so the factor is a function of the edge alone.
// The `order_dependent` option skips that ordering (patch order): the midpoint a + (b - a)/2
// then rounds differently on the two sides, which the adaptivity measure must catch.
// Inner levels come from the edges with the D3D11 helpers (ProcessTri/QuadTessFactors
// Avg/Max/Min, inside scale 1), ported from core/tess/factor_helpers.cpp.
#ifndef TB_TESS_FACTORS_GLSL
#define TB_TESS_FACTORS_GLSL

#include "float_order.glsl"

// The descriptor set of the harness's bindings: 1 in a TCS (set 0 is the program's); the
// compute levels pass (shaders/gpu/policy_levels.comp) defines it as 0 before including.
#ifndef TB_HARNESS_SET
#define TB_HARNESS_SET 1
#endif

// TbFactorParams::policy
const uint kTbPolicyUniform = 0u;         // every edge = target (a level)
const uint kTbPolicyDistance = 1u;        // target / |eye - midpoint| (target: level x world units)
const uint kTbPolicySphereDiameter = 2u;  // |d P11 / w| * H / (2 target px)
const uint kTbPolicyLp2Edge = 3u;         // max(L R C / D0, L R C / D1), C = target
const uint kTbPolicyErrorBound = 4u;      // the least levels within target px (error_bound.h)
// TbFactorParams::flags
const uint kTbFactorOrderDependent = 1u;
const uint kTbFactorSilhouette = 2u;  // scale by 1 - (1 - s_min) |n . v|
const uint kTbFactorRoundness = 4u;   // scale by how far the end normals turn
const uint kTbFactorDenseEdges = 8u;  // error_bound_dense: edges at every allowed level (a control)
// TbFactorParams::reduction
const uint kTbReduceAverage = 0u;
const uint kTbReduceMax = 1u;
const uint kTbReduceMin = 2u;
// TbFactorParams::spacing (tess::Spacing)
const uint kTbSpacingInteger = 0u;
const uint kTbSpacingPow2 = 1u;
const uint kTbSpacingFractionalOdd = 2u;
const uint kTbSpacingFractionalEven = 3u;

// TbFactorPatch, TbFactorParamsBlock (tb_factor) and TbFactorOut: the host shares them.
#include "layout/factor_layout.h"

// D3D11 IEEE-754R min/max: a NaN second operand yields the first.
float tbD3dMin(float a, float b) { return isnan(b) ? a : (a < b ? a : b); }
float tbD3dMax(float a, float b) { return isnan(b) ? a : (a >= b ? a : b); }
float tbCleanupFactor(float x) { return (isnan(x) || x < 1.0) ? 1.0 : x; }

float tbRoundUpFactor(float x, uint spacing) {
  if (spacing == kTbSpacingPow2) {
    const uint bits = floatBitsToUint(x);
    if ((bits & 0x007fffffu) == 0u) return x;
    return uintBitsToFloat((bits & 0x7f800000u) + 0x00800000u);
  }
  return spacing == kTbSpacingInteger ? ceil(x) : x;
}

float tbClampFactor(float x, uint spacing) {
  const float low = spacing == kTbSpacingFractionalEven ? 2.0 : 1.0;
  const float high = spacing == kTbSpacingFractionalOdd ? 63.0 : 64.0;
  const float at_least_low = x > low ? x : low;
  return high < at_least_low ? high : at_least_low;
}

bool tbHardwareInteger(uint spacing) {
  return spacing == kTbSpacingInteger || spacing == kTbSpacingPow2;
}

// Left to right over e[0..n-1]; the average divides once at the end.
float tbReduce(uint reduction, float e[4], uint n) {
  precise float result = e[0];
  for (uint i = 1u; i < n; ++i) {
    if (reduction == kTbReduceAverage) {
      result = result + e[i];
    } else if (reduction == kTbReduceMax) {
      result = tbD3dMax(result, e[i]);
    } else {
      result = tbD3dMin(result, e[i]);
    }
  }
  if (reduction == kTbReduceAverage) result = result / float(n);
  return result;
}

// The rounded inside factor (factor_helpers.cpp insideFactor, inside scale 1).
float tbInsideFactor(uint reduction, float e[4], uint n, uint spacing) {
  precise float scaled = tbReduce(reduction, e, n) * 1.0;
  float rounded = tbClampFactor(scaled, spacing);
  bool odd;
  if (tbHardwareInteger(spacing)) {
    rounded = tbRoundUpFactor(rounded, spacing);
    odd = !(((int(rounded) & 1) == 0) || rounded == 1.0);
  } else {
    odd = spacing == kTbSpacingFractionalOdd;
  }
  if (odd && rounded < 3.0) {
    const uint widen = reduction == kTbReduceMax ? kTbReduceMax : kTbReduceAverage;
    rounded = tbClampFactor(tbD3dMin(3.0, tbReduce(widen, e, n)), spacing);
    if (spacing == kTbSpacingInteger) rounded = ceil(rounded);
  }
  return rounded;
}

// (row 3 of M) . (p, 1), left to right: the clip w of p.
float tbClipW(vec3 p) {
  const mat4 m = tb_factor.view_projection;
  precise float w = m[0][3] * p.x + m[1][3] * p.y + m[2][3] * p.z + m[3][3];
  return w;
}

float tbLength(vec3 v) {
  precise float len = sqrt(tbDot(v, v));
  return len;
}

// a before b when a is lexicographically smaller (x, then y, then z).
bool tbPositionLess(vec3 a, vec3 b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// The raw factor of the edge from corner a to corner b (unclamped; the helpers clamp).
float tbEdgeFactor(vec3 a, vec3 b, vec3 na, vec3 nb) {
  if ((tb_factor.flags & kTbFactorOrderDependent) == 0u && tbPositionLess(b, a)) {
    const vec3 p = a;
    a = b;
    b = p;
    const vec3 n = na;
    na = nb;
    nb = n;
  }
  const vec3 eye = tb_factor.eye.xyz;
  precise vec3 edge = b - a;
  precise vec3 mid = a + edge * 0.5;
  precise float factor;
  if (tb_factor.policy == kTbPolicyUniform) {
    factor = tb_factor.target;
  } else if (tb_factor.policy == kTbPolicyDistance) {
    factor = tb_factor.target / tbLength(mid - eye);
  } else if (tb_factor.policy == kTbPolicySphereDiameter) {
    precise float ndc_height = abs(tbLength(edge) * tb_factor.projection_y_scale / tbClipW(mid));
    factor = ndc_height * tb_factor.pixel_scale;
  } else {
    precise float lrc = tbLength(edge) * tb_factor.viewport_height_px * tb_factor.target;
    factor = max(lrc / tbLength(a - eye), lrc / tbLength(b - eye));
  }
  if ((tb_factor.flags & kTbFactorSilhouette) != 0u) {
    const vec3 n = tbNormalize(na + nb);
    const vec3 v = tbNormalize(eye - mid);
    precise float scale = 1.0 - (1.0 - tb_factor.min_scale) * abs(tbDot(n, v));
    factor = factor * scale;
  }
  if ((tb_factor.flags & kTbFactorRoundness) != 0u) {
    precise float turn = (1.0 - tbDot(na, nb)) / tb_factor.roundness_span;
    precise float scale = tb_factor.min_scale + (1.0 - tb_factor.min_scale) * min(turn, 1.0);
    factor = factor * scale;
  }
  return factor;
}

// error_bound's world error at a hull sphere (xyz centre, w radius): the pixel target at its
// nearest clip w (at least the near plane's: only samples in front of it count) over the
// projection's largest stretch there; +inf (any level will do) when the sphere is wholly
// behind the near plane or outside a side of the view.
const float kTbSideMargin = 1.0 + 1.0 / 1024.0;

// The largest stretch sqrt(1 + a^2 + b^2) of the projection's Jacobian over the sphere (a, b
// = view x / z, y / z, each at most the view's edge: only visible samples count).
float tbProjectionStretch(float cx, float cy, float radius, float near_w) {
  precise float a = (abs(cx) + radius * tb_factor.row_length_x) * tb_factor.inv_scale_x / near_w;
  precise float b = (abs(cy) + radius * tb_factor.row_length_y) * tb_factor.inv_scale_y / near_w;
  a = a < tb_factor.tan_half_x ? a : tb_factor.tan_half_x;
  b = b < tb_factor.tan_half_y ? b : tb_factor.tan_half_y;
  precise float stretch = sqrt(1.0 + a * a + b * b);
  return stretch;
}

float tbErrorBoundEps(vec4 sphere) {
  const mat4 m = tb_factor.view_projection;
  precise float w = tbClipW(sphere.xyz);
  const float r = sphere.w;
  precise float far_w = w + r * tb_factor.hull_w_scale;
  if (far_w < tb_factor.near_w) return uintBitsToFloat(0x7f800000u);
  precise float cx = m[0][0] * sphere.x + m[1][0] * sphere.y + m[2][0] * sphere.z + m[3][0];
  precise float cy = m[0][1] * sphere.x + m[1][1] * sphere.y + m[2][1] * sphere.z + m[3][1];
  precise float sides[4] = float[4](w + cx, w - cx, w + cy, w - cy);
  for (uint k = 0u; k < 4u; ++k) {
    precise float reach = -(r * tb_factor.side_length[k]) * kTbSideMargin;
    if (sides[k] < reach) return uintBitsToFloat(0x7f800000u);
  }
  precise float hull_near_w = w - r * tb_factor.hull_w_scale;
  const float near_w = hull_near_w > tb_factor.near_w ? hull_near_w : tb_factor.near_w;
  precise float eps = near_w * tb_factor.error_scale / tbProjectionStretch(cx, cy, r, near_w);
  return eps;
}

// The whole levels error_bound takes (factor_policy.cpp, errorBoundLevelAllowed): those at
// which the spacing's segments are all equal.
bool tbErrorBoundLevelAllowed(uint n, uint spacing) {
  if (spacing == kTbSpacingPow2) return (n & (n - 1u)) == 0u;
  if (spacing == kTbSpacingFractionalOdd) return n % 2u == 1u;
  if (spacing == kTbSpacingFractionalEven) return n % 2u == 0u;
  return true;
}

// The levels error_bound gives an edge (transition_extents.h, narrowEdgeLevel): a family in
// which any two stitch narrowly to a common inside level.
bool tbErrorBoundEdgeAllowed(uint n, uint spacing) {
  if (!tbErrorBoundLevelAllowed(n, spacing)) return false;
  if (spacing == kTbSpacingInteger) return n <= 3u || n == 64u || ((n - 1u) & (n - 2u)) == 0u;
  if (spacing == kTbSpacingFractionalOdd) return n == 1u || n == 63u || ((n - 1u) & (n - 2u)) == 0u;
  return (n & (n - 1u)) == 0u;
}

float tbTransition(uint e, uint axis, uint o, uint n) {
  return tb_factor.tb_transition[((e * 3u + axis) * 64u + (o - 1u)) * 64u + (n - 1u)];
}

// The least allowed whole level whose longest segment keeps m / eps (a bound over 8) within
// the target: m s^2 <= eps; the spacing's top level where none does.
float tbErrorBoundEdge(vec4 sphere, float bound, uint edges, float top) {
  const float eps = tbErrorBoundEps(sphere);
  if (!(eps > 0.0)) return top;
  precise float m = bound / eps;
  for (uint o = 1u; o <= uint(top); ++o) {
    const bool dense = (tb_factor.flags & kTbFactorDenseEdges) != 0u;
    if (!(dense ? tbErrorBoundLevelAllowed(o, tb_factor.spacing)
                : tbErrorBoundEdgeAllowed(o, tb_factor.spacing))) continue;
    const float s = tb_factor.tb_transition[edges * 3u * 64u * 64u + (o - 1u)];
    precise float need = m * s * s;
    if (need <= 1.0) return float(o);
  }
  return top;
}

// The least allowed whole inside level n for which every triangle of the tessellation, the
// edges at `outer`, is within the patch's bound (the smaller of a du^2 + b dv^2 and
// 4 max(a, b) r^2 at most 1); where none is, the one that comes closest.
float tbErrorBoundInside(uint patch_index, float outer[4], uint edges, float top) {
  // Every sphere of the record holds the patch's hull: the largest eps (factor_policy.cpp).
  float eps = tbErrorBoundEps(tb_factor_patches[patch_index].patch_sphere);
  for (uint e = 0u; e < edges; ++e) {
    const float edge_eps = tbErrorBoundEps(tb_factor_patches[patch_index].edge_sphere[e]);
    eps = edge_eps > eps ? edge_eps : eps;
  }
  if (!(eps > 0.0)) return top;
  precise float a = tb_factor_patches[patch_index].inner_ab.x / eps;
  precise float b = tb_factor_patches[patch_index].inner_ab.y / eps;
  float best_n = top;
  float best = uintBitsToFloat(0x7f800000u);
  for (uint n = 1u; n <= uint(top); ++n) {
    if (!tbErrorBoundLevelAllowed(n, tb_factor.spacing)) continue;
    float du = 0.0, dv = 0.0, r2 = 0.0;
    for (uint e = 0u; e < edges; ++e) {
      const uint o = uint(outer[e]);
      const float eu = tbTransition(e, 0u, o, n), ev = tbTransition(e, 1u, o, n);
      const float er = tbTransition(e, 2u, o, n);
      du = eu > du ? eu : du;
      dv = ev > dv ? ev : dv;
      r2 = er > r2 ? er : r2;
    }
    precise float box = a * du * du + b * dv * dv;
    precise float circle = 4.0 * (a > b ? a : b) * r2;
    const float need = box < circle ? box : circle;
    if (need <= 1.0) return float(n);
    if (need < best) {
      best = need;
      best_n = float(n);
    }
  }
  return best_n;
}

// This patch's levels from the policy (outer[0..3], inner[0..1]; triangles leave outer[3]
// and inner[1] at 0). Call from one invocation.
void tbPolicyLevels(uint patch_index, out float outer[4], out float inner[2]) {
  const bool quad = tb_factor.domain == 1u;
  const uint n = quad ? 4u : 3u;
  vec3 p[4];
  vec3 nrm[4];
  if (tb_factor.policy == kTbPolicyErrorBound) {
    // Edges from their shared records, the inside against the tessellation they make,
    // transition rings included (factor_policy.cpp, errorBoundLevels).
    const float top = tbClampFactor(64.0, tb_factor.spacing);
    outer = float[4](0.0, 0.0, 0.0, 0.0);
    for (uint j = 0u; j < n; ++j) {
      outer[j] = tbErrorBoundEdge(tb_factor_patches[patch_index].edge_sphere[j],
                                  tb_factor_patches[patch_index].edge_m[j], n, top);
    }
    const float inside = tbErrorBoundInside(patch_index, outer, n, top);
    inner = float[2](inside, quad ? inside : 0.0);
    return;
  }
  for (uint c = 0u; c < 4u; ++c) {
    p[c] = tb_factor_patches[patch_index].corner[c].position.xyz;
    nrm[c] = tb_factor_patches[patch_index].corner[c].normal.xyz;
  }
  // gl_TessLevelOuter[j] is the edge between corners (start, end): quad (u = 0, v = 0,
  // u = 1, v = 1) = (3,0), (0,1), (1,2), (2,3); triangle (u = 0, v = 0, w = 0) = (1,2),
  // (2,0), (0,1).
  float raw[4];
  for (uint j = 0u; j < n; ++j) {
    const uint start = quad ? (j + 3u) % 4u : (j + 1u) % 3u;
    const uint end = quad ? j : (j + 2u) % 3u;
    raw[j] = tbEdgeFactor(p[start], p[end], nrm[start], nrm[end]);
  }
  if (!quad) raw[3] = 0.0;
  outer = float[4](0.0, 0.0, 0.0, 0.0);
  float inside = 0.0;
  bool culled = false;
  for (uint j = 0u; j < n; ++j) culled = culled || !(raw[j] > 0.0);
  if (!culled) {
    float cleaned[4];
    for (uint j = 0u; j < 4u; ++j) {
      cleaned[j] = tbCleanupFactor(raw[j]);
      if (j < n) outer[j] = tbClampFactor(tbRoundUpFactor(cleaned[j], tb_factor.spacing),
                                          tb_factor.spacing);
    }
    // Quads reduce (v = 0, v = 1, u = 0, u = 1), as ProcessQuadTessFactors* does.
    float e[4] = quad ? float[4](cleaned[1], cleaned[3], cleaned[0], cleaned[2]) : cleaned;
    inside = tbInsideFactor(tb_factor.reduction, e, n, tb_factor.spacing);
  }
  inner = float[2](inside, quad ? inside : 0.0);
}

// Writes the levels a TCS chose (policy and culling) to the read-back buffer.
void tbWriteBackLevels(uint patch_index, float outer[4], float inner[2]) {
  tb_factor_out[patch_index * 2u] = floatBitsToUint(vec4(outer[0], outer[1], outer[2], outer[3]));
  tb_factor_out[patch_index * 2u + 1u] =
      uvec4(floatBitsToUint(inner[0]), floatBitsToUint(inner[1]), 0u, 0u);
}

#endif
