// Phong tessellation (Boubekeur & Alexa, "Phong Tessellation", SIGGRAPH Asia 2008).
// Templated on the scalar so the same operation order runs in float (as the
// shader does), in double, and with a counting scalar for instruction counts.
#pragma once

#include <array>

#include "harness/mesh/vec.h"

namespace tb::phong {

template <class T>
struct PhongTriangle {
  std::array<Vec3T<T>, 3> position;  // corner positions p_i
  std::array<Vec3T<T>, 3> normal;    // unit corner normals n_i
};

template <class T>
struct PhongPoint {
  Vec3T<T> position;
  Vec3T<T> normal;  // normalised linear interpolation of the corner normals (paper §3)
};

// Paper eq. (3)-(4): p* = (1 - α) p + α Σ w_i π_i(p), with p = Σ w_i p_i the flat
// point and π_i(q) = q - ((q - p_i)·n_i) n_i its projection onto corner i's
// tangent plane. Written as p - α Σ w_i ((p - p_i)·n_i) n_i, which is the same
// surface with three fewer vector multiplies. α = 0 is the flat triangle; the
// paper recommends α = 3/4.
// Terms are summed in corner order 0, 1, 2: callers that need watertightness pass
// corners in a canonical order (see PhongPatches).
template <class T>
PhongPoint<T> evaluatePhong(const PhongTriangle<T>& tri, const std::array<T, 3>& weight, T alpha) {
  const Vec3T<T> flat =
      tri.position[0] * weight[0] + tri.position[1] * weight[1] + tri.position[2] * weight[2];
  Vec3T<T> offset{};
  for (int i = 0; i < 3; ++i) {
    const T height = dot(flat - tri.position[i], tri.normal[i]);
    offset = offset + tri.normal[i] * (weight[i] * height);
  }
  PhongPoint<T> result;
  result.position = flat - offset * alpha;
  result.normal = normalize(tri.normal[0] * weight[0] + tri.normal[1] * weight[1] +
                            tri.normal[2] * weight[2]);
  return result;
}

}  // namespace tb::phong
