// Batched evaluation of Gregory patches (techniques/batch_eval.h). At a fixed domain point a
// Gregory patch is linear in its control points (Loop et al. 2009 eq. 2), so the pattern
// tabulates each point's weights once (180 multiply-adds a point on a quad, 135 on a
// triangle); the weights come from gregory_eval.h run on unit control points, so the batch is
// the per-point surface by construction (docs/derivations/acc_gregory.md).
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
