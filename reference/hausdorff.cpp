#include "reference/hausdorff.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"

namespace tb::ref {
namespace {

struct TriangleSums {
  double max = 0;
  mesh::Vec3d max_at;
  double sum_d = 0;   // sum of centroid distances (each weighs area / m^2)
  double sum_d2 = 0;  // sum of squared centroid distances
  double area = 0;
};

mesh::Vec3d barycentricPoint(const mesh::Vec3d& a, const mesh::Vec3d& b, const mesh::Vec3d& c,
                             double wb, double wc) {
  return a * (1 - wb - wc) + b * wb + c * wc;
}

// The distances of the lattice points source triangles share, computed once: every vertex
// (a corner of each triangle around it) and each edge's interior lattice points, as the
// edge's first triangle (lowest index) computes them. A triangle uses a shared distance only
// where its own point is bitwise the shared one (so every figure is what sampling each
// triangle alone gives, bit for bit); a dense reference mesh then needs about 6 queries a
// triangle at lattice level 2 instead of 10.
class SharedLattice {
 public:
  SharedLattice(const TriangleMeshRef& source, const TriangleDistanceField& target, int m)
      : m_(m), vertex_(source.positions.size(), kUnset) {
    std::vector<std::array<uint32_t, 4>> sides;  // lo, hi, triangle, local edge
    for (uint32_t t = 0; t < source.triangles.size(); ++t) {
      for (uint32_t e = 0; e < 3; ++e) {
        const uint32_t a = source.triangles[t][e], b = source.triangles[t][(e + 1) % 3];
        sides.push_back({std::min(a, b), std::max(a, b), t, e});
      }
    }
    std::sort(sides.begin(), sides.end());
    for (size_t i = 0; i < sides.size(); ++i) {
      if (i > 0 && sides[i][0] == sides[i - 1][0] && sides[i][1] == sides[i - 1][1]) continue;
      edges_.push_back({sides[i][0], sides[i][1]});
      owners_.push_back({sides[i][2], sides[i][3]});
    }
    const size_t per_edge = size_t(std::max(m - 1, 0));
    edge_points_.resize(edges_.size() * per_edge);
    edge_distance_.resize(edges_.size() * per_edge);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, edges_.size()),
                      [&](const tbb::blocked_range<size_t>& range) {
                        uint32_t hint = kNoTriangle;
                        for (size_t e = range.begin(); e != range.end(); ++e) {
                          fillEdge(source, target, e, &hint);
                        }
                      });
    std::vector<uint8_t> used(source.positions.size(), 0);
    for (const Triangle& tri : source.triangles) used[tri[0]] = used[tri[1]] = used[tri[2]] = 1;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_.size()),
                      [&](const tbb::blocked_range<size_t>& range) {
                        uint32_t hint = kNoTriangle;
                        for (size_t v = range.begin(); v != range.end(); ++v) {
                          if (!used[v]) continue;
                          const ClosestPoint closest = target.closest(source.positions[v], hint);
                          hint = closest.triangle;
                          vertex_[v] = closest.distance;
                        }
                      });
  }

  // The shared distance of the lattice point (i, j) of triangle `tri` (weights i/m of its
  // corner 1 and j/m of corner 2) whose position is `p`, or kUnset when it has none.
  double find(const Triangle& tri, const std::span<const mesh::Vec3d> positions, int i, int j,
              const mesh::Vec3d& p) const {
    const int corner = i == 0 && j == 0 ? 0 : i == m_ && j == 0 ? 1 : i == 0 && j == m_ ? 2 : -1;
    if (corner >= 0) {
      return sameBits(p, positions[tri[size_t(corner)]]) ? vertex_[tri[size_t(corner)]] : kUnset;
    }
    // Edge 0 (corner 0 -> 1): j == 0; edge 1 (1 -> 2): i + j == m; edge 2 (2 -> 0): i == 0.
    const int edge = j == 0 ? 0 : i + j == m_ ? 1 : i == 0 ? 2 : -1;
    if (edge < 0) return kUnset;
    const int along = edge == 0 ? i : edge == 1 ? j : m_ - j;  // from the edge's first corner
    const uint32_t a = tri[size_t(edge)], b = tri[size_t(edge + 1) % 3];
    const auto it = std::lower_bound(edges_.begin(), edges_.end(),
                                     std::array<uint32_t, 2>{std::min(a, b), std::max(a, b)});
    const size_t slot =
        size_t(it - edges_.begin()) * size_t(m_ - 1) + size_t((a < b ? along : m_ - along) - 1);
    return sameBits(p, edge_points_[slot]) ? edge_distance_[slot] : kUnset;
  }

  static constexpr double kUnset = -1;

 private:
  static bool sameBits(const mesh::Vec3d& a, const mesh::Vec3d& b) {
    return std::memcmp(&a, &b, sizeof(mesh::Vec3d)) == 0;
  }

  // Edge e's interior points as its owner triangle's lattice gives them, from its lo corner.
  void fillEdge(const TriangleMeshRef& source, const TriangleDistanceField& target, size_t e,
                uint32_t* hint) {
    const auto [t, local] = owners_[e];
    const Triangle& tri = source.triangles[t];
    const mesh::Vec3d &a = source.positions[tri[0]], &b = source.positions[tri[1]],
                      &c = source.positions[tri[2]];
    const double inv_m = 1.0 / m_;
    for (int k = 1; k < m_; ++k) {  // k steps from the edge's first corner in the triangle
      const int i = local == 0 ? k : local == 1 ? m_ - k : 0;
      const int j = local == 0 ? 0 : local == 1 ? k : m_ - k;
      const mesh::Vec3d p = barycentricPoint(a, b, c, i * inv_m, j * inv_m);
      const bool forward = tri[local] < tri[(local + 1) % 3];
      const size_t slot = e * size_t(m_ - 1) + size_t((forward ? k : m_ - k) - 1);
      const ClosestPoint closest = target.closest(p, *hint);
      *hint = closest.triangle;
      edge_points_[slot] = p;
      edge_distance_[slot] = closest.distance;
    }
  }

  int m_;
  std::vector<double> vertex_;
  std::vector<std::array<uint32_t, 2>> edges_;   // sorted (lo, hi)
  std::vector<std::array<uint32_t, 2>> owners_;  // per edge: triangle, local edge
  std::vector<mesh::Vec3d> edge_points_;
  std::vector<double> edge_distance_;
};

