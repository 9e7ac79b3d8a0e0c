// Batched evaluation of acc patches (techniques/batch_eval.h): at a fixed (u, v) the
// geometry patch and both tangent patches are linear in their control points, with
// tensor-product Bernstein weights (bezier_eval.h):
//   position  Σ B3_i(u) B3_j(v) b[i + 4 j]       16 control points
//   du        Σ B2_i(u) B3_j(v) tu[i + 3 j]      12 (the ∂/∂u tangent patch)
//   dv        Σ B3_i(u) B2_j(v) tv[i + 4 j]      12 (the ∂/∂v tangent patch)
// The pattern tabulates the 40 weights of every point once; a patch then costs
// 3 · 40 = 120 multiply-adds per point. The normal, when asked for, is
// normalize(du x dv) as evaluate() computes it.
#pragma once

#include <vector>

#include "techniques/acc/acc_patch.h"
#include "techniques/batch_eval.h"
#include "techniques/common/basis_table.h"

namespace tb::acc {

class AccBatchPattern final : public techniques::BatchPattern {
 public:
  // Quad domain points (u, v, unused).
  AccBatchPattern(std::vector<techniques::DomainCoord> coords, techniques::BatchOutput output);
  double multiplyAddsPerPoint() const override { return 3.0 * (16 + 12 + 12); }
  // Every point of the pattern on the patch with these control points.
  void evaluate(const AccControlPoints<double>& patch, techniques::BatchPoints& out) const;

 private:
  techniques::BasisTable geometry_, tangent_u_, tangent_v_;
};

}  // namespace tb::acc
