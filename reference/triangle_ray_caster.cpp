#include "reference/triangle_ray_caster.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/mesh/input_error.h"
#include "reference/embree_device.h"
#include "reference/mesh_checks.h"

namespace tb::ref {

struct TriangleRayCaster::Impl {
  std::vector<mesh::Vec3d> positions;
  std::vector<Triangle> triangles;
  RTCScene scene = nullptr;

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
  }
};

namespace {

// The ray parameter of the plane hit on triangle (a, b, c), Moller & Trumbore (1997), in
// double, without the inside test: Embree has already chosen the triangle, so only its
// distance is refined. NaN when the ray is parallel to the triangle's plane.
double planeHitDistance(const mesh::Vec3d& origin, const mesh::Vec3d& direction,
                        const mesh::Vec3d& a, const mesh::Vec3d& b, const mesh::Vec3d& c) {
  const mesh::Vec3d e1 = b - a, e2 = c - a;
  const mesh::Vec3d p = cross(direction, e2);
  const double det = dot(e1, p);
  if (det == 0) return std::nan("");
  const mesh::Vec3d q = cross(origin - a, e1);
  return dot(e2, q) / det;
}

}  // namespace

TriangleRayCaster::TriangleRayCaster(std::span<const mesh::Vec3d> positions,
                                     std::span<const Triangle> triangles, const std::string& source)
    : impl_(std::make_unique<Impl>()) {
  checkFinitePositions(positions, source);
  checkTriangleCorners(triangles, positions.size(), source);
  impl_->positions.assign(positions.begin(), positions.end());
  impl_->triangles.assign(triangles.begin(), triangles.end());

  impl_->scene = rtcNewScene(sharedEmbreeDevice());
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  attachTriangleGeometry(impl_->scene, positions, triangles);
  rtcCommitScene(impl_->scene);
  throwOnEmbreeError(source, "triangle scene");
}

TriangleRayCaster::~TriangleRayCaster() = default;
TriangleRayCaster::TriangleRayCaster(TriangleRayCaster&&) noexcept = default;
TriangleRayCaster& TriangleRayCaster::operator=(TriangleRayCaster&&) noexcept = default;

size_t TriangleRayCaster::triangleCount() const { return impl_->triangles.size(); }

std::optional<RayHit> TriangleRayCaster::nearestHit(const mesh::Vec3d& origin,
                                                    const mesh::Vec3d& direction,
                                                    double max_distance) const {
  if (impl_->triangles.empty()) return std::nullopt;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit ray_hit{};
  ray_hit.ray.org_x = float(origin.x);
  ray_hit.ray.org_y = float(origin.y);
  ray_hit.ray.org_z = float(origin.z);
  ray_hit.ray.dir_x = float(direction.x);
  ray_hit.ray.dir_y = float(direction.y);
  ray_hit.ray.dir_z = float(direction.z);
  ray_hit.ray.tnear = 0.0f;
  ray_hit.ray.tfar =
      std::isinf(max_distance) ? std::numeric_limits<float>::infinity() : float(max_distance);
  ray_hit.ray.mask = 0xFFFFFFFFu;
  ray_hit.ray.flags = 0;
  ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  ray_hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &ray_hit);
  if (ray_hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const uint32_t id = ray_hit.hit.primID;
  const Triangle& tri = impl_->triangles[id];
  const std::vector<mesh::Vec3d>& p = impl_->positions;
  double distance = planeHitDistance(origin, direction, p[tri[0]], p[tri[1]], p[tri[2]]);
  // A grazing hit whose double plane distance is undefined keeps Embree's float one.
  if (!std::isfinite(distance)) distance = double(ray_hit.ray.tfar);
  return RayHit{std::max(distance, 0.0), id};
}

}  // namespace tb::ref
