// OpenSubdiv's ways of evaluating position and first derivatives (double) at fixed points
// of every face of a Catmull-Clark mesh, prepared before timing, for the evaluation
// benchmark's side-by-side rows. Each evaluates the same points: a list of (u, v) in the
// face's domain, the same on every face (a lattice), on meshes of quads only.
//
//   bfr_surface        Bfr::Surface<double> per face from a RefinerSurfaceFactory, patch
//                      points prepared once per face, Surface::Evaluate(uv, P, Du, Dv)
//                      per point (at the reference's ApproxLevel 10, or OpenSubdiv's
//                      default levels 2 smooth / 6 sharp)
//   far_patch_map      adaptive Far::PatchTable (Gregory end caps, double), all refined and
//                      local points computed once, then per point PatchMap::FindPatch,
//                      PatchTable::EvaluateBasis and the sum over the patch's points
//   far_limit_stencils Far::LimitStencilTable (double) of every point, built once; per point
//                      the sum of its stencil (position, du and dv weights) over the mesh
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"

namespace tb::bench {

class OsdEvaluation {
 public:
  virtual ~OsdEvaluation() = default;
  // Every point of every face once, positions and derivatives written to an internal
  // buffer; returns the points evaluated.
  virtual int64_t evaluateAll() = 0;
  // After evaluateAll: point i of face f (position, du, dv).
  virtual mesh::Vec3d position(size_t face, size_t i) const = 0;
  virtual mesh::Vec3d du(size_t face, size_t i) const = 0;
  virtual mesh::Vec3d dv(size_t face, size_t i) const = 0;
  // Multiply-adds of the per-point sums where they are plain weighted sums (the limit
  // stencils: 9 per stencil entry), else 0.
  virtual double multiplyAddsPerPoint() const { return 0; }
};

// `approx_level`: Bfr's ApproxLevelSmooth; the sharp level is max(approx_level, 6).
// Throws std::runtime_error for a mesh with non-quad faces.
std::unique_ptr<OsdEvaluation> makeBfrSurfaces(const mesh::Mesh& mesh,
                                               const std::vector<mesh::Vec2d>& uv,
                                               int approx_level);
// `isolation`: the adaptive refinement level of the patch table / stencils.
std::unique_ptr<OsdEvaluation> makePatchMap(const mesh::Mesh& mesh,
                                            const std::vector<mesh::Vec2d>& uv, int isolation);
std::unique_ptr<OsdEvaluation> makeLimitStencils(const mesh::Mesh& mesh,
                                                 const std::vector<mesh::Vec2d>& uv, int isolation);

}  // namespace tb::bench
