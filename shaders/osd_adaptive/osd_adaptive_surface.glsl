// osd_adaptive's TES declarations, shared with the compute path (osd_adaptive.comp); the
// body is osd_adaptive_evaluate.glsl. OpenSubdiv Far's feature-adaptive patches of one base
// face: finds the Far patch (sub-patch) covering gl_TessCoord, maps it to the sub-patch's local (s, t),
// weighs the sub-patch's points (bicubic B-spline with Far's boundary rule, or a Gregory
// basis end cap) and sums them. techniques/osd_adaptive/osd_basis.h and evaluateFloat in
// osd_adaptive.cpp are the CPU twin, operation for operation, every value `precise` (NIR
// neither reassociates nor contracts); keep them in step.
//   binding 1  points, vec4 each: every refined level, then the end caps' local points
//   binding 2  per base face (first sub-patch, sub-patch count)
//   binding 3  per sub-patch (packed, first index): packed = U (bits 0-9), V (10-19),
//              depth (20-23), boundary edges (24-27), Gregory basis end cap (bit 28)
//   binding 4  control-point indices into binding 1, 16 or 20 per sub-patch
#ifndef TB_OSD_ADAPTIVE_SURFACE_GLSL
#define TB_OSD_ADAPTIVE_SURFACE_GLSL

#include "osd_layout.h"
layout(std430, set = 0, binding = TB_OSD_BINDING_POINTS) readonly buffer Points {
  vec4 points[];
};
layout(std430, set = 0, binding = TB_OSD_BINDING_FACE_RANGES) readonly buffer FaceRanges {
  uvec2 face_ranges[];
};
layout(std430, set = 0, binding = TB_OSD_BINDING_SUB_PATCHES) readonly buffer SubPatches {
  uvec2 sub_patches[];
};
layout(std430, set = 0, binding = TB_OSD_BINDING_POINT_INDICES) readonly buffer PointIndices {
  uint point_indices[];
};

// The float nearest 1/6 (osd_basis.h kSixth).
const float kSixth = 0.1666666716337204;

uint subDepth(uint packed) { return (packed >> 20u) & 15u; }

// floor(x 2^d), x = 1 in the last cell (osd_basis.h subPatchCell).
float cellOf(float x, float scale) {
  precise float cell = min(floor(x * scale), scale - 1.0);
  return cell;
}

void bsplineCurve(float x, out float b[4], out float d[4]) {
  precise float y = 1.0 - x;
  precise float x2 = x * x, y2 = y * y;
  precise float b0 = y2 * y * kSixth;
  precise float b1 = (x2 * (x * 3.0 - 6.0) + 4.0) * kSixth;
  precise float b2 = (y2 * (y * 3.0 - 6.0) + 4.0) * kSixth;
  precise float b3 = x2 * x * kSixth;
  precise float d0 = -(y2 * 0.5);
  precise float d1 = x * (x * 1.5 - 2.0);
  precise float d2 = -(y * (y * 1.5 - 2.0));
  precise float d3 = x2 * 0.5;
  b = float[4](b0, b1, b2, b3);
  d = float[4](d0, d1, d2, d3);
}

// Phantom point p_outer = 2 p_next - p_after folded into the weights (osd_basis.h).
void foldPhantom(inout float w[4], int outer, int next, int after) {
  precise float w_next = w[next] + w[outer] * 2.0;
  precise float w_after = w[after] - w[outer];
  w[next] = w_next;
  w[after] = w_after;
  w[outer] = 0.0;
}

void bezierCurve(float x, out float b[4], out float d[4]) {
  precise float y = 1.0 - x;
  precise float x2 = x * x, y2 = y * y;
  precise float b0 = y2 * y;
  precise float b1 = x * y2 * 3.0;
  precise float b2 = x2 * y * 3.0;
  precise float b3 = x2 * x;
  precise float d0 = -(y2 * 3.0);
  precise float d1 = y * (y - x * 2.0) * 3.0;
  precise float d2 = x * (y * 2.0 - x) * 3.0;
  precise float d3 = x2 * 3.0;
  b = float[4](b0, b1, b2, b3);
  d = float[4](d0, d1, d2, d3);
}

