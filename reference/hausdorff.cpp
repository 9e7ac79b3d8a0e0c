#include "reference/hausdorff.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
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

// `hint`: the target triangle closest to the previous sample (speeds the search, never
// changes an answer); updated to this triangle's last.
TriangleSums sampleTriangle(const mesh::Vec3d& a, const mesh::Vec3d& b, const mesh::Vec3d& c,
                            const TriangleDistanceField& target, int m, uint32_t* hint) {
  TriangleSums sums;
  sums.area = 0.5 * length(cross(b - a, c - a));
  const double inv_m = 1.0 / m;
  bool first = true;
  auto consider = [&](const mesh::Vec3d& p) {
    const ClosestPoint closest = target.closest(p, *hint);
    *hint = closest.triangle;
    const double d = closest.distance;
    if (first || d > sums.max) {
      sums.max = d;
      sums.max_at = p;
      first = false;
    }
    return d;
  };
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; i + j <= m; ++j) consider(barycentricPoint(a, b, c, i * inv_m, j * inv_m));
  }
  // Centroids of the "upward" sub-triangles (i,j) and the "downward" ones.
  for (int i = 0; i < m; ++i) {
    for (int j = 0; i + j < m; ++j) {
      const double up =
          consider(barycentricPoint(a, b, c, (i + 1.0 / 3) * inv_m, (j + 1.0 / 3) * inv_m));
      sums.sum_d += up;
      sums.sum_d2 += up * up;
      if (i + j < m - 1) {
        const double down =
            consider(barycentricPoint(a, b, c, (i + 2.0 / 3) * inv_m, (j + 2.0 / 3) * inv_m));
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
  std::vector<TriangleSums> per_triangle(source.triangles.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, per_triangle.size()),
                    [&](const tbb::blocked_range<size_t>& range) {
                      // Neighbouring source triangles (in index order) are usually
                      // close on the target too.
                      uint32_t hint = kNoTriangle;
                      for (size_t t = range.begin(); t != range.end(); ++t) {
                        const Triangle& tri = source.triangles[t];
                        per_triangle[t] =
                            sampleTriangle(source.positions[tri[0]], source.positions[tri[1]],
                                           source.positions[tri[2]], target, m, &hint);
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
