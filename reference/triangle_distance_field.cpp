#include "reference/triangle_distance_field.h"

#include <embree3/rtcore.h>

#include <algorithm>
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

double maxAbsCoordinate(const Vec3d& p) {
  return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

}  // namespace

struct TriangleDistanceField::Impl {
  std::vector<Vec3d> positions;
  std::vector<Triangle> triangles;
  double max_abs = 0;  // largest |coordinate| of the mesh
  RTCScene scene = nullptr;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }
};

namespace {

struct QueryState {
  const std::vector<Vec3d>* positions;
  const std::vector<Triangle>* triangles;
  Vec3d query;
  double pad;
  ClosestPoint best;
};

bool visitTriangle(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<QueryState*>(args->userPtr);
  const uint32_t id = args->primID;
  const Triangle& tri = (*state->triangles)[id];
  const std::vector<Vec3d>& p = *state->positions;
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

TriangleDistanceField::TriangleDistanceField(std::span<const Vec3d> positions,
                                             std::span<const Triangle> triangles,
                                             const std::string& source)
    : impl_(std::make_unique<Impl>()) {
  checkFinitePositions(positions, source);
  for (const Vec3d& q : positions) impl_->max_abs = std::max(impl_->max_abs, maxAbsCoordinate(q));
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (uint32_t corner : triangles[t]) {
      if (corner >= positions.size()) {
        throw InputError(source, "triangle " + std::to_string(t),
                         "corner index " + std::to_string(corner) + " is out of range (" +
                             std::to_string(positions.size()) + " vertices)");
      }
    }
  }
  impl_->positions.assign(positions.begin(), positions.end());
  impl_->triangles.assign(triangles.begin(), triangles.end());

  const RTCDevice device = sharedEmbreeDevice();
  impl_->scene = rtcNewScene(device);
  if (triangles.empty()) {
    rtcCommitScene(impl_->scene);
    throwOnEmbreeError(source, "triangle scene");
    return;
  }
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Padded to 16 bytes with a zero: Embree loads vertices as 4 floats.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 4 * sizeof(float), positions.size()));
  for (size_t i = 0; i < positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) vertices[4 * i + size_t(k)] = float(positions[i][k]);
    vertices[4 * i + 3] = 0.0f;
  }
  auto* indices = static_cast<uint32_t*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(uint32_t), triangles.size()));
  for (size_t t = 0; t < triangles.size(); ++t) {
    std::copy(triangles[t].begin(), triangles[t].end(), indices + 3 * t);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(impl_->scene, geometry);
  rtcReleaseGeometry(geometry);  // the scene holds it
  rtcCommitScene(impl_->scene);
  throwOnEmbreeError(source, "triangle scene");
}

TriangleDistanceField::~TriangleDistanceField() = default;
TriangleDistanceField::TriangleDistanceField(TriangleDistanceField&&) noexcept = default;
TriangleDistanceField& TriangleDistanceField::operator=(TriangleDistanceField&&) noexcept = default;

size_t TriangleDistanceField::triangleCount() const { return impl_->triangles.size(); }

ClosestPoint TriangleDistanceField::closest(const Vec3d& query) const {
  QueryState state{&impl_->positions,
                   &impl_->triangles,
                   query,
                   kRadiusPad * (impl_->max_abs + maxAbsCoordinate(query)),
                   {}};
  if (impl_->triangles.empty()) return state.best;
  RTCPointQuery point_query;
  point_query.x = float(query.x);
  point_query.y = float(query.y);
  point_query.z = float(query.z);
  point_query.time = 0;
  point_query.radius = std::numeric_limits<float>::infinity();
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(impl_->scene, &point_query, &context, visitTriangle, &state);
  return state.best;
}

}  // namespace tb::ref