// Gregory point -> Bézier net (column, row) of the 12 boundary points.
const int kGregoryBoundaryPoint[12] = int[](0, 1, 7, 5, 2, 6, 16, 12, 15, 17, 11, 10);
const int kGregoryBoundaryColumn[12] = int[](0, 1, 2, 3, 0, 3, 0, 3, 0, 1, 2, 3);
const int kGregoryBoundaryRow[12] = int[](0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 3, 3);
// Bézier net position of corner c's interior point.
const int kInteriorColumn[4] = int[](1, 2, 2, 1);
const int kInteriorRow[4] = int[](1, 1, 2, 2);

// Weights of the sub-patch's points for position, d/ds and d/dt (osd_basis.h
// subPatchWeights); returns the point count.
int subPatchWeights(uint packed, float s, float t, out float w[20], out float ws[20],
                    out float wt[20]) {
  float bs[4], ds[4], bt[4], dt[4];
  if (((packed >> 28u) & 1u) == 0u) {
    bsplineCurve(s, bs, ds);
    bsplineCurve(t, bt, dt);
    const uint boundary = (packed >> 24u) & 15u;
    if ((boundary & 1u) != 0u) { foldPhantom(bt, 0, 1, 2); foldPhantom(dt, 0, 1, 2); }
    if ((boundary & 2u) != 0u) { foldPhantom(bs, 3, 2, 1); foldPhantom(ds, 3, 2, 1); }
    if ((boundary & 4u) != 0u) { foldPhantom(bt, 3, 2, 1); foldPhantom(dt, 3, 2, 1); }
    if ((boundary & 8u) != 0u) { foldPhantom(bs, 0, 1, 2); foldPhantom(ds, 0, 1, 2); }
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        precise float wk = bs[i] * bt[j];
        precise float wsk = ds[i] * bt[j];
        precise float wtk = bs[i] * dt[j];
        w[4 * j + i] = wk;
        ws[4 * j + i] = wsk;
        wt[4 * j + i] = wtk;
      }
    }
    return 16;
  }
  bezierCurve(s, bs, ds);
  bezierCurve(t, bt, dt);
  for (int k = 0; k < 12; ++k) {
    const int column = kGregoryBoundaryColumn[k], row = kGregoryBoundaryRow[k];
    precise float wk = bs[column] * bt[row];
    precise float wsk = ds[column] * bt[row];
    precise float wtk = bs[column] * dt[row];
    w[kGregoryBoundaryPoint[k]] = wk;
    ws[kGregoryBoundaryPoint[k]] = wsk;
    wt[kGregoryBoundaryPoint[k]] = wtk;
  }
  // Corner c's interior point (g+ F+ + g- F-) / (g+ + g-) (osd_basis.h).
  precise float is = 1.0 - s, it = 1.0 - t;
  const float g_plus[4] = float[4](s, t, is, it);
  const float g_minus[4] = float[4](t, is, it, s);
  for (int c = 0; c < 4; ++c) {
    precise float sum = g_plus[c] + g_minus[c];
    precise float r_plus = 0.5, r_minus = 0.5, rs = 0.0, rt = 0.0;
    if (sum > 0.0) {
      precise float inverse = 1.0 / sum;
      r_plus = g_plus[c] * inverse;
      r_minus = g_minus[c] * inverse;
      if (c == 0) {
        rs = r_minus * inverse;
        rt = -(r_plus * inverse);
      } else if (c == 1) {
        rs = r_plus * inverse;
        rt = r_minus * inverse;
      } else if (c == 2) {
        rs = -(r_minus * inverse);
        rt = r_plus * inverse;
      } else {
        rs = -(r_plus * inverse);
        rt = -(r_minus * inverse);
      }
    }
    const int column = kInteriorColumn[c], row = kInteriorRow[c];
    precise float b = bs[column] * bt[row];
    precise float b_s = ds[column] * bt[row];
    precise float b_t = bs[column] * dt[row];
    precise float w_plus = b * r_plus, w_minus = b * r_minus;
    precise float ws_plus = b_s * r_plus + b * rs, ws_minus = b_s * r_minus - b * rs;
    precise float wt_plus = b_t * r_plus + b * rt, wt_minus = b_t * r_minus - b * rt;
    w[5 * c + 3] = w_plus;
    w[5 * c + 4] = w_minus;
    ws[5 * c + 3] = ws_plus;
    ws[5 * c + 4] = ws_minus;
    wt[5 * c + 3] = wt_plus;
    wt[5 * c + 4] = wt_minus;
  }
  return 20;
}

#endif
