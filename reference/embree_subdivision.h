// The same control mesh as Embree 3 subdivision geometry, evaluated with rtcInterpolate: the
// independent cross-check of LimitSurface on the meshes crossCheckIneligibility() accepts,
// to ~1e-6 of the model size (Embree evaluates in float). Tags: creases -> edge creases,
// corners -> vertex creases (sharpness >= 10 becomes +inf), holes -> the hole buffer;
// EDGE_AND_CORNER -> PIN_CORNERS, EDGE_ONLY -> SMOOTH_BOUNDARY (valence-2 corners differ),
// NONE -> NO_BOUNDARY. evaluate() may be called from several threads at once.
#pragma once

#include <cstddef>
#include <memory>

#include "core/mesh/mesh.h"
#include "reference/cross_check_eligibility.h"
#include "reference/limit_point.h"

namespace tb::ref {

class EmbreeSubdivision {
 public:
  // Throws InputError for meshes Embree cannot hold at all (a face with fewer than 3
  // or more than 15 corners, a non-finite coordinate). Meshes that are representable
  // but not eligible for the cross-check are accepted; see crossCheckIneligibility().
  explicit EmbreeSubdivision(const mesh::Mesh& mesh);
  ~EmbreeSubdivision();
  EmbreeSubdivision(EmbreeSubdivision&&) noexcept;
  EmbreeSubdivision& operator=(EmbreeSubdivision&&) noexcept;

  size_t faceCount() const;

  // (u,v) in Bfr's convention (face_domain.h), so results compare one to one with
  // LimitSurface::evaluate; derivatives are converted to per unit of face (u,v).
  // Throws InputError naming the face when it is out of range or outside the domain.
  LimitPoint evaluate(size_t face, double u, double v) const;

  // Embree's own (U,V) encoding; derivatives per unit of U and V.
  LimitPoint evaluateNative(size_t face, float u, float v) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::ref
