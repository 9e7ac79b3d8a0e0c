#include "harness/pictures/up_axis.h"

#include <algorithm>
#include <cmath>

namespace tb::pictures {

const char* toString(UpAxis up) { return up == UpAxis::kZ ? "z" : "y"; }

mesh::Vec3d upVector(UpAxis up) {
  return up == UpAxis::kZ ? mesh::Vec3d{0, 0, 1} : mesh::Vec3d{0, 1, 0};
}

namespace {

// x and y alike (within kUpAxisSymmetryTolerance of the larger), z unlike their mean (by
// more than kUpAxisDistinctTolerance of it).
bool symmetricAboutZ(double x, double y, double z) {
  const double xy_max = std::max(x, y);
  const double xy_mean = 0.5 * (x + y);
  if (!(xy_max > 0) || !std::isfinite(xy_max) || !std::isfinite(z)) return false;
  return std::abs(x - y) <= kUpAxisSymmetryTolerance * xy_max &&
         std::abs(z - xy_mean) > kUpAxisDistinctTolerance * xy_mean;
}

}  // namespace

UpAxis detectUpAxis(std::span<const mesh::Vec3d> positions) {
  if (positions.size() < 2) return UpAxis::kY;
  mesh::Vec3d lo = positions.front(), hi = positions.front();
  for (const mesh::Vec3d& p : positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
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
  const mesh::Vec3d extent = hi - lo;
  return symmetricAboutZ(vx, vy, vz) || symmetricAboutZ(extent.x, extent.y, extent.z) ? UpAxis::kZ
                                                                                      : UpAxis::kY;
}

}  // namespace tb::pictures
