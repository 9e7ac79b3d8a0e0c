#include "techniques/osd_adaptive/osd_curvature.h"

#include <algorithm>
#include <vector>

#include "techniques/common/curvature_bounds.h"

namespace tb::osd_adaptive {
namespace {

using Grid = std::array<std::array<mesh::Vec3d, 4>, 4>;  // [row j along t][column i along s]

double secondDifference(const mesh::Vec3d& a, const mesh::Vec3d& b, const mesh::Vec3d& c) {
  return length(a - b * 2.0 + c);
}

// The B-spline curve's bound max |Δ² q| over its 4 points (uniform cubic: sup |C''| is the
// larger of the two second differences, attained at a knot).
double bsplineCurveBound(const std::array<mesh::Vec3d, 4>& q) {
  return std::max(secondDifference(q[0], q[1], q[2]), secondDifference(q[1], q[2], q[3]));
}

// The 16 points with each boundary edge's phantom row or column replaced by 2 p1 - p2
// (osd_basis.h's foldPhantom on the weights is this on the points): s first, then t; the
// two commute (they act on different indices).
Grid regularGrid(uint32_t packed, const std::array<mesh::Vec3d, kMaxSubPatchPoints>& points) {
  Grid e;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) e[j][i] = points[size_t(4 * j + i)];
  }
  const uint32_t boundary = subPatchBoundary(packed);
  for (int j = 0; j < 4; ++j) {
    if ((boundary & 8u) != 0) e[j][0] = e[j][1] * 2.0 - e[j][2];  // s = 0
    if ((boundary & 2u) != 0) e[j][3] = e[j][2] * 2.0 - e[j][1];  // s = 1
  }
  for (int i = 0; i < 4; ++i) {
    if ((boundary & 1u) != 0) e[0][i] = e[1][i] * 2.0 - e[2][i];  // t = 0
    if ((boundary & 4u) != 0) e[3][i] = e[2][i] * 2.0 - e[1][i];  // t = 1
  }
  return e;
}

techniques::CurvatureBounds regularBounds(
    uint32_t packed, const std::array<mesh::Vec3d, kMaxSubPatchPoints>& points) {
  const Grid e = regularGrid(packed, points);
  techniques::CurvatureBounds b;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 2; ++i) {
      b.uu = std::max(b.uu, secondDifference(e[j][i], e[j][i + 1], e[j][i + 2]));
      b.vv = std::max(b.vv, secondDifference(e[i][j], e[i + 1][j], e[i + 2][j]));
    }
  }
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      b.uv = std::max(b.uv, length(e[j + 1][i + 1] - e[j + 1][i] - e[j][i + 1] + e[j][i]));
    }
  }
  // Boundary curves: the basis at 0 is (1, 4, 1, 0) / 6, at 1 (0, 1, 4, 1) / 6.
  const auto blend = [](const mesh::Vec3d& a, const mesh::Vec3d& m, const mesh::Vec3d& c) {
    return (a + m * 4.0 + c) * (1.0 / 6.0);
  };
  std::array<std::array<mesh::Vec3d, 4>, 4> q;  // edges s = 0, t = 0, s = 1, t = 1
  for (int k = 0; k < 4; ++k) {
    q[0][k] = blend(e[k][0], e[k][1], e[k][2]);
    q[1][k] = blend(e[0][k], e[1][k], e[2][k]);
    q[2][k] = blend(e[k][1], e[k][2], e[k][3]);
    q[3][k] = blend(e[1][k], e[2][k], e[3][k]);
  }
  for (int edge = 0; edge < 4; ++edge) {
    b.edge[edge] = bsplineCurveBound(q[edge]);
    b.edge_hull[edge].assign(q[edge].begin(), q[edge].end());
  }
  for (const auto& row : e) b.hull.insert(b.hull.end(), row.begin(), row.end());
  return b;
}

techniques::CurvatureBounds gregoryBounds(
    const std::array<mesh::Vec3d, kMaxSubPatchPoints>& points) {
  std::vector<mesh::Vec3d> net(16);
  for (const auto& [point, column, row] : kGregoryBoundaryNet) {
    net[size_t(column + 4 * row)] = points[size_t(point)];
  }
  std::array<double, 4> half_gaps{};
  for (int c = 0; c < 4; ++c) {
    const mesh::Vec3d& f_plus = points[size_t(5 * c + 3)];
    const mesh::Vec3d& f_minus = points[size_t(5 * c + 4)];
    net[size_t(kGregoryInteriorColumn[c] + 4 * kGregoryInteriorRow[c])] = (f_plus + f_minus) * 0.5;
    half_gaps[size_t(c)] = 0.5 * length(f_plus - f_minus);
  }
  techniques::CurvatureBounds b = techniques::gregoryQuadNetCurvatureBounds(net, half_gaps);
  b.hull.assign(points.begin(), points.end());
  return b;
}

}  // namespace

techniques::CurvatureBounds subPatchCurvatureBounds(
    uint32_t packed, const std::array<mesh::Vec3d, kMaxSubPatchPoints>& points) {
  return subPatchIsGregory(packed) ? gregoryBounds(points) : regularBounds(packed, points);
}

}  // namespace tb::osd_adaptive
