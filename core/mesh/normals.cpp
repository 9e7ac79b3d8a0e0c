#include "core/mesh/normals.h"

#include <algorithm>
#include <cmath>

namespace tb::mesh {

void assignAngleWeightedNormals(Mesh* mesh) {
  std::vector<Vec3d> sums(mesh->positions.size());
  for (size_t f = 0; f < mesh->faceCount(); ++f) {
    const auto face = mesh->facePositions(f);
    const size_t n = face.size();
    for (size_t k = 0; k < n; ++k) {
      const Vec3d& corner = mesh->positions[face[k]];
      const Vec3d to_next = mesh->positions[face[(k + 1) % n]] - corner;
      const Vec3d to_prev = mesh->positions[face[(k + n - 1) % n]] - corner;
      const Vec3d normal = normalize(cross(to_next, to_prev));
      const double len_product = length(to_next) * length(to_prev);
      if (!(len_product > 0)) continue;
      const double cosine = std::clamp(dot(to_next, to_prev) / len_product, -1.0, 1.0);
      sums[face[k]] = sums[face[k]] + normal * std::acos(cosine);
    }
  }
  mesh->normals.resize(sums.size());
  std::transform(sums.begin(), sums.end(), mesh->normals.begin(),
                 [](const Vec3d& sum) { return normalize(sum); });
  for (size_t c = 0; c < mesh->corner_positions.size(); ++c) {
    mesh->corner_normals[c] = int32_t(mesh->corner_positions[c]);
  }
  mesh->normals_computed = true;
}

}  // namespace tb::mesh
