// Seed 003's per-edge Phong tessellation (Lost Planet 2): Phong tessellation rebuilt on
// the triangle's edges so that per-edge normals (geometry normals on flagged edges) can
// apply and a shared edge depends on that edge's data alone.
//
// The seed defines an inscribed triangle whose corners are the point's closest points
// q_e on the three edges, the point's barycentric coordinates (U', V', W') in it, and
// takes each q_e's tangent-plane projection by linear interpolation along its edge. Here
// q_e is the point of edge (i, j) seen from the opposite corner, t = (w_i, w_j) / (w_i +
// w_j), and the inscribed-triangle weights are U'_ij = w_i w_j / (w0 w1 + w0 w2 + w1 w2),
// which are exactly 1 and 0 on an edge (x / x = 1 in IEEE arithmetic), so the edge curve is
// bitwise the same from both faces. The flat point itself stays the linear interpolant
// (α = 0 is the flat triangle, as in Boubekeur & Alexa eq. 4); only the offset is
// rebuilt per edge:
//   p* = p - α Σ_e U'_e Σ_{k∈e} t_k ((q_e - p_k)·n_k^e) n_k^e.
// Corners are in a canonical order (labels sorted by position), as evaluatePhongInOrder.
#pragma once

#include <array>

#include "core/mesh/vec.h"
#include "techniques/phong/phong_eval.h"

namespace tb::phong {

inline constexpr int kPhongEdgeEnds[3][2] = {{0, 1}, {0, 2}, {1, 2}};

template <class T>
struct PhongEdgeTriangle {
  std::array<mesh::Vec3T<T>, 3> position;                    // canonical order
  std::array<mesh::Vec3T<T>, 3> normal;                      // unit shading normals
  std::array<std::array<mesh::Vec3T<T>, 2>, 3> edge_normal;  // unit normal of edge e at end k
};

template <class T>
PhongPoint<T> evaluatePhongEdge(const PhongEdgeTriangle<T>& tri, const std::array<T, 3>& w,
                                T alpha) {
  PhongPoint<T> result;
  const mesh::Vec3T<T> flat =
      tri.position[0] * w[0] + tri.position[1] * w[1] + tri.position[2] * w[2];
  result.normal = normalize(tri.normal[0] * w[0] + tri.normal[1] * w[1] + tri.normal[2] * w[2]);
  const T denominator = (w[0] * w[1] + w[0] * w[2]) + w[1] * w[2];
  result.position = flat;
  if (!(denominator > T(0))) return result;  // a corner: p* = p_k
  mesh::Vec3T<T> offset{};
  for (int e = 0; e < 3; ++e) {
    const int i = kPhongEdgeEnds[e][0], j = kPhongEdgeEnds[e][1];
    const T sum = w[i] + w[j];
    if (!(sum > T(0))) continue;  // the opposite corner: U'_e = 0
    const T ti = w[i] / sum, tj = w[j] / sum;
    const mesh::Vec3T<T> q = tri.position[i] * ti + tri.position[j] * tj;
    const mesh::Vec3T<T>& ni = tri.edge_normal[e][0];
    const mesh::Vec3T<T>& nj = tri.edge_normal[e][1];
    const mesh::Vec3T<T> edge_offset =
        ni * (ti * dot(q - tri.position[i], ni)) + nj * (tj * dot(q - tri.position[j], nj));
    offset = offset + edge_offset * ((w[i] * w[j]) / denominator);
  }
  result.position = flat - offset * alpha;
  return result;
}

}  // namespace tb::phong
