// The PN triangle's cubic geometry patch as a Bézier net, for its culling bounds
// (PnPatches::cullBounds): the net is the hull, its quartic normal patch
// (techniques/common/patch_bounds.h) the normal generators.
#pragma once

#include <vector>

#include "techniques/common/patch_bounds.h"
#include "techniques/pn_triangles/pn_eval.h"

namespace tb::pn_triangles {

// b_ijk in patch_bounds.h's net order, i, j, k the powers of canonical labels 0, 1, 2's
// weights: the corners, the edge points of canonical edges (0,1), (0,2), (1,2) near their
// first and second end (evaluateControl's terms), the centre b111.
inline std::vector<mesh::Vec3d> cubicNet(const PnControl<double>& c) {
  std::vector<mesh::Vec3d> net(techniques::triangleNetSize(3));
  const auto set = [&net](int i, int j, const mesh::Vec3d& p) {
    net[techniques::triangleNetSlot(3, i, j)] = p;
  };
  set(3, 0, c.corner[0]);
  set(0, 3, c.corner[1]);
  set(0, 0, c.corner[2]);
  set(2, 1, c.edge[0][0]);  // b210
  set(1, 2, c.edge[0][1]);  // b120
  set(2, 0, c.edge[1][0]);  // b201
  set(1, 0, c.edge[1][1]);  // b102
  set(0, 2, c.edge[2][0]);  // b021
  set(0, 1, c.edge[2][1]);  // b012
  set(1, 1, c.center);
  return net;
}

}  // namespace tb::pn_triangles
