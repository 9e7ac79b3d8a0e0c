#include "core/mesh/bounds.h"

#include <algorithm>

namespace tb::mesh {

Aabb boundsOf(const Mesh& mesh) {
  if (mesh.positions.empty()) return {{-1, -1, -1}, {1, 1, 1}};
  Aabb box{mesh.positions[0], mesh.positions[0]};
  for (const Vec3d& p : mesh.positions) {
    for (int i = 0; i < 3; ++i) {
      box.min[i] = std::min(box.min[i], p[i]);
      box.max[i] = std::max(box.max[i], p[i]);
    }
  }
  return box;
}

}  // namespace tb::mesh