// `hint`: the target triangle closest to the previous sample (speeds the search, never
// changes an answer); updated to this triangle's last.
TriangleSums sampleTriangle(const TriangleMeshRef& source, size_t t,
                            const TriangleDistanceField& target, const SharedLattice& shared, int m,
                            uint32_t* hint) {
  const Triangle& tri = source.triangles[t];
  const mesh::Vec3d &a = source.positions[tri[0]], &b = source.positions[tri[1]],
                    &c = source.positions[tri[2]];
  TriangleSums sums;
  sums.area = 0.5 * length(cross(b - a, c - a));
  const double inv_m = 1.0 / m;
  bool first = true;
  auto consider = [&](const mesh::Vec3d& p, double known) {
    double d = known;
    if (d == SharedLattice::kUnset) {
      const ClosestPoint closest = target.closest(p, *hint);
      *hint = closest.triangle;
      d = closest.distance;
    }
    if (first || d > sums.max) {
      sums.max = d;
      sums.max_at = p;
      first = false;
    }
    return d;
  };
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; i + j <= m; ++j) {
      const mesh::Vec3d p = barycentricPoint(a, b, c, i * inv_m, j * inv_m);
      consider(p, shared.find(tri, source.positions, i, j, p));
    }
  }
  // Centroids of the "upward" sub-triangles (i,j) and the "downward" ones.
  for (int i = 0; i < m; ++i) {
    for (int j = 0; i + j < m; ++j) {
      const double up =
          consider(barycentricPoint(a, b, c, (i + 1.0 / 3) * inv_m, (j + 1.0 / 3) * inv_m),
                   SharedLattice::kUnset);
      sums.sum_d += up;
      sums.sum_d2 += up * up;
      if (i + j < m - 1) {
        const double down =
            consider(barycentricPoint(a, b, c, (i + 2.0 / 3) * inv_m, (j + 2.0 / 3) * inv_m),
                     SharedLattice::kUnset);
        sums.sum_d += down;
        sums.sum_d2 += down * down;
      }
    }
  }
  return sums;
}

}  // namespace

