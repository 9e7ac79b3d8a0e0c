// Nearest ray hits on a triangle mesh: an Embree BVH over the triangles (float, rtcIntersect1)
// finds the hit triangle, and the distance is then recomputed in double on that triangle
// (Moller & Trumbore 1997), so a hit's distance carries double, not float, rounding.
//
// Thread safety: nearestHit() may be called from several threads at once.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "reference/triangle_mesh_ref.h"

namespace tb::ref {

struct RayHit {
  double distance = 0;  // along the unit direction, world units (>= 0)
  uint32_t triangle = 0;
};

class TriangleRayCaster {
 public:
  // Copies the mesh. Throws InputError (naming `source`) for a corner index out of range or
  // a non-finite coordinate. The scene is built robust (RTC_SCENE_FLAG_ROBUST), so a ray
  // through a shared edge does not slip between its two triangles.
  TriangleRayCaster(std::span<const mesh::Vec3d> positions, std::span<const Triangle> triangles,
                    const std::string& source = "triangle mesh");
  ~TriangleRayCaster();
  TriangleRayCaster(TriangleRayCaster&&) noexcept;
  TriangleRayCaster& operator=(TriangleRayCaster&&) noexcept;

  size_t triangleCount() const;
  // The first hit of the ray origin + t * direction, 0 <= t <= max_distance (direction of unit
  // length, world units), either side of a triangle; nullopt when it hits nothing.
  std::optional<RayHit> nearestHit(
      const mesh::Vec3d& origin, const mesh::Vec3d& direction,
      double max_distance = std::numeric_limits<double>::infinity()) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::ref
