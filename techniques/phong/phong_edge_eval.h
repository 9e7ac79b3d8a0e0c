// Seed 003's per-edge Phong tessellation (Lost Planet 2): Phong tessellation rebuilt on the
// triangle's edges so that per-edge normals can apply and a shared edge depends on that
// edge's data alone. The inscribed-triangle weights U'_ij = w_i w_j / (w0 w1 + w0 w2 + w1 w2)
// are exactly 1 and 0 on an edge, so the edge curve is bitwise the same from both faces;
// only the offset is rebuilt per edge (Boubekeur & Alexa eq. 4 for the flat point).
// Derivation: docs/derivations/normal_cones.md. Corners in canonical (position) order.
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
