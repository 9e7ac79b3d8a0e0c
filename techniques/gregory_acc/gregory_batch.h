// Batched evaluation of Gregory patches (techniques/batch_eval.h). For a fixed domain
// point a quad (20 control points) or triangle (15) Gregory patch is linear in its
// control points: the rational interior blends (a Fp + b Fm) / (a + b) and their
// derivatives weigh Fp and Fm with functions of (u, v) alone (Loop et al. 2009 eq. 2).
// So position, du and dv are each Σ_k w_k(u, v) cp_k, and the pattern tabulates the
// w_k once: a quad patch then costs 3 · 3 · 20 = 180 multiply-adds per point, a triangle
// 3 · 3 · 15 = 135.
//
// The weights come from the evaluator itself (gregory_eval.h) run on unit control
// points, so the batched surface is the per-point surface by construction, edge rules
// (symmetric_edges) and the corner case of the blend included.
#pragma once

#include <vector>

#include "techniques/batch_eval.h"
#include "techniques/common/basis_table.h"
#include "techniques/gregory_acc/gregory_eval.h"

namespace tb::gregory_acc {

class GregoryBatchPattern final : public techniques::BatchPattern {
 public:
  GregoryBatchPattern(techniques::PatchDomain domain, std::vector<techniques::DomainCoord> coords,
                      techniques::BatchOutput output, bool symmetric_edges);
  double multiplyAddsPerPoint() const override { return 9.0 * double(controlPoints()); }
  bool symmetricEdges() const { return symmetric_edges_; }
  // Every point of the pattern on the patch with these control points.
  void evaluate(const GregoryPoints<double>& patch, techniques::BatchPoints& out) const;

 private:
  size_t controlPoints() const { return position_.controlPoints(); }
  bool symmetric_edges_;
  techniques::BasisTable position_, tangent_u_, tangent_v_;
};

}  // namespace tb::gregory_acc
