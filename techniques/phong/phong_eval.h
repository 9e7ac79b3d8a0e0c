// Phong tessellation (Boubekeur & Alexa, "Phong Tessellation", SIGGRAPH Asia 2008).
// Templated on the scalar so the same operation order runs in float (as the
// shader does), in double, and with a counting scalar for instruction counts.
#pragma once

#include <array>
#include <utility>

#include "core/mesh/vec.h"

namespace tb::phong {

template <class T>
struct PhongTriangle {
  std::array<mesh::Vec3T<T>, 3> position;  // corner positions p_i
  std::array<mesh::Vec3T<T>, 3> normal;    // unit corner normals n_i
};

template <class T>
struct PhongPoint {
  mesh::Vec3T<T> position;
  mesh::Vec3T<T> normal;  // normalised linear interpolation of the corner normals (paper §3)
};

// Paper eq. (3)-(4): p* = (1 - α) p + α Σ w_i π_i(p), with p = Σ w_i p_i the flat
// point and π_i(q) = q - ((q - p_i)·n_i) n_i its projection onto corner i's
// tangent plane. Written as p - α Σ w_i ((p - p_i)·n_i) n_i, which is the same
// surface with three fewer vector multiplies. α = 0 is the flat triangle; the
// paper recommends α = 3/4.
// Terms are summed in a canonical corner order (canonicalCornerOrder), so the
// result is a function of the corners as a set: rotating or mirroring a face,
// or meeting the same edge from the neighbouring face, sums the same terms in the
// same order (docs/ARCHITECTURE.md §5 rule 1).
template <class T>
PhongPoint<T> evaluatePhongInOrder(const PhongTriangle<T>& tri, const std::array<T, 3>& weight,
                                   T alpha) {
  const mesh::Vec3T<T> flat =
      tri.position[0] * weight[0] + tri.position[1] * weight[1] + tri.position[2] * weight[2];
  mesh::Vec3T<T> offset{};
  for (int i = 0; i < 3; ++i) {
    const T height = dot(flat - tri.position[i], tri.normal[i]);
    offset = offset + tri.normal[i] * (weight[i] * height);
  }
  PhongPoint<T> result;
  result.position = flat - offset * alpha;
  result.normal =
      normalize(tri.normal[0] * weight[0] + tri.normal[1] * weight[1] + tri.normal[2] * weight[2]);
  return result;
}

// True when corner a sorts before corner b: lexicographic on position, then normal.
template <class T>
bool cornerPrecedes(const PhongTriangle<T>& tri, int a, int b) {
  for (int k = 0; k < 3; ++k) {
    if (tri.position[a][k] != tri.position[b][k]) return tri.position[a][k] < tri.position[b][k];
  }
  for (int k = 0; k < 3; ++k) {
    if (tri.normal[a][k] != tri.normal[b][k]) return tri.normal[a][k] < tri.normal[b][k];
  }
  return false;
}

// The corner order evaluatePhong sums in: sorted by position, which both faces
// of a shared edge see identically, even where the mesh duplicates positions.
template <class T>
std::array<int, 3> canonicalCornerOrder(const PhongTriangle<T>& tri) {
  std::array<int, 3> order{0, 1, 2};
  if (cornerPrecedes(tri, order[1], order[0])) std::swap(order[0], order[1]);
  if (cornerPrecedes(tri, order[2], order[1])) std::swap(order[1], order[2]);
  if (cornerPrecedes(tri, order[1], order[0])) std::swap(order[0], order[1]);
  return order;
}

// The corners of `tri` in `order` (canonicalCornerOrder's): what evaluatePhong sums over.
template <class T>
PhongTriangle<T> reorderedTriangle(const PhongTriangle<T>& tri, const std::array<int, 3>& order) {
  PhongTriangle<T> sorted;
  for (int i = 0; i < 3; ++i) {
    sorted.position[i] = tri.position[order[i]];
    sorted.normal[i] = tri.normal[order[i]];
  }
  return sorted;
}

template <class T>
PhongPoint<T> evaluatePhong(const PhongTriangle<T>& tri, const std::array<T, 3>& weight, T alpha) {
  const std::array<int, 3> order = canonicalCornerOrder(tri);
  return evaluatePhongInOrder(reorderedTriangle(tri, order),
                              {weight[order[0]], weight[order[1]], weight[order[2]]}, alpha);
}

}  // namespace tb::phong
