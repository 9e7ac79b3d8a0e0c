// osd_adaptive's own evaluation of one Far sub-patch, templated on the scalar: in float the
// CPU twin of shaders/osd_adaptive/osd_adaptive.tese, operation for operation (keep the two
// in step); in double it checks the float path against Far's EvaluateBasis. Written from
// OpenSubdiv's conventions (far/patchParam.h, far/patchDescriptor.h): sub-patch domains,
// point orders, boundary bits and phantom rows are in docs/derivations/parameterisation.md.
// Derivatives are in the local (s, t), 2^d times smaller than the base face's (u, v).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/mesh/vec.h"

namespace tb::osd_adaptive {

// Most points of a sub-patch: a Gregory basis end cap.
constexpr int kMaxSubPatchPoints = 20;

// One Far patch of a base face as the GPU keeps it (8 bytes): its place in the face and
// kind in `packed`, its control points at point_indices[first_index ...].
struct SubPatchWords {
  uint32_t packed = 0;       // U (bits 0-9), V (10-19), depth (20-23), boundary (24-27),
                             // Gregory basis end cap (bit 28)
  uint32_t first_index = 0;  // into the concatenated control-point indices
};

inline uint32_t packSubPatch(uint32_t u_offset, uint32_t v_offset, uint32_t depth,
                             uint32_t boundary, bool gregory) {
  return (u_offset & 0x3ffu) | (v_offset & 0x3ffu) << 10 | (depth & 0xfu) << 20 |
         (boundary & 0xfu) << 24 | (gregory ? 1u : 0u) << 28;
}
inline uint32_t subPatchU(uint32_t packed) { return packed & 0x3ffu; }
inline uint32_t subPatchV(uint32_t packed) { return packed >> 10 & 0x3ffu; }
inline uint32_t subPatchDepth(uint32_t packed) { return packed >> 20 & 0xfu; }
inline uint32_t subPatchBoundary(uint32_t packed) { return packed >> 24 & 0xfu; }
inline bool subPatchIsGregory(uint32_t packed) { return (packed >> 28 & 1u) != 0; }
inline int subPatchPointCount(uint32_t packed) { return subPatchIsGregory(packed) ? 20 : 16; }

// The cell (0 .. 2^depth - 1) of a base-face parameter x in [0, 1] at `depth`: floor(x 2^d),
// x = 1 in the last cell; the rule of Far::PatchMap (a parameter on a cell border belongs to
// the upper cell). x 2^d is exact in float and double.
template <class T>
T subPatchCell(T x, T scale) {
  using std::floor;
  using std::min;
  return min(floor(x * scale), scale - T(1));
}

// True when the sub-patch `packed` covers base-face (u, v), both in [0, 1].
template <class T>
bool subPatchCovers(uint32_t packed, T u, T v) {
  const T scale = T(uint32_t(1) << subPatchDepth(packed));
  return subPatchCell(u, scale) == T(subPatchU(packed)) &&
         subPatchCell(v, scale) == T(subPatchV(packed));
}

// Local (s, t) of base-face (u, v) in the sub-patch: exact in float and double.
template <class T>
mesh::Vec2T<T> subPatchLocal(uint32_t packed, T u, T v) {
  const T scale = T(uint32_t(1) << subPatchDepth(packed));
  return {u * scale - T(subPatchU(packed)), v * scale - T(subPatchV(packed))};
}

// 1/6, the float nearest to it written out so GLSL and C++ parse the same value.
template <class T>
constexpr T kSixth = T(0.1666666716337204);
template <>
constexpr double kSixth<double> = 1.0 / 6.0;

// Uniform cubic B-spline basis at x and its derivative, written symmetric in x and 1 - x:
// b1(x) = b2(1 - x) = (x^2 (3x - 6) + 4) / 6.
template <class T>
void bsplineCurve(T x, T b[4], T d[4]) {
  const T y = T(1) - x;
  const T x2 = x * x, y2 = y * y;
  b[0] = y2 * y * kSixth<T>;
  b[1] = (x2 * (x * T(3) - T(6)) + T(4)) * kSixth<T>;
  b[2] = (y2 * (y * T(3) - T(6)) + T(4)) * kSixth<T>;
  b[3] = x2 * x * kSixth<T>;
  d[0] = -(y2 * T(0.5));
  d[1] = x * (x * T(1.5) - T(2));
  d[2] = -(y * (y * T(1.5) - T(2)));
  d[3] = x2 * T(0.5);
}

// A boundary edge's phantom point p0 = 2 p1 - p2 (p0 the outer one), folded into the
// curve's weights: w1 += 2 w0, w2 -= w0, w0 = 0 (and the same for the derivatives).
template <class T>
void foldPhantom(T w[4], int outer, int next, int after) {
  w[next] = w[next] + w[outer] * T(2);
  w[after] = w[after] - w[outer];
  w[outer] = T(0);
}

// Cubic Bernstein basis at x and its derivative.
template <class T>
void bezierCurve(T x, T b[4], T d[4]) {
  const T y = T(1) - x;
  const T x2 = x * x, y2 = y * y;
  b[0] = y2 * y;
  b[1] = x * y2 * T(3);
  b[2] = x2 * y * T(3);
  b[3] = x2 * x;
  d[0] = -(y2 * T(3));
  d[1] = y * (y - x * T(2)) * T(3);
  d[2] = x * (y * T(2) - x) * T(3);
  d[3] = x2 * T(3);
}

// The 4x4 Bézier net of a Gregory basis end cap: the 12 boundary Bézier points are Gregory
// points (point, column, row); each of the 4 interior ones, at (kGregoryInteriorColumn[c],
// kGregoryInteriorRow[c]), blends corner c's F+ and F-.
inline constexpr int kGregoryBoundaryNet[12][3] = {{0, 0, 0},  {1, 1, 0},  {7, 2, 0},  {5, 3, 0},
                                                   {2, 0, 1},  {6, 3, 1},  {16, 0, 2}, {12, 3, 2},
                                                   {15, 0, 3}, {17, 1, 3}, {11, 2, 3}, {10, 3, 3}};
inline constexpr int kGregoryInteriorColumn[4] = {1, 2, 2, 1};
inline constexpr int kGregoryInteriorRow[4] = {1, 1, 2, 2};

// Weights of one sub-patch's points for the position (w), d/ds (ws) and d/dt (wt) at local
// (s, t); returns the point count (16 or 20).
template <class T>
int subPatchWeights(uint32_t packed, T s, T t, T w[kMaxSubPatchPoints], T ws[kMaxSubPatchPoints],
                    T wt[kMaxSubPatchPoints]) {
  T bs[4], ds[4], bt[4], dt[4];
  if (!subPatchIsGregory(packed)) {
    bsplineCurve(s, bs, ds);
    bsplineCurve(t, bt, dt);
    const uint32_t boundary = subPatchBoundary(packed);
    if ((boundary & 1u) != 0) {  // t = 0: row 0 is the phantom
      foldPhantom(bt, 0, 1, 2);
      foldPhantom(dt, 0, 1, 2);
    }
    if ((boundary & 2u) != 0) {  // s = 1: column 3
      foldPhantom(bs, 3, 2, 1);
      foldPhantom(ds, 3, 2, 1);
    }
    if ((boundary & 4u) != 0) {  // t = 1: row 3
      foldPhantom(bt, 3, 2, 1);
      foldPhantom(dt, 3, 2, 1);
    }
    if ((boundary & 8u) != 0) {  // s = 0: column 0
      foldPhantom(bs, 0, 1, 2);
      foldPhantom(ds, 0, 1, 2);
    }
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        w[4 * j + i] = bs[i] * bt[j];
        ws[4 * j + i] = ds[i] * bt[j];
        wt[4 * j + i] = bs[i] * dt[j];
      }
    }
    return 16;
  }
  bezierCurve(s, bs, ds);
  bezierCurve(t, bt, dt);
  for (const auto& [point, column, row] : kGregoryBoundaryNet) {
    w[point] = bs[column] * bt[row];
    ws[point] = ds[column] * bt[row];
    wt[point] = bs[column] * dt[row];
  }
  // Corner c's interior point is (g+ F+ + g- F-) / (g+ + g-), g+ vanishing on the edge of E-
  // and g- on the edge of E+: corner 0 (s, t), 1 (t, 1 - s), 2 (1 - s, 1 - t), 3 (1 - t, s).
  // r+ = g+ / D, r- = g- / D, D = g+ + g-; at the corner itself (D = 0) both are 1/2 (the
  // Bézier weight is 0 there). dr+/ds = (g+_s r- - g-_s r+) / D, and the same in t; r- = 1 - r+.
  const T is = T(1) - s, it = T(1) - t;
  const T g_plus[4] = {s, t, is, it};
  const T g_minus[4] = {t, is, it, s};
  for (int c = 0; c < 4; ++c) {
    const T sum = g_plus[c] + g_minus[c];
    T r_plus = T(0.5), r_minus = T(0.5), rs = T(0), rt = T(0);
    if (sum > T(0)) {
      const T inverse = T(1) / sum;
      r_plus = g_plus[c] * inverse;
      r_minus = g_minus[c] * inverse;
      // (g+_s, g+_t, g-_s, g-_t) per corner: (1, 0, 0, 1), (0, 1, -1, 0), (-1, 0, 0, -1),
      // (0, -1, 1, 0).
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
    const T b = bs[kGregoryInteriorColumn[c]] * bt[kGregoryInteriorRow[c]];
    const T b_s = ds[kGregoryInteriorColumn[c]] * bt[kGregoryInteriorRow[c]];
    const T b_t = bs[kGregoryInteriorColumn[c]] * dt[kGregoryInteriorRow[c]];
    const int f_plus = 5 * c + 3, f_minus = 5 * c + 4;
    w[f_plus] = b * r_plus;
    w[f_minus] = b * r_minus;
    ws[f_plus] = b_s * r_plus + b * rs;
    ws[f_minus] = b_s * r_minus - b * rs;
    wt[f_plus] = b_t * r_plus + b * rt;
    wt[f_minus] = b_t * r_minus - b * rt;
  }
  return 20;
}

}  // namespace tb::osd_adaptive
