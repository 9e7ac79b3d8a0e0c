// Unsigned distance from any point to a triangle mesh: an Embree BVH over the
// triangles (float, only to cull) queried with rtcPointQuery, and an exact
// closest-point-on-triangle callback in double (closest_point.h). Culling radii are
// padded for the float rounding of the BVH, so the answer is the exact double
// minimum over all triangles.
//
// Thread safety: closest() may be called from several threads at once.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "reference/triangle_mesh_ref.h"

namespace tb::ref {

inline constexpr uint32_t kNoTriangle = std::numeric_limits<uint32_t>::max();

struct ClosestPoint {
  double distance = std::numeric_limits<double>::infinity();  // world units; inf: no triangles
  mesh::Vec3d point;                                          // closest point on the mesh
  uint32_t triangle = kNoTriangle;  // its triangle (the lowest index on ties)
  mesh::Vec3d barycentric;          // its weights of the triangle's corners 0, 1, 2
};

class TriangleDistanceField {
 public:
  // Reads the mesh in place: `positions` and `triangles` must outlive the field (a
  // production asset's dense reference is millions of triangles; no copy is kept). Throws
  // InputError (naming `source`) for a corner index out of range or a non-finite coordinate.
  TriangleDistanceField(std::span<const mesh::Vec3d> positions, std::span<const Triangle> triangles,
                        const std::string& source = "triangle mesh");
  explicit TriangleDistanceField(const TriangleMeshRef& mesh,
                                 const std::string& source = "triangle mesh");
  ~TriangleDistanceField();
  TriangleDistanceField(TriangleDistanceField&&) noexcept;
  TriangleDistanceField& operator=(TriangleDistanceField&&) noexcept;

  size_t triangleCount() const;
  ClosestPoint closest(const mesh::Vec3d& query) const;
  // The same answer, bit for bit, found faster when `hint` is a triangle near the answer
  // (e.g. the previous answer of a coherent run of queries): the search starts with the
  // hint's distance as its radius instead of infinity. Any hint (kNoTriangle, or out of
  // range, included) is valid: the minimum and its tie-break (lowest triangle index)
  // do not depend on it.
  ClosestPoint closest(const mesh::Vec3d& query, uint32_t hint) const;
  // World units: the distance from `query` to triangle t < triangleCount(), computed as
  // closest() computes each triangle's (so never below closest(query).distance).
  double distanceTo(const mesh::Vec3d& query, uint32_t t) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::ref
