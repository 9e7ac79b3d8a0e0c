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

constexpr double kUnset = -1;    // no shared distance: the triangle finds its own
constexpr double kSkipped = -2;  // bounded below the floor: cannot hold the maximum

// The lattice points' distances only feed the maximum (the centroids carry the RMS and mean),
// and the largest centroid distance (the floor) bounds that maximum from below. A lattice
// point of triangle t is a corner of one "upward" sub-triangle, whose centroid's closest
// target triangle T is known: D(p) <= distance(p, T), so a point whose bound is below the
// floor can neither hold nor tie the maximum, and is skipped (kSkipped) without a query.
struct LatticeBound {
  const TriangleDistanceField* target;
  std::span<const uint32_t> centroid_triangle;  // per source triangle, per upward centroid
  int m;
  double floor;
  double scale;  // 1; the broken control's 0.5 (MaxSearch::kBrokenSkip)

  size_t ups() const { return size_t(m) * size_t(m + 1) / 2; }
  // The closest target triangle of the upward centroid next to lattice point (i, j) of t.
  uint32_t triangleNear(size_t t, int i, int j) const {
    if (i + j > m - 1) (i > 0 ? i : j) -= 1;
    const size_t row = size_t(i) * size_t(m) - size_t(i) * size_t(i - 1) / 2;
    return centroid_triangle[t * ups() + row + size_t(j)];
  }
  // The exact distance of p, or kSkipped; `hint` as TriangleDistanceField::closest's.
  double distance(size_t t, int i, int j, const mesh::Vec3d& p, uint32_t* hint) const {
    const uint32_t near = centroid_triangle.empty() ? kNoTriangle : triangleNear(t, i, j);
    if (near != kNoTriangle) {
      if (scale * target->distanceTo(p, near) < floor) return kSkipped;
      *hint = near;
    }
    const ClosestPoint closest = target->closest(p, *hint);
    *hint = closest.triangle;
    return closest.distance;
  }
};

// The distances of the lattice points source triangles share, computed once: every vertex
// (as its first triangle, lowest index, has it as a corner) and each edge's interior lattice
// points (as the edge's first triangle computes them). A triangle uses a shared distance only
// where its own point is bitwise the shared one (so every figure is what sampling each
// triangle alone gives, bit for bit); a dense reference mesh then needs about 6 queries a
// triangle at lattice level 2 instead of 10.
class SharedLattice {
 public:
  SharedLattice(const TriangleMeshRef& source, const LatticeBound& bound)
      : m_(bound.m), vertex_(source.positions.size(), kUnset) {
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
    const size_t per_edge = size_t(std::max(m_ - 1, 0));
    edge_points_.resize(edges_.size() * per_edge);
    edge_distance_.resize(edges_.size() * per_edge);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, edges_.size()),
                      [&](const tbb::blocked_range<size_t>& range) {
                        uint32_t hint = kNoTriangle;
                        for (size_t e = range.begin(); e != range.end(); ++e) {
                          fillEdge(source, bound, e, &hint);
                        }
                      });
    // Each vertex as a corner of its first triangle: (i, j) = (0, 0), (m, 0) or (0, m).
    std::vector<std::array<uint32_t, 2>> owner(source.positions.size(), {kNoTriangle, 0});
    for (uint32_t t = source.triangles.size(); t-- > 0;) {
      for (uint32_t k = 0; k < 3; ++k) owner[source.triangles[t][k]] = {t, k};
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_.size()),
                      [&](const tbb::blocked_range<size_t>& range) {
                        uint32_t hint = kNoTriangle;
                        for (size_t v = range.begin(); v != range.end(); ++v) {
                          const auto [t, k] = owner[v];
                          if (t == kNoTriangle) continue;
                          vertex_[v] = bound.distance(t, k == 1 ? m_ : 0, k == 2 ? m_ : 0,
                                                      source.positions[v], &hint);
                        }
                      });
  }

  // The shared distance of the lattice point (i, j) of triangle `tri` (weights i/m of its
  // corner 1 and j/m of corner 2) whose position is `p`: kSkipped, kUnset when it has none,
  // or the distance.
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

 private:
  static bool sameBits(const mesh::Vec3d& a, const mesh::Vec3d& b) {
    return std::memcmp(&a, &b, sizeof(mesh::Vec3d)) == 0;
  }

  // Edge e's interior points as its owner triangle's lattice gives them, from its lo corner.
  void fillEdge(const TriangleMeshRef& source, const LatticeBound& bound, size_t e,
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
      edge_points_[slot] = p;
      edge_distance_[slot] = bound.distance(t, i, j, p, hint);
    }
  }

  int m_;
  std::vector<double> vertex_;
  std::vector<std::array<uint32_t, 2>> edges_;   // sorted (lo, hi)
  std::vector<std::array<uint32_t, 2>> owners_;  // per edge: triangle, local edge
  std::vector<mesh::Vec3d> edge_points_;
  std::vector<double> edge_distance_;
};