DirectedDistance directedDistance(const TriangleMeshRef& source,
                                  const TriangleDistanceField& target, int lattice_level) {
  if (lattice_level < 1 || lattice_level > kMaxLatticeLevel) {
    throw mesh::InputError("hausdorff", "option 'lattice_level'",
                           "level " + std::to_string(lattice_level) + " is outside [1, " +
                               std::to_string(kMaxLatticeLevel) + "]");
  }
  const int m = lattice_level;
  const SharedLattice shared(source, target, m);
  std::vector<TriangleSums> per_triangle(source.triangles.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, per_triangle.size()),
                    [&](const tbb::blocked_range<size_t>& range) {
                      // Neighbouring source triangles (in index order) are usually
                      // close on the target too.
                      uint32_t hint = kNoTriangle;
                      for (size_t t = range.begin(); t != range.end(); ++t) {
                        per_triangle[t] = sampleTriangle(source, t, target, shared, m, &hint);
                      }
                    });
  // Reduced serially in triangle order, so the result does not depend on scheduling.
  DirectedDistance result;
  double weighted_d = 0, weighted_d2 = 0;
  bool first = true;
  for (const TriangleSums& sums : per_triangle) {
    if (first || sums.max > result.max) {
      result.max = sums.max;
      result.max_at = sums.max_at;
      first = false;
    }
    const double weight = sums.area / (double(m) * m);
    weighted_d += weight * sums.sum_d;
    weighted_d2 += weight * sums.sum_d2;
    result.area += sums.area;
  }
  if (result.area > 0) {
    result.mean = weighted_d / result.area;
    result.rms = std::sqrt(weighted_d2 / result.area);
  }
  const size_t per = size_t(m + 1) * size_t(m + 2) / 2 + size_t(m) * size_t(m);
  result.samples = per * source.triangles.size();
  return result;
}

HausdorffResult hausdorff(const TriangleMeshRef& a, const TriangleMeshRef& b, int lattice_level) {
  return hausdorff(a, a, b, b, lattice_level);
}

HausdorffResult hausdorff(const TriangleMeshRef& a_part, const TriangleMeshRef& a_around,
                          const TriangleMeshRef& b_part, const TriangleMeshRef& b_around,
                          int lattice_level) {
  HausdorffResult result;
  {
    const TriangleDistanceField field_b(b_around, "hausdorff mesh b");
    result.a_to_b = directedDistance(a_part, field_b, lattice_level);
  }  // one field at a time: the larger (a dense reference) is freed before the other is built
  {
    const TriangleDistanceField field_a(a_around, "hausdorff mesh a");
    result.b_to_a = directedDistance(b_part, field_a, lattice_level);
  }
  result.hausdorff = std::max(result.a_to_b.max, result.b_to_a.max);
  const double area = result.a_to_b.area + result.b_to_a.area;
  if (area > 0) {
    result.rms = std::sqrt((result.a_to_b.area * result.a_to_b.rms * result.a_to_b.rms +
                            result.b_to_a.area * result.b_to_a.rms * result.b_to_a.rms) /
                           area);
  }
  return result;
}

}  // namespace tb::ref
