#include "reference/triangle_distance_field.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "core/mesh/input_error.h"
#include "reference/closest_point.h"
#include "reference/embree_device.h"
#include "reference/mesh_checks.h"

namespace tb::ref {
namespace {

// Float rounding moves a BVH box, and the float query point, by at most 2^-24 of the
// coordinates' magnitude each; culling with a radius padded by 2^-18 of it (64 times
// that) never drops a triangle that could hold the double minimum.
constexpr double kRadiusPad = 0x1p-18;

double maxAbsCoordinate(const mesh::Vec3d& p) {
  return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

}  // namespace

// A triangle's plane: the unit normal n and offset n . a of the plane through its first
// corner a. |n . q - offset| bounds the distance from below, up to rounding. Computing n tilts
// it by at most `tilt` radians (a sliver's cross product cancels: 16 eps |b - a| |c - a| /
// |cross|), which moves the bound by tilt |q - a|; n = 0 (no test) when degenerate. 40 bytes a
// triangle: with the boxes kept as well (they are computed from the corners at query time),
// a production asset's dense reference of 11 million triangles needed 0.8 GB more.
struct TrianglePlane {
  mesh::Vec3d normal;
  double offset = 0, tilt = 0;
};

namespace {

// The squared distance from p to the bounding box of a, b, c (in double): it bounds the
// distance to the triangle from below, and costs a fraction of the exact closest point.
inline double squaredDistanceToBox(const mesh::Vec3d& p, const mesh::Vec3d& a, const mesh::Vec3d& b,
                                   const mesh::Vec3d& c) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double lo = std::min({a[k], b[k], c[k]}), hi = std::max({a[k], b[k], c[k]});
    const double gap = std::max({lo - p[k], p[k] - hi, 0.0});
    sum += gap * gap;
  }
  return sum;
}

}  // namespace

struct TriangleDistanceField::Impl {
  std::span<const mesh::Vec3d> positions;  // the caller's (TriangleDistanceField's contract)
  std::span<const Triangle> triangles;
  std::vector<TrianglePlane> planes;  // per triangle
  double max_abs = 0;                 // largest |coordinate| of the mesh
  RTCScene scene = nullptr;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }
};

namespace {

struct QueryState {
  std::span<const mesh::Vec3d> positions;
  std::span<const Triangle> triangles;
  const std::vector<TrianglePlane>* planes;
  mesh::Vec3d query;
  double pad;
  double plane_slack;  // world units: the plane test's rounding, far above it
  ClosestPoint best;
};

bool visitTriangle(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<QueryState*>(args->userPtr);
  const uint32_t id = args->primID;
  const Triangle& tri = state->triangles[id];
  const std::span<const mesh::Vec3d> p = state->positions;
  const mesh::Vec3d& a = p[tri[0]];
  const double box_squared = squaredDistanceToBox(state->query, a, p[tri[1]], p[tri[2]]);
  const double best_distance = state->best.distance;
  if (box_squared > best_distance * best_distance * (1 + 1e-12)) return false;
  const TrianglePlane& plane = (*state->planes)[id];
  const mesh::Vec3d& q = state->query;
  const double height = std::abs(dot(plane.normal, q) - plane.offset);
  const double reach =
      std::abs(q.x - a.x) + std::abs(q.y - a.y) + std::abs(q.z - a.z);  // >= |q - a|
  if (height - plane.tilt * reach - state->plane_slack > best_distance * (1 + 1e-12)) return false;
  const TrianglePoint hit = closestPointOnTriangle(q, a, p[tri[1]], p[tri[2]]);
  const double distance = length(hit.point - state->query);
  ClosestPoint& best = state->best;
  if (distance > best.distance || (distance == best.distance && id > best.triangle)) return false;
  best = {distance, hit.point, id, hit.barycentric};
  args->query->radius =
      std::nextafter(float(distance + state->pad), std::numeric_limits<float>::infinity());
  return true;
}

}  // namespace