// The centroids of triangle t's "upward" sub-triangles (i, j) and its "downward" ones: their
// sums and maximum (the first on ties, in this order), and each upward centroid's closest
// target triangle into `up_triangle` (m (m + 1) / 2 of them). `hint` as closest()'s.
TriangleSums sampleCentroids(const TriangleMeshRef& source, size_t t,
                             const TriangleDistanceField& target, int m, uint32_t* hint,
                             uint32_t* up_triangle) {
  const Triangle& tri = source.triangles[t];
  const mesh::Vec3d &a = source.positions[tri[0]], &b = source.positions[tri[1]],
                    &c = source.positions[tri[2]];
  TriangleSums sums;
  sums.area = 0.5 * length(cross(b - a, c - a));
  const double inv_m = 1.0 / m;
  bool first = true;
  auto sample = [&](double wb, double wc) {
    const mesh::Vec3d p = barycentricPoint(a, b, c, wb, wc);
    const ClosestPoint closest = target.closest(p, *hint);
    *hint = closest.triangle;
    if (first || closest.distance > sums.max) {
      sums.max = closest.distance;
      sums.max_at = p;
      first = false;
    }
    sums.sum_d += closest.distance;
    sums.sum_d2 += closest.distance * closest.distance;
    return closest.triangle;
  };
  for (int i = 0; i < m; ++i) {
    for (int j = 0; i + j < m; ++j) {
      *up_triangle++ = sample((i + 1.0 / 3) * inv_m, (j + 1.0 / 3) * inv_m);
      if (i + j < m - 1) sample((i + 2.0 / 3) * inv_m, (j + 2.0 / 3) * inv_m);
    }
  }
  return sums;
}

// The lattice points of triangle t, before its centroids in sample order: `sums` (its
// centroids' figures) takes the first lattice point of a larger maximum, or of an equal one.
void sampleLattice(const TriangleMeshRef& source, size_t t, const SharedLattice& shared,
                   const LatticeBound& bound, uint32_t* hint, TriangleSums* sums) {
  const Triangle& tri = source.triangles[t];
  const mesh::Vec3d &a = source.positions[tri[0]], &b = source.positions[tri[1]],
                    &c = source.positions[tri[2]];
  const int m = bound.m;
  const double inv_m = 1.0 / m;
  bool found = false;
  double max = 0;
  mesh::Vec3d max_at;
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; i + j <= m; ++j) {
      const mesh::Vec3d p = barycentricPoint(a, b, c, i * inv_m, j * inv_m);
      double d = shared.find(tri, source.positions, i, j, p);
      if (d == kUnset) d = bound.distance(t, i, j, p, hint);
      if (d == kSkipped) continue;
      if (!found || d > max) {
        max = d;
        max_at = p;
        found = true;
      }
    }
  }
  if (found && max >= sums->max) {
    sums->max = max;
    sums->max_at = max_at;
  }
}

}  // namespace

DirectedDistance directedDistance(const TriangleMeshRef& source,
                                  const TriangleDistanceField& target, int lattice_level,
                                  MaxSearch search) {
  if (lattice_level < 1 || lattice_level > kMaxLatticeLevel) {
    throw mesh::InputError("hausdorff", "option 'lattice_level'",
                           "level " + std::to_string(lattice_level) + " is outside [1, " +
                               std::to_string(kMaxLatticeLevel) + "]");
  }
  const int m = lattice_level;
  const size_t ups = size_t(m) * size_t(m + 1) / 2;
  std::vector<TriangleSums> per_triangle(source.triangles.size());
  std::vector<uint32_t> up_triangle(per_triangle.size() * ups);
  // Neighbouring source triangles (in index order) are usually close on the target too.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, per_triangle.size()),
                    [&](const tbb::blocked_range<size_t>& range) {
                      uint32_t hint = kNoTriangle;
                      for (size_t t = range.begin(); t != range.end(); ++t) {
                        per_triangle[t] = sampleCentroids(source, t, target, m, &hint,
                                                          up_triangle.data() + t * ups);
                      }
                    });
  LatticeBound bound{&target, {}, m, 0, search == MaxSearch::kBrokenSkip ? 0.5 : 1.0};
  if (search != MaxSearch::kEverySample) {
    bound.centroid_triangle = up_triangle;
    for (const TriangleSums& sums : per_triangle) bound.floor = std::max(bound.floor, sums.max);
  }
  const SharedLattice shared(source, bound);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, per_triangle.size()),
                    [&](const tbb::blocked_range<size_t>& range) {
                      uint32_t hint = kNoTriangle;
                      for (size_t t = range.begin(); t != range.end(); ++t) {
                        sampleLattice(source, t, shared, bound, &hint, &per_triangle[t]);
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
