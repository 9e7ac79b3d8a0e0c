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

// A triangle's bounding box in double: the distance to it bounds the distance to the
// triangle from below, and costs a fraction of the exact closest point.
struct TriangleBox {
  mesh::Vec3d lo, hi;
  // The unit normal n and offset n . a of the plane through corner a: |n . q - offset| bounds
  // the distance from below too, up to rounding. Computing n tilts it by at most `tilt`
  // radians (a sliver's cross product cancels: 16 eps |b - a| |c - a| / |cross|), which moves
  // the bound by tilt |q - a|; n = 0 (no test) when degenerate.
  mesh::Vec3d normal, corner;
  double offset = 0, tilt = 0;
};

namespace {

inline double squaredDistanceToBox(const mesh::Vec3d& p, const TriangleBox& box) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const double below = box.lo[k] - p[k], above = p[k] - box.hi[k];
    const double gap = std::max({below, above, 0.0});
    sum += gap * gap;
  }
  return sum;
}

}  // namespace

struct TriangleDistanceField::Impl {
  std::vector<mesh::Vec3d> positions;
  std::vector<Triangle> triangles;
  std::vector<TriangleBox> boxes;  // per triangle
  double max_abs = 0;              // largest |coordinate| of the mesh
  RTCScene scene = nullptr;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }
};

namespace {

struct QueryState {
  const std::vector<mesh::Vec3d>* positions;
  const std::vector<Triangle>* triangles;
  const std::vector<TriangleBox>* boxes;
  mesh::Vec3d query;
  double pad;
  double plane_slack;  // world units: the plane test's rounding, far above it
  ClosestPoint best;
};

bool visitTriangle(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<QueryState*>(args->userPtr);
  const uint32_t id = args->primID;
  // A box farther than the best answer holds no better (or tying) point, since the box
  // contains the triangle; the slack of 1e-12 keeps rounding (a few ulps) from dropping a
  // triangle that ties with the best.
  const TriangleBox& box = (*state->boxes)[id];
  const double box_squared = squaredDistanceToBox(state->query, box);
  const double best_distance = state->best.distance;
  if (box_squared > best_distance * best_distance * (1 + 1e-12)) return false;
  const mesh::Vec3d& q = state->query;
  const double height = std::abs(dot(box.normal, q) - box.offset);
  const double reach = std::abs(q.x - box.corner.x) + std::abs(q.y - box.corner.y) +
                       std::abs(q.z - box.corner.z);  // >= |q - a|
  if (height - box.tilt * reach - state->plane_slack > best_distance * (1 + 1e-12)) return false;
  const Triangle& tri = (*state->triangles)[id];
  const std::vector<mesh::Vec3d>& p = *state->positions;
  const TrianglePoint hit = closestPointOnTriangle(state->query, p[tri[0]], p[tri[1]], p[tri[2]]);
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
  impl_->positions.assign(positions.begin(), positions.end());
  impl_->triangles.assign(triangles.begin(), triangles.end());
  impl_->boxes.reserve(triangles.size());
  for (const Triangle& tri : triangles) {
    TriangleBox box{positions[tri[0]], positions[tri[0]]};
    for (int c = 1; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], positions[tri[c]][k]);
        box.hi[k] = std::max(box.hi[k], positions[tri[c]][k]);
      }
    }
    const mesh::Vec3d& a = positions[tri[0]];
    const mesh::Vec3d e1 = positions[tri[1]] - a, e2 = positions[tri[2]] - a;
    const mesh::Vec3d n = cross(e1, e2);
    if (const double area2 = length(n); area2 > 0 && std::isfinite(area2)) {
      box.normal = n * (1 / area2);
      box.corner = a;
      box.offset = dot(box.normal, a);
      box.tilt = 16 * std::numeric_limits<double>::epsilon() * length(e1) * length(e2) / area2;
    }
    impl_->boxes.push_back(box);
  }

  impl_->scene = rtcNewScene(sharedEmbreeDevice());
  attachTriangleGeometry(impl_->scene, positions, triangles);
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
  QueryState state{&impl_->positions,
                   &impl_->triangles,
                   &impl_->boxes,
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
  const std::vector<mesh::Vec3d>& p = impl_->positions;
  return length(closestPointOnTriangle(query, p[tri[0]], p[tri[1]], p[tri[2]]).point - query);
}

}  // namespace tb::ref
