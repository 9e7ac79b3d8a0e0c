// Exact closest point on one triangle, in double.
#pragma once

#include "core/mesh/vec.h"

namespace tb::ref {

struct TrianglePoint {
  mesh::Vec3d point;        // closest point of the triangle to the query
  mesh::Vec3d barycentric;  // weights of corners a, b, c (sum 1, each in [0,1])
};

// Ericson, Real-Time Collision Detection (2005), section 5.1.5: classify the query
// against the Voronoi regions of the three vertices, then the three edges, and fall
// through to the face, so only the region that holds the answer does any division.
// Degenerate (zero-area) triangles are answered as the closest of their three edges.
TrianglePoint closestPointOnTriangle(const mesh::Vec3d& p, const mesh::Vec3d& a,
                                     const mesh::Vec3d& b, const mesh::Vec3d& c);

}  // namespace tb::ref
