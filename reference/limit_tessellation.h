// A dense triangle mesh of a limit surface at a chosen rate: the reference side of
// the distance measures (docs/MEASURES.md, error). Each vertex keeps the face and (u,v)
// it was evaluated at, so a closest point found on this mesh (triangle + barycentrics)
// maps back to a parametric location whose exact limit normal LimitSurface can give.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh/vec.h"
#include "reference/limit_surface.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::ref {

inline constexpr int kMaxTessellationRate = 1024;

struct LimitTessellation {
  std::vector<mesh::Vec3d> positions;   // limit points, world units
  std::vector<mesh::Vec3d> normals;     // unit limit normals
  std::vector<Triangle> triangles;      // counter-clockwise, as their control faces
  std::vector<uint32_t> triangle_face;  // control face of each triangle
  std::vector<uint32_t> vertex_face;    // control face each vertex was evaluated on
  std::vector<mesh::Vec2d> vertex_uv;   // its face (u,v) (face_domain.h)
  size_t faces_skipped = 0;             // faces without a limit surface (holes, ...)

  TriangleMeshRef view() const { return {positions, triangles}; }
};

// Rate n >= 1:
//  - a quad (Catmull-Clark) is an n x n grid of parameter cells, 2 triangles each;
//  - a Loop triangle has n segments per edge, n^2 triangles;
//  - each sub-face of another N-gon is a ceil(n/2) x ceil(n/2) grid, so with n even
//    every control edge carries n segments on both of its sides.
// Vertices are not shared between faces; points on a shared edge agree to round-off.
// Faces are evaluated in parallel (TBB); the result does not depend on scheduling.
// Throws InputError naming the option for a rate outside [1, kMaxTessellationRate].
// `faces`: when not empty, one flag per face; only flagged faces are tessellated (the others
// are left out without counting in faces_skipped).
LimitTessellation tessellateLimit(const LimitSurface& surface, int rate,
                                  std::span<const uint8_t> faces = {});

}  // namespace tb::ref
