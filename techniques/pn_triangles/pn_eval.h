// Curved PN triangles (Vlachos, Peters, Boyd, Mitchell, I3D 2001), templated on the
// scalar so one operation order runs in float (as shaders/pn_triangles/ does), in
// double and with CountingScalar. The shaders mirror these functions line by line.
//
// Corners are given in a canonical order (labels 0 < 1 < 2, sorted by position; see
// pn_build.h), so the terms of a shared edge are computed and summed identically from
// both faces (docs/ARCHITECTURE.md §5 rule 1 and 2).
#pragma once

#include <array>

#include "core/mesh/vec.h"
#include "techniques/common/triangle_records.h"  // kEdgeEnds

namespace tb::pn_triangles {

template <class T>
struct PnInput {
  std::array<mesh::Vec3T<T>, 3> position;  // P_i, canonical order
  std::array<mesh::Vec3T<T>, 3> normal;    // unit shading normals N_i (the normal patch)
  // Unit normals that build edge e's geometry control point at end k (0: the first
  // label of the edge): the shading normal, a geometry normal (seed 003) or, for
  // PN-AEN, this face's (own) and the neighbour's (other) normal at that position.
  std::array<std::array<mesh::Vec3T<T>, 2>, 3> edge_own;
  std::array<std::array<mesh::Vec3T<T>, 2>, 3> edge_other;
  std::array<T, 3> edge_scale{T(1), T(1), T(1)};  // multiplies w_ij (0: straight edge)
  bool aen = false;                               // average own and other (McDonald & Kilgard 2010)
  bool use_scale = false;                         // apply edge_scale (boundary flags, rounding)
};

template <class T>
struct PnControl {
  std::array<mesh::Vec3T<T>, 3> corner;               // b300, b030, b003 (canonical labels)
  std::array<std::array<mesh::Vec3T<T>, 2>, 3> edge;  // edge e: point near its first, second end
  mesh::Vec3T<T> center;                              // b111
  std::array<mesh::Vec3T<T>, 3> corner_normal;        // n200, n020, n002
  std::array<mesh::Vec3T<T>, 3> edge_normal;          // n110 of edge e
};

template <class T>
struct PnPoint {
  mesh::Vec3T<T> position;
  mesh::Vec3T<T> normal;
};

// Left to right, as shaders/common/float_order.glsl tbDot.
template <class T>
T dotInOrder(const mesh::Vec3T<T>& a, const mesh::Vec3T<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// v * (1 / |v|), zero stays zero (as vec.h normalize and float_order.glsl tbNormalize).
template <class T>
mesh::Vec3T<T> normalizeInOrder(const mesh::Vec3T<T>& v) {
  using std::sqrt;
  const T len = sqrt(dotInOrder(v, v));
  if (!(len > T(0))) return v;
  return v * (T(1) / len);
}

// Paper §3.1: b_iij = (2 P_i + P_j - w_ij N_i) / 3 with w_ij = (P_j - P_i)·N_i. The
// straight-edge point (scale 0) is (2 P_i + P_j) / 3.
template <class T>
mesh::Vec3T<T> edgePoint(const mesh::Vec3T<T>& pi, const mesh::Vec3T<T>& pj,
                         const mesh::Vec3T<T>& ni, const T& scale, bool use_scale) {
  T w = dotInOrder(pj - pi, ni);
  if (use_scale) w = w * scale;
  return ((pi * T(2) + pj) - ni * w) * T(1.0 / 3.0);
}

template <class T>
PnControl<T> computeControl(const PnInput<T>& in) {
  PnControl<T> c;
  for (int i = 0; i < 3; ++i) {
    c.corner[i] = in.position[i];
    c.corner_normal[i] = in.normal[i];
  }
  for (int e = 0; e < 3; ++e) {
    for (int end = 0; end < 2; ++end) {
      const int i = techniques::kEdgeEnds[e][end], j = techniques::kEdgeEnds[e][1 - end];
      mesh::Vec3T<T> point = edgePoint(in.position[i], in.position[j], in.edge_own[e][end],
                                       in.edge_scale[e], in.use_scale);
      if (in.aen) {
        // PN-AEN: the mean of both faces' points; a + b is commutative in IEEE
        // arithmetic, so the neighbour gets the same bits.
        const mesh::Vec3T<T> other = edgePoint(
            in.position[i], in.position[j], in.edge_other[e][end], in.edge_scale[e], in.use_scale);
        point = (point + other) * T(0.5);
      }
      c.edge[e][end] = point;
    }
    // Paper §3.2: n_ij = normalize(N_i + N_j - v_ij (P_j - P_i)),
    // v_ij = 2 (P_j - P_i)·(N_i + N_j) / ((P_j - P_i)·(P_j - P_i)).
    const int i = techniques::kEdgeEnds[e][0], j = techniques::kEdgeEnds[e][1];
    const mesh::Vec3T<T> d = in.position[j] - in.position[i];
    const mesh::Vec3T<T> sum = in.normal[i] + in.normal[j];
    const T dd = dotInOrder(d, d);
    T v = T(0);
    if (dd > T(0)) v = (T(2) * dotInOrder(d, sum)) / dd;
    c.edge_normal[e] = normalizeInOrder(sum - d * v);
  }
  // Paper §3.1: b111 = E + (E - V) / 2, E the mean of the six edge points, V of the corners.
  const mesh::Vec3T<T> e_sum =
      ((((c.edge[0][0] + c.edge[0][1]) + c.edge[1][0]) + c.edge[1][1]) + c.edge[2][0]) +
      c.edge[2][1];
  const mesh::Vec3T<T> mean_edge = e_sum * T(1.0 / 6.0);
  const mesh::Vec3T<T> mean_corner =
      ((in.position[0] + in.position[1]) + in.position[2]) * T(1.0 / 3.0);
  c.center = mean_edge + (mean_edge - mean_corner) * T(0.5);
  return c;
}

// The barycentric products both patches use: aa, bb, cc, ab, ac, bc.
template <class T>
std::array<T, 6> pnProducts(const std::array<T, 3>& w) {
  return {w[0] * w[0], w[1] * w[1], w[2] * w[2], w[0] * w[1], w[0] * w[2], w[1] * w[2]};
}

// The cubic geometry patch from the products of pnProducts.
template <class T>
mesh::Vec3T<T> controlPosition(const PnControl<T>& c, const std::array<T, 3>& w,
                               const std::array<T, 6>& q) {
  const T aa = q[0], bb = q[1], cc = q[2], ab = q[3], ac = q[4], bc = q[5];
  mesh::Vec3T<T> p =
      (c.corner[0] * (aa * w[0]) + c.corner[1] * (bb * w[1])) + c.corner[2] * (cc * w[2]);
  const std::array<T, 3> pair = {ab, ac, bc};
  for (int e = 0; e < 3; ++e) {
    const int i = techniques::kEdgeEnds[e][0], j = techniques::kEdgeEnds[e][1];
    p = p + (c.edge[e][0] * w[i] + c.edge[e][1] * w[j]) * (pair[e] * T(3));
  }
  return p + c.center * ((ab * w[2]) * T(6));
}

// The geometry patch alone: evaluateControl's position, bit for bit.
template <class T>
mesh::Vec3T<T> evaluateControlPosition(const PnControl<T>& c, const std::array<T, 3>& w) {
  return controlPosition(c, w, pnProducts(w));
}

// The cubic geometry patch and quadratic normal patch at canonical barycentric weights
// (a, b, c) of labels 0, 1, 2. Grouped as corners, then edges (0,1), (0,2), (1,2), then
// the centre: on an edge the third weight is exactly 0, every term that holds it is ±0,
// and the remaining terms are summed in the same order from both faces.
template <class T>
PnPoint<T> evaluateControl(const PnControl<T>& c, const std::array<T, 3>& w) {
  const std::array<T, 6> q = pnProducts(w);
  const mesh::Vec3T<T> p = controlPosition(c, w, q);
  const T aa = q[0], bb = q[1], cc = q[2], ab = q[3], ac = q[4], bc = q[5];
  // Paper §3.2: the normal patch has no binomial factors.
  mesh::Vec3T<T> n = (c.corner_normal[0] * aa + c.corner_normal[1] * bb) + c.corner_normal[2] * cc;
  n = ((n + c.edge_normal[0] * ab) + c.edge_normal[1] * ac) + c.edge_normal[2] * bc;
  return {p, normalizeInOrder(n)};
}

}  // namespace tb::pn_triangles
