#include "harness/measures/error/displaced_error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/triangle_distance_field.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::measures {
namespace {

// The lattice of one patch: level + 1 points a side (quads) or the triangle's
// (level + 1)(level + 2) / 2, and its triangles (counter-clockwise in the domain).
struct Lattice {
  std::vector<techniques::DomainCoord> points;
  std::vector<ref::Triangle> triangles;
};

Lattice latticeOf(techniques::PatchDomain domain, int level) {
  Lattice lattice;
  const double step = 1.0 / level;
  if (domain == techniques::PatchDomain::kQuad) {
    for (int j = 0; j <= level; ++j) {
      for (int i = 0; i <= level; ++i) lattice.points.push_back({i * step, j * step, 0});
    }
    auto at = [level](int i, int j) { return uint32_t(j * (level + 1) + i); };
    for (int j = 0; j < level; ++j) {
      for (int i = 0; i < level; ++i) {
        lattice.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        lattice.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
    return lattice;
  }
  // Rows of constant w1 = j / level; in row j, w0 = i / level for i <= level - j.
  std::vector<uint32_t> row_start;
  for (int j = 0; j <= level; ++j) {
    row_start.push_back(uint32_t(lattice.points.size()));
    for (int i = 0; i <= level - j; ++i) {
      const double w0 = i * step, w1 = j * step;
      lattice.points.push_back({w0, w1, std::max(0.0, 1 - w0 - w1)});
    }
  }
  for (int j = 0; j < level; ++j) {
    for (int i = 0; i < level - j; ++i) {
      const uint32_t a = row_start[j] + i, b = a + 1, c = row_start[j + 1] + i;
      lattice.triangles.push_back({a, b, c});
      if (i + 1 < level - j) lattice.triangles.push_back({b, row_start[j + 1] + i + 1, c});
    }
  }
  return lattice;
}

}  // namespace

DisplacedErrorFigures measureDisplacedError(const techniques::SurfacePatches& displaced,
                                            const DisplacementTarget& target, int level,
                                            uint32_t map_texels_per_side) {
  DisplacedErrorFigures figures;
  figures.map_texels_per_side = map_texels_per_side;
  figures.bbox_diagonal = ref::boundingBoxDiagonal(displaced.controlMesh().positions);
  const size_t patches = displaced.patchCount();
  const Lattice lattices[2] = {latticeOf(techniques::PatchDomain::kTriangle, level),
                               latticeOf(techniques::PatchDomain::kQuad, level)};
  auto latticeFor = [&](size_t p) -> const Lattice& {
    return lattices[displaced.patchDomain(p) == techniques::PatchDomain::kQuad ? 1 : 0];
  };
  std::vector<size_t> first(patches + 1, 0);
  for (size_t p = 0; p < patches; ++p) first[p + 1] = first[p] + latticeFor(p).points.size();
  std::vector<mesh::Vec3d> points(first.back());
  std::vector<double> distance(first.back());
  tbb::parallel_for(size_t(0), patches, [&](size_t p) {
    uint32_t hint = ref::kNoTriangle;
    const Lattice& lattice = latticeFor(p);
    for (size_t k = 0; k < lattice.points.size(); ++k) {
      const mesh::Vec3d point = displaced.evaluate(p, lattice.points[k]).position;
      const ref::ClosestPoint hit = target.field->closest(point, hint);
      hint = hit.triangle;
      points[first[p] + k] = point;
      distance[first[p] + k] = length(hit.point - point);
    }
  });
  std::vector<ref::Triangle> triangles;
  for (size_t p = 0; p < patches; ++p) {
    for (const ref::Triangle& t : latticeFor(p).triangles) {
      triangles.push_back(
          {uint32_t(first[p] + t[0]), uint32_t(first[p] + t[1]), uint32_t(first[p] + t[2])});
    }
  }
  const ref::TriangleDistanceField surface(points, triangles, "displaced surface");
  const size_t target_count = target.positions.size();
  std::vector<double> back(target_count, 0);
  tbb::parallel_for(size_t(0), target_count, [&](size_t v) {
    back[v] = length(surface.closest(target.positions[v]).point - target.positions[v]);
  });
  // Reductions in index order, so the figures do not depend on the thread count.
  double sum_squares = 0;
  for (double d : distance) {
    figures.hausdorff_tech_to_target = std::max(figures.hausdorff_tech_to_target, d);
    sum_squares += d * d;
  }
  for (double d : back)
    figures.hausdorff_target_to_tech = std::max(figures.hausdorff_target_to_tech, d);
  figures.samples = distance.size();
  const double scale = figures.bbox_diagonal > 0 ? 1 / figures.bbox_diagonal : 0;
  figures.hausdorff_tech_to_target *= scale;
  figures.hausdorff_target_to_tech *= scale;
  figures.hausdorff = std::max(figures.hausdorff_tech_to_target, figures.hausdorff_target_to_tech);
  figures.rms_distance =
      distance.empty() ? 0 : std::sqrt(sum_squares / double(distance.size())) * scale;
  return figures;
}

}  // namespace tb::measures
