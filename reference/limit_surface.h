// The exact limit surface of a Catmull-Clark or Loop control mesh, evaluated in
// double with OpenSubdiv 3.5 Bfr (docs/ARCHITECTURE.md §7). Creases, corners,
// holes and boundary interpolation come from the mesh's `t` tags.
//
// (u,v) follows Bfr's parameterisation of each face; face_domain.h says what it means
// for quads, Loop triangles and the quad sub-faces of other N-gons.
//
// Thread safety: every const member may be called from several threads at once. The
// factory's cache of irregular patches is guarded by a shared mutex
// (Bfr::SurfaceFactoryCacheThreaded).
#pragma once

#include <cstddef>
#include <memory>
#include <span>

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"
#include "reference/limit_face.h"
#include "reference/limit_point.h"

namespace tb::ref {

// Deepest Bfr approximation level OpenSubdiv 3.5.0 evaluates correctly; deeper levels
// crash or return garbage, so they are rejected.
inline constexpr int kMaxApproxLevel = 10;

struct LimitOptions {
  // Bfr::SurfaceFactory::Options: how many levels irregular (smooth) and sharp
  // neighbourhoods are refined before Bfr approximates them with Gregory or linear
  // patches. OpenSubdiv's defaults (2 and 6) leave errors of ~3e-3 of the bounding-box
  // diagonal near extraordinary vertices; 10 puts them below double round-off for
  // display purposes. Valid range [1, kMaxApproxLevel].
  int approx_level_smooth = kMaxApproxLevel;
  int approx_level_sharp = kMaxApproxLevel;
};

class LimitSurface {
 public:
  // Copies what it needs from `mesh`. Throws InputError for an option out of range
  // (naming the option), a non-finite coordinate, and any mesh the reference cannot
  // represent (see osd::buildTopologyRefiner: e.g. a non-triangle face for Loop, or topology
  // OpenSubdiv rejects).
  LimitSurface(const mesh::Mesh& mesh, osd::Scheme scheme, const LimitOptions& options = {});
  ~LimitSurface();
  LimitSurface(LimitSurface&&) noexcept;
  LimitSurface& operator=(LimitSurface&&) noexcept;

  osd::Scheme scheme() const;
  const mesh::Mesh& mesh() const;  // the control mesh as copied at construction
  size_t faceCount() const;

  // False for hole faces, and for faces on a boundary when `interpolateboundary` is
  // none: neither has a limit surface. Throws InputError for an out-of-range face.
  bool hasLimitSurface(size_t face) const;
  // True when Bfr represents the face by one regular B-spline (or box-spline) patch.
  // Throws InputError like face().
  bool isRegular(size_t face) const;

  // Prepares one face for many evaluations (the fast path). Throws InputError naming
  // the face when it is out of range or has no limit surface, with the reason.
  LimitFace face(size_t face) const;

  // One point; prepares the face each call. Throws like face(), and for (u,v) outside
  // the face's domain.
  LimitPoint evaluate(size_t face, double u, double v) const;
  // Many points of one face; out.size() must equal uv.size().
  void evaluate(size_t face, std::span<const mesh::Vec2d> uv, std::span<LimitPoint> out) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::ref
