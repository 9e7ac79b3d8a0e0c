#include "techniques/common/patch_bounds.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tb::techniques {

std::array<mesh::Vec3d, 36> bicubicNormalPatch(const std::array<mesh::Vec3d, 16>& b) {
  QuadPoly<mesh::Vec3d> patch(3, 3);
  patch.c.assign(b.begin(), b.end());
  const QuadPoly<mesh::Vec3d> normal = derivativeU(patch) * derivativeV(patch);  // cross products
  std::array<mesh::Vec3d, 36> n;
  std::copy(normal.c.begin(), normal.c.end(), n.begin());
  return n;
}

std::vector<mesh::Vec3d> triangleNormalPatch(int degree, std::span<const mesh::Vec3d> net) {
  if (degree < 1 || int(net.size()) != triangleNetSize(degree)) {
    throw std::invalid_argument("triangleNormalPatch: a degree " + std::to_string(degree) +
                                " net has " + std::to_string(triangleNetSize(degree)) +
                                " points, got " + std::to_string(net.size()));
  }
  TrianglePoly<mesh::Vec3d> patch(degree);
  patch.c.assign(net.begin(), net.end());
  return (derivativeToward(patch, 1) * derivativeToward(patch, 2)).c;
}

std::vector<mesh::Vec3d> withoutZeros(std::span<const mesh::Vec3d> vectors) {
  std::vector<mesh::Vec3d> out;
  for (const mesh::Vec3d& v : vectors) {
    if (!(v.x == 0 && v.y == 0 && v.z == 0)) out.push_back(v);
  }
  return out;
}

std::vector<mesh::Vec3d> negated(std::vector<mesh::Vec3d> vectors) {
  for (mesh::Vec3d& v : vectors) v = mesh::Vec3d{} - v;
  return vectors;
}

}  // namespace tb::techniques
