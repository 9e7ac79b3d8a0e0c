#include "harness/lod/error_bound.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <utility>

#include "core/mesh/topology.h"
#include "harness/lod/transition_extents.h"

namespace tb::lod {
namespace {

using techniques::CurvatureBounds;
using techniques::PatchDomain;

// `value` as the smallest float not below it.
float roundUp(double value) {
  float f = float(value);
  if (double(f) < value) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// A sphere around `points`: the box's centre rounded to float, the radius the largest
// distance from that float centre, rounded up.
std::array<float, 4> sphereAround(std::span<const mesh::Vec3d> points) {
  assert(!points.empty());
  mesh::Vec3d low = points[0], high = points[0];
  for (const mesh::Vec3d& p : points) {
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  }
  std::array<float, 4> sphere{};
  mesh::Vec3d centre;
  for (int k = 0; k < 3; ++k) {
    sphere[k] = float((low[k] + high[k]) * 0.5);
    centre[k] = double(sphere[k]);
  }
  double radius = 0;
  for (const mesh::Vec3d& p : points) radius = std::max(radius, length(p - centre));
  sphere[3] = roundUp(radius);
  return sphere;
}

// Outer edge j's corners (start, end) in patchCorners order: quad (3,0), (0,1), (1,2), (2,3);
// triangle (1,2), (2,0), (0,1) (factor_policy.cpp's order).
std::pair<size_t, size_t> edgeCorners(PatchDomain domain, size_t j) {
  if (domain == PatchDomain::kQuad) return {(j + 3) % 4, j};
  return {(j + 1) % 3, (j + 2) % 3};
}

size_t edgeCount(PatchDomain domain) { return domain == PatchDomain::kQuad ? 4 : 3; }

// One side of an edge: patch and outer index.
struct Side {
  uint32_t patch = 0, j = 0;
};

// Sides grouped by welded edge (canonical vertex pair), in patch order; map order is the
// pair's, so the grouping does not depend on threads.
std::vector<std::vector<Side>> edgeSides(const techniques::SurfacePatches& patches) {
  const mesh::Welding welding = mesh::weldByPosition(patches.controlMesh());
  std::map<std::pair<uint32_t, uint32_t>, std::vector<Side>> by_edge;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const PatchDomain domain = patches.patchDomain(p);
    const std::array<uint32_t, 4> corners = patches.patchCorners(p);
    for (size_t j = 0; j < edgeCount(domain); ++j) {
      const auto [a, b] = edgeCorners(domain, j);
      const uint32_t va = welding.canonical[corners[a]], vb = welding.canonical[corners[b]];
      by_edge[{std::min(va, vb), std::max(va, vb)}].push_back({uint32_t(p), uint32_t(j)});
    }
  }
  std::vector<std::vector<Side>> out;
  out.reserve(by_edge.size());
  for (auto& [key, sides] : by_edge) out.push_back(std::move(sides));
  return out;
}

// A patch's bound on the regular pattern of level o, times o^2 (over 8, as edge_m): the
// smaller of the box and circle bounds (transition_extents.h) with the pattern's widest
// triangles. Quads (uu + 2 uv + vv) / 8; the triangle domain's rings are wider.
double sideBound(const CurvatureBounds& b, PatchDomain domain) {
  const RingFactors k =
      ringFactors(domain == PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle);
  const double a = (b.uu + b.uv) / 8, c = (b.vv + b.uv) / 8;
  return std::min(a * k.u * k.u + c * k.v * k.v, 4 * std::max(a, c) * k.circle);
}

}  // namespace

ErrorBounds errorBounds(const techniques::SurfacePatches& patches) {
  const size_t count = patches.patchCount();
  std::vector<std::optional<CurvatureBounds>> bounds(count);
  tbb::parallel_for(size_t(0), count, [&](size_t p) { bounds[p] = patches.curvatureBounds(p); });
  ErrorBounds out;
  for (size_t p = 0; p < count; ++p) {
    if (!bounds[p]) {
      out.unavailable = "patch " + std::to_string(p) + " (face " +
                        std::to_string(patches.sourceFace(p)) +
                        ") has no second-derivative bound (techniques::CurvatureBounds)";
      return out;
    }
  }
  out.patches.resize(count);
  for (size_t p = 0; p < count; ++p) {
    const CurvatureBounds& b = *bounds[p];
    out.patches[p].patch_sphere = sphereAround(b.hull);
    out.patches[p].inner_a = roundUp((b.uu + b.uv) / 8);
    out.patches[p].inner_b = roundUp((b.vv + b.uv) / 8);
  }
  // Each edge once: the largest bound of its sides (its own curve's, and each side's patch
  // on a regular pattern of the edge's level: sideBound), a sphere around all their hulls.
  for (const std::vector<Side>& sides : edgeSides(patches)) {
    double m = 0;
    std::vector<mesh::Vec3d> points;
    for (const Side& side : sides) {
      const CurvatureBounds& b = *bounds[side.patch];
      m = std::max({m, b.edge[side.j] / 8, sideBound(b, patches.patchDomain(side.patch))});
      points.insert(points.end(), b.hull.begin(), b.hull.end());
    }
    const std::array<float, 4> sphere = sphereAround(points);
    const float edge_m = roundUp(m);
    for (const Side& side : sides) {
      out.patches[side.patch].edge_sphere[side.j] = sphere;
      out.patches[side.patch].edge_m[side.j] = edge_m;
    }
  }
  return out;
}

}  // namespace tb::lod
