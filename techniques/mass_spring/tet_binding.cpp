#include "techniques/mass_spring/tet_binding.h"

#include <cmath>
#include <stdexcept>

namespace tb::mass_spring {

mesh::Vec3d virtualApex(const mesh::Vec3d& p0, const mesh::Vec3d& p1, const mesh::Vec3d& p2,
                        double volume) {
  const mesh::Vec3d c = (1.0 / 3.0) * (p0 + p1 + p2);
  const mesh::Vec3d n = cross(p1 - p0, p2 - p0);  // |n| = 2 area
  const double nn = dot(n, n);
  if (!(nn > 0)) return c;
  // height = 3V / area = 6V / |n|, along n / |n|: c + n * 6V / |n|^2.
  return c + (6 * volume / nn) * n;
}

TetBinding bindToTriangle(const std::vector<mesh::Vec3d>& rest, uint32_t v0, uint32_t v1,
                          uint32_t v2, const mesh::Vec3d& q, double apex_height) {
  TetBinding binding{v0, v1, v2, 0, 0, 0, 0};
  const mesh::Vec3d &p0 = rest[v0], &p1 = rest[v1], &p2 = rest[v2];
  const double area = 0.5 * length(cross(p1 - p0, p2 - p0));
  if (!(area > 0)) throw std::invalid_argument("bindToTriangle: degenerate triangle");
  binding.volume = area * apex_height / 3;
  const mesh::Vec3d p3 = virtualApex(p0, p1, p2, binding.volume);
  // q - p3 = w0 (p0 - p3) + w1 (p1 - p3) + w2 (p2 - p3): Cramer's rule.
  const mesh::Vec3d a = p0 - p3, b = p1 - p3, c = p2 - p3, r = q - p3;
  const double det = dot(a, cross(b, c));
  binding.w0 = dot(r, cross(b, c)) / det;
  binding.w1 = dot(a, cross(r, c)) / det;
  binding.w2 = dot(a, cross(b, r)) / det;
  return binding;
}

mesh::Vec3d drawVertex(const TetBinding& binding, const std::vector<mesh::Vec3d>& positions) {
  const mesh::Vec3d &p0 = positions[binding.v0], &p1 = positions[binding.v1],
                    &p2 = positions[binding.v2];
  const mesh::Vec3d p3 = virtualApex(p0, p1, p2, binding.volume);
  return binding.w0 * p0 + binding.w1 * p1 + binding.w2 * p2 +
         (1 - binding.w0 - binding.w1 - binding.w2) * p3;
}

mesh::Vec3f drawVertexFloat(const TetBinding& binding, const std::vector<mesh::Vec3f>& positions) {
  const mesh::Vec3f &p0 = positions[binding.v0], &p1 = positions[binding.v1],
                    &p2 = positions[binding.v2];
  const float third = 1.0f / 3.0f;  // 0.333333343, as the shader's constant
  const float w0 = float(binding.w0), w1 = float(binding.w1), w2 = float(binding.w2);
  const float volume = float(binding.volume);
  const mesh::Vec3f c{(p0.x + p1.x + p2.x) * third, (p0.y + p1.y + p2.y) * third,
                      (p0.z + p1.z + p2.z) * third};
  const mesh::Vec3f e1{p1.x - p0.x, p1.y - p0.y, p1.z - p0.z};
  const mesh::Vec3f e2{p2.x - p0.x, p2.y - p0.y, p2.z - p0.z};
  const mesh::Vec3f n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                      e1.x * e2.y - e1.y * e2.x};
  const float nn = n.x * n.x + n.y * n.y + n.z * n.z;
  const float s = nn > 0.0f ? (6.0f * volume) / nn : 0.0f;
  const mesh::Vec3f p3{c.x + n.x * s, c.y + n.y * s, c.z + n.z * s};
  const float w3 = 1.0f - w0 - w1 - w2;
  return {p0.x * w0 + p1.x * w1 + p2.x * w2 + p3.x * w3,
          p0.y * w0 + p1.y * w1 + p2.y * w2 + p3.y * w3,
          p0.z * w0 + p1.z * w1 + p2.z * w2 + p3.z * w3};
}

RenderMesh tessellateForRendering(const mesh::Mesh& mesh, uint32_t level, double apex_height) {
  if (level < 1) throw std::invalid_argument("tessellateForRendering: level must be >= 1");
  RenderMesh out;
  const std::vector<mesh::Vec3d>& rest = mesh.positions;
  auto add = [&](uint32_t v0, uint32_t v1, uint32_t v2, const mesh::Vec3d& q) {
    out.bindings.push_back(bindToTriangle(rest, v0, v1, v2, q, apex_height));
    out.rest_positions.push_back(q);
    return uint32_t(out.bindings.size() - 1);
  };
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.facePositions(f);
    if (face.size() == 4) {
      // Bilinear grid; corner k at (0,0), (1,0), (1,1), (0,1); v <= u lies in (0,1,2).
      std::vector<uint32_t> grid((level + 1) * (level + 1));
      for (uint32_t j = 0; j <= level; ++j) {
        for (uint32_t i = 0; i <= level; ++i) {
          const double u = double(i) / level, v = double(j) / level;
          const mesh::Vec3d q = (1 - v) * ((1 - u) * rest[face[0]] + u * rest[face[1]]) +
                                v * ((1 - u) * rest[face[3]] + u * rest[face[2]]);
          grid[j * (level + 1) + i] =
              j <= i ? add(face[0], face[1], face[2], q) : add(face[0], face[2], face[3], q);
        }
      }
      for (uint32_t j = 0; j < level; ++j) {
        for (uint32_t i = 0; i < level; ++i) {
          const uint32_t a = grid[j * (level + 1) + i], b = grid[j * (level + 1) + i + 1],
                         c = grid[(j + 1) * (level + 1) + i + 1],
                         d = grid[(j + 1) * (level + 1) + i];
          out.triangles.insert(out.triangles.end(), {a, b, c, a, c, d});
        }
      }
      continue;
    }
    for (size_t k = 1; k + 1 < face.size(); ++k) {  // fan triangles, each tessellated linearly
      const uint32_t t[3] = {face[0], face[k], face[k + 1]};
      std::vector<uint32_t> row_start;
      std::vector<uint32_t> ids;
      for (uint32_t j = 0; j <= level; ++j) {
        row_start.push_back(uint32_t(ids.size()));
        for (uint32_t i = 0; i + j <= level; ++i) {
          const double b1 = double(i) / level, b2 = double(j) / level;
          const mesh::Vec3d q = (1 - b1 - b2) * rest[t[0]] + b1 * rest[t[1]] + b2 * rest[t[2]];
          ids.push_back(add(t[0], t[1], t[2], q));
        }
      }
      for (uint32_t j = 0; j < level; ++j) {
        for (uint32_t i = 0; i + j < level; ++i) {
          const uint32_t a = ids[row_start[j] + i], b = ids[row_start[j] + i + 1],
                         c = ids[row_start[j + 1] + i];
          out.triangles.insert(out.triangles.end(), {a, b, c});
          if (i + j + 1 < level) {
            out.triangles.insert(out.triangles.end(), {b, ids[row_start[j + 1] + i + 1], c});
          }
        }
      }
    }
  }
  return out;
}

}  // namespace tb::mass_spring
