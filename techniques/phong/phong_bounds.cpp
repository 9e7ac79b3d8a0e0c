#include "techniques/phong/phong_bounds.h"

#include "techniques/common/patch_bounds.h"

namespace tb::phong {

std::vector<mesh::Vec3d> phongQuadraticNet(const PhongTriangle<double>& tri, double alpha) {
  const auto& p = tri.position;
  const auto& n = tri.normal;
  const auto edgePoint = [&](int i, int j) {
    const double h_ij = dot(p[j] - p[i], n[i]), h_ji = dot(p[i] - p[j], n[j]);
    return (p[i] + p[j]) * 0.5 - (n[i] * h_ij + n[j] * h_ji) * (0.5 * alpha);
  };
  std::vector<mesh::Vec3d> net(techniques::triangleNetSize(2));
  const auto set = [&net](int i, int j, const mesh::Vec3d& point) {
    net[techniques::triangleNetSlot(2, i, j)] = point;
  };
  set(2, 0, p[0]);
  set(0, 2, p[1]);
  set(0, 0, p[2]);
  set(1, 1, edgePoint(0, 1));
  set(1, 0, edgePoint(0, 2));
  set(0, 1, edgePoint(1, 2));
  return net;
}

techniques::PatchCullBounds phongCullBounds(const PhongTriangle<double>& tri, double alpha) {
  techniques::PatchCullBounds bounds;
  bounds.hull = phongQuadraticNet(tri, alpha);
  bounds.normal_generators =
      techniques::withoutZeros(techniques::triangleNormalPatch(2, bounds.hull));
  bounds.bezier_net = bounds.hull;
  bounds.bezier_degree = 2;
  return bounds;
}

techniques::PatchCullBounds phongEdgeCullBounds(const PhongEdgeTriangle<double>& tri,
                                                double alpha) {
  const auto& p = tri.position;
  // The largest offset each edge can contribute, -α K_e / 4.
  std::array<mesh::Vec3d, 3> reach;
  for (int e = 0; e < 3; ++e) {
    const int i = kPhongEdgeEnds[e][0], j = kPhongEdgeEnds[e][1];
    const mesh::Vec3d& ni = tri.edge_normal[e][0];
    const mesh::Vec3d& nj = tri.edge_normal[e][1];
    const mesh::Vec3d k = ni * dot(p[j] - p[i], ni) + nj * dot(p[i] - p[j], nj);
    reach[e] = k * (-0.25 * alpha);
  }
  techniques::PatchCullBounds bounds;
  for (const mesh::Vec3d& corner : p) {
    for (int subset = 0; subset < 8; ++subset) {
      mesh::Vec3d point = corner;
      for (int e = 0; e < 3; ++e) {
        if ((subset >> e) & 1) point = point + reach[e];
      }
      bounds.hull.push_back(point);
    }
  }
  return bounds;
}

}  // namespace tb::phong
