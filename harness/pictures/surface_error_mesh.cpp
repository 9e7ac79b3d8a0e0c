#include "harness/pictures/surface_error_mesh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/tess/tessellator.h"
#include "harness/measures/error/error.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::pictures {
namespace {

constexpr double kNoError = std::numeric_limits<double>::quiet_NaN();

// gl_TessCoord as the technique takes it (techniques/batch_eval.h): quads (u, v, 0),
// triangles the barycentric weights of corners 0, 1, 2.
techniques::DomainCoord domainCoord(techniques::PatchDomain domain, const tess::DomainPoint& p) {
  return domain == techniques::PatchDomain::kQuad ? techniques::DomainCoord{p[0], p[1], 0}
                                                  : techniques::DomainCoord{p[0], p[1], p[2]};
}

}  // namespace

SurfaceErrorMesh tessellateWithError(const techniques::SurfacePatches& patches,
                                     const ref::LimitSurface& limit, int level) {
  if (level < 1 || level > 64) {
    throw std::invalid_argument("tessellateWithError: level " + std::to_string(level) +
                                " outside 1..64");
  }
  const osd::Scheme scheme = lod::referenceScheme(patches.approximates());
  tess::Levels levels;
  levels.outer = {float(level), float(level), float(level), float(level)};
  levels.inner = {float(level), float(level)};
  const std::array<tess::Tessellation, 2> patterns = {
      tess::tessellate(tess::Domain::kTriangle, tess::Spacing::kInteger, levels),
      tess::tessellate(tess::Domain::kQuad, tess::Spacing::kInteger, levels)};
  auto patternOf = [&](size_t p) -> const tess::Tessellation& {
    return patterns[patches.patchDomain(p) == techniques::PatchDomain::kQuad ? 1 : 0];
  };

  // Where each patch's vertices and triangles start, so patches fill fixed slots.
  const size_t patch_count = patches.patchCount();
  std::vector<size_t> first_vertex(patch_count + 1, 0), first_triangle(patch_count + 1, 0);
  for (size_t p = 0; p < patch_count; ++p) {
    first_vertex[p + 1] = first_vertex[p] + patternOf(p).points.size();
    first_triangle[p + 1] = first_triangle[p] + patternOf(p).triangles.size();
  }
  SurfaceErrorMesh mesh;
  mesh.positions.resize(first_vertex[patch_count]);
  mesh.vertex_error.resize(first_vertex[patch_count]);
  mesh.triangles.resize(first_triangle[patch_count]);
  const double diagonal = ref::boundingBoxDiagonal(patches.controlMesh().positions);
  const double scale = diagonal > 0 ? 1 / diagonal : 0;
  tbb::parallel_for(size_t(0), patch_count, [&](size_t p) {
    const techniques::PatchDomain domain = patches.patchDomain(p);
    const tess::Tessellation& pattern = patternOf(p);
    const bool has_limit = limit.hasLimitSurface(p);
    for (size_t k = 0; k < pattern.points.size(); ++k) {
      mesh.positions[first_vertex[p] + k] =
          patches.evaluate(p, domainCoord(domain, pattern.points[k])).position;
    }
    if (has_limit) {
      const ref::LimitFace face = limit.face(p);
      for (size_t k = 0; k < pattern.points.size(); ++k) {
        mesh.vertex_error[first_vertex[p] + k] =
            measures::parametricErrorAt(patches, face, scheme, p,
                                        domainCoord(domain, pattern.points[k])) *
            scale;
      }
    } else {
      std::fill_n(mesh.vertex_error.begin() + ptrdiff_t(first_vertex[p]), pattern.points.size(),
                  kNoError);
    }
    const uint32_t base = uint32_t(first_vertex[p]);
    for (size_t t = 0; t < pattern.triangles.size(); ++t) {
      const auto& tri = pattern.triangles[t];
      mesh.triangles[first_triangle[p] + t] = {base + tri[0], base + tri[1], base + tri[2]};
    }
  });
  // Serial reductions, in vertex order.
  mesh.triangle_error.resize(mesh.triangles.size());
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    double worst = kNoError;
    for (uint32_t v : mesh.triangles[t]) {
      const double e = mesh.vertex_error[v];
      if (!std::isnan(e)) worst = std::isnan(worst) ? e : std::max(worst, e);
    }
    mesh.triangle_error[t] = worst;
  }
  for (size_t p = 0; p < patch_count; ++p) mesh.patches_without_limit += !limit.hasLimitSurface(p);
  for (double e : mesh.vertex_error) {
    if (!std::isnan(e)) mesh.error_max = std::max(mesh.error_max, e);
  }
  if (!mesh.positions.empty()) {
    mesh.bounds = {mesh.positions.front(), mesh.positions.front()};
    for (const mesh::Vec3d& q : mesh.positions) {
      for (int i = 0; i < 3; ++i) {
        mesh.bounds.min[i] = std::min(mesh.bounds.min[i], q[i]);
        mesh.bounds.max[i] = std::max(mesh.bounds.max[i], q[i]);
      }
    }
  }
  return mesh;
}

}  // namespace tb::pictures
