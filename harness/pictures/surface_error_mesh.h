// A technique's surface tessellated on the CPU, with its parametric error against the
// limit at every vertex: what the error and wireframe pictures draw.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh/bounds.h"
#include "core/mesh/vec.h"
#include "reference/limit_surface.h"
#include "techniques/technique.h"

namespace tb::pictures {

struct SurfaceErrorMesh {
  // Every patch's tessellation vertices, patch by patch, in world units (positions from
  // the double evaluator, patches.evaluate).
  std::vector<mesh::Vec3d> positions;
  // Per vertex: |S - limit| at the same parameter (harness/measures/error/error.h,
  // parametricErrorAt), a fraction of the control mesh's bounding-box diagonal. NaN on
  // patches whose face has no limit surface (holes).
  std::vector<double> vertex_error;
  // Indices into positions, in the tessellator's winding (layout(ccw): front faces
  // counter-clockwise seen from outside a closed surface), patch by patch.
  std::vector<std::array<uint32_t, 3>> triangles;
  // Per triangle: the largest error of its three vertices (NaN when they have none): a
  // triangle is coloured by its worst corner, so the picture never hides a peak.
  std::vector<double> triangle_error;
  double error_max = 0;  // over every vertex with a limit; fraction of the diagonal
  size_t patches_without_limit = 0;
  mesh::Aabb bounds;  // of the tessellated positions, world units
};

// Tessellates every patch with the CPU tessellator (core/tess, bit-exact with lavapipe)
// at uniform integer level `level` (1..64) and grades every vertex against `limit`, which
// must be built over patches.controlMesh() under the scheme patches.approximates() names
// (as the error measure builds it). Patches run in parallel (TBB) into fixed slots, so the
// result does not depend on the thread count. Throws std::logic_error like
// measureSurfaceError for a patch domain the limit cannot be mapped to.
// Cost: one double evaluation and one limit evaluation per vertex ((level + 1)^2 on a quad
// patch, 61 on a triangle patch at level 8).
SurfaceErrorMesh tessellateWithError(const techniques::SurfacePatches& patches,
                                     const ref::LimitSurface& limit, int level);

}  // namespace tb::pictures
