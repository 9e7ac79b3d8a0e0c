// Render vertices that follow the simulated mesh through barycentric coordinates of a
// virtual tetrahedron (seed 003, "vertex buffer update"): each render vertex is bound to a
// simulated triangle p0 p1 p2 and its apex p3, and is
//   DrawVertex = p0 w0 + p1 w1 + p2 w2 + p3 (1 - w0 - w1 - w2).
// For a triangle mesh the apex is virtual, built so the tetrahedron keeps its rest volume:
// p3 = centroid + n * 3V / area (n the unit normal of p0 p1 p2), so a render vertex off the
// simulated surface keeps its distance when the triangle moves rigidly. The rendered mesh
// can therefore differ from the simulated one (here: the simulated quads' tessellation).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"

namespace tb::mass_spring {

struct TetBinding {
  uint32_t v0 = 0, v1 = 0, v2 = 0;  // simulated vertices of the triangle
  double w0 = 0, w1 = 0, w2 = 0;    // barycentric weights; the apex has 1 - w0 - w1 - w2
  double volume = 0;                // the virtual tetrahedron's rest volume (m^3)
};

// The virtual apex of triangle p0 p1 p2 for a tetrahedron of `volume`.
mesh::Vec3d virtualApex(const mesh::Vec3d& p0, const mesh::Vec3d& p1, const mesh::Vec3d& p2,
                        double volume);

// Binds the point q to triangle (v0, v1, v2) of `rest`, with a rest apex at height
// `apex_height` above the centroid (the tetrahedron's volume is area * height / 3).
TetBinding bindToTriangle(const std::vector<mesh::Vec3d>& rest, uint32_t v0, uint32_t v1,
                          uint32_t v2, const mesh::Vec3d& q, double apex_height);

// DrawVertex of `binding` over the current simulated positions.
mesh::Vec3d drawVertex(const TetBinding& binding, const std::vector<mesh::Vec3d>& positions);
// The same in float, in the operation order of shaders/mass_spring/render.comp (the weights
// and volume rounded to float, as the GPU holds them).
mesh::Vec3f drawVertexFloat(const TetBinding& binding, const std::vector<mesh::Vec3f>& positions);

// A rendered mesh: the simulated mesh's faces tessellated uniformly at `level` (bilinear
// on quads, linear on triangles, fan triangles on larger polygons), each point bound to the
// fan triangle of its face that contains it, with an apex at `apex_height` metres.
struct RenderMesh {
  std::vector<TetBinding> bindings;         // one per render vertex (points on shared edges repeat)
  std::vector<mesh::Vec3d> rest_positions;  // the render vertices at rest
  std::vector<uint32_t> triangles;          // 3 indices per triangle into bindings
};
RenderMesh tessellateForRendering(const mesh::Mesh& mesh, uint32_t level, double apex_height);

}  // namespace tb::mass_spring
