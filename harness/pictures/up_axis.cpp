#include "harness/pictures/up_axis.h"

#include <algorithm>
#include <cmath>

namespace tb::pictures {

const char* toString(UpAxis up) { return up == UpAxis::kZ ? "z" : "y"; }

mesh::Vec3d upVector(UpAxis up) {
  return up == UpAxis::kZ ? mesh::Vec3d{0, 0, 1} : mesh::Vec3d{0, 1, 0};
}

UpAxis detectUpAxis(std::span<const mesh::Vec3d> positions) {
  if (positions.size() < 2) return UpAxis::kY;
  mesh::Vec3d mean{0, 0, 0};
  for (const mesh::Vec3d& p : positions) mean = mean + p;
  mean = (1.0 / double(positions.size())) * mean;
  double vx = 0, vy = 0, vz = 0;
  for (const mesh::Vec3d& p : positions) {
    const mesh::Vec3d d = p - mean;
    vx += d.x * d.x;
    vy += d.y * d.y;
    vz += d.z * d.z;
  }
  const double xy_max = std::max(vx, vy);
  const double xy_mean = 0.5 * (vx + vy);
  if (!(xy_max > 0) || !std::isfinite(xy_max) || !std::isfinite(vz)) return UpAxis::kY;
  const bool symmetric = std::abs(vx - vy) <= kUpAxisSymmetryTolerance * xy_max;
  const bool distinct = std::abs(vz - xy_mean) > kUpAxisDistinctTolerance * xy_mean;
  return symmetric && distinct ? UpAxis::kZ : UpAxis::kY;
}

}  // namespace tb::pictures
