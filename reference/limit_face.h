// One face of a LimitSurface, prepared for evaluation: Bfr's patch for the face and
// its patch points, computed once. Evaluating a prepared face costs one patch
// evaluation per point. A LimitFace refers to its LimitSurface, which must outlive it.
// It is not shared between threads; prepare one per thread instead.
#pragma once

#include <cstddef>
#include <memory>

#include "core/mesh/vec.h"
#include "reference/limit_point.h"

namespace tb::ref {

class LimitFace {
 public:
  ~LimitFace();
  LimitFace(LimitFace&&) noexcept;
  LimitFace& operator=(LimitFace&&) noexcept;

  size_t index() const;  // face index in the control mesh
  int faceSize() const;  // corners of the control face
  bool isRegular() const;
  int subFaceCount() const;  // face_domain.h: N for N-gons with sub-faces, else 1

  // (u,v) in the face's domain (face_domain.h). Throws InputError outside it.
  LimitPoint evaluate(double u, double v) const;
  // Normalised sub-face coordinates (s,t) in [0,1]^2 of sub-face k; derivatives are
  // still per unit of the face's (u,v).
  LimitPoint evaluateSubFace(int sub_face, double s, double t) const;

  struct Impl;

 private:
  friend class LimitSurface;
  explicit LimitFace(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tb::ref