TriangleDistanceField::TriangleDistanceField(const TriangleMeshRef& mesh, const std::string& source)
    : TriangleDistanceField(mesh.positions, mesh.triangles, source) {}

TriangleDistanceField::TriangleDistanceField(std::span<const mesh::Vec3d> positions,
                                             std::span<const Triangle> triangles,
                                             const std::string& source)
    : impl_(std::make_unique<Impl>()) {
  checkFinitePositions(positions, source);
  for (const mesh::Vec3d& q : positions)
    impl_->max_abs = std::max(impl_->max_abs, maxAbsCoordinate(q));
  checkTriangleCorners(triangles, positions.size(), source);
  impl_->positions = positions;
  impl_->triangles = triangles;
  impl_->planes.reserve(triangles.size());
  for (const Triangle& tri : triangles) {
    TrianglePlane plane;
    const mesh::Vec3d& a = positions[tri[0]];
    const mesh::Vec3d e1 = positions[tri[1]] - a, e2 = positions[tri[2]] - a;
    const mesh::Vec3d n = cross(e1, e2);
    if (const double area2 = length(n); area2 > 0 && std::isfinite(area2)) {
      plane.normal = n * (1 / area2);
      plane.offset = dot(plane.normal, a);
      plane.tilt = 16 * std::numeric_limits<double>::epsilon() * length(e1) * length(e2) / area2;
    }
    impl_->planes.push_back(plane);
  }

  impl_->scene = rtcNewScene(sharedEmbreeDevice());
  // Compact: about half the BVH's memory; the closest point does not depend on the tree.
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_COMPACT);
  attachTriangleGeometry(impl_->scene, positions, triangles, /*share_triangles=*/true);
  rtcCommitScene(impl_->scene);
  throwOnEmbreeError(source, "triangle scene");
}

TriangleDistanceField::~TriangleDistanceField() = default;
TriangleDistanceField::TriangleDistanceField(TriangleDistanceField&&) noexcept = default;
TriangleDistanceField& TriangleDistanceField::operator=(TriangleDistanceField&&) noexcept = default;

size_t TriangleDistanceField::triangleCount() const { return impl_->triangles.size(); }

ClosestPoint TriangleDistanceField::closest(const mesh::Vec3d& query) const {
  return closest(query, kNoTriangle);
}

ClosestPoint TriangleDistanceField::closest(const mesh::Vec3d& query, uint32_t hint) const {
  QueryState state{impl_->positions,
                   impl_->triangles,
                   &impl_->planes,
                   query,
                   kRadiusPad * (impl_->max_abs + maxAbsCoordinate(query)),
                   1e-12 * (impl_->max_abs + maxAbsCoordinate(query)),
                   {}};
  if (impl_->triangles.empty()) return state.best;
  RTCPointQuery point_query;
  point_query.x = float(query.x);
  point_query.y = float(query.y);
  point_query.z = float(query.z);
  point_query.time = 0;
  point_query.radius = std::numeric_limits<float>::infinity();
  if (hint < impl_->triangles.size()) {
    // The hint's distance bounds the minimum. It is not kept as the best: the traversal
    // visits it again inside the padded radius, so the answer is found exactly as
    // without a hint, only with fewer BVH nodes opened.
    const double distance = distanceTo(query, hint);
    point_query.radius =
        std::nextafter(float(distance + state.pad), std::numeric_limits<float>::infinity());
  }
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &point_query, &context, visitTriangle, &state);
  return state.best;
}

double TriangleDistanceField::distanceTo(const mesh::Vec3d& query, uint32_t t) const {
  assert(t < impl_->triangles.size());
  const Triangle& tri = impl_->triangles[t];
  const std::span<const mesh::Vec3d> p = impl_->positions;
  return length(closestPointOnTriangle(query, p[tri[0]], p[tri[1]], p[tri[2]]).point - query);
}

}  // namespace tb::ref
