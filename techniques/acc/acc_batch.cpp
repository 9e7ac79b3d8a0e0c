#include "techniques/acc/acc_batch.h"

#include "techniques/common/bezier_eval.h"

namespace tb::acc {

AccBatchPattern::AccBatchPattern(std::vector<techniques::DomainCoord> coords,
                                 techniques::BatchOutput output)
    : techniques::BatchPattern(techniques::PatchDomain::kQuad, std::move(coords), output),
      geometry_(pointCount(), 16),
      tangent_u_(pointCount(), 12),
      tangent_v_(pointCount(), 12) {
  for (size_t n = 0; n < pointCount(); ++n) {
    const double u = this->coords()[n][0], v = this->coords()[n][1];
    const std::array<double, 4> cubic_u = techniques::cubicBasis(u),
                                cubic_v = techniques::cubicBasis(v);
    const std::array<double, 3> quadratic_u = techniques::quadraticBasis(u),
                                quadratic_v = techniques::quadraticBasis(v);
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) geometry_.at(n, i + 4 * j) = cubic_u[i] * cubic_v[j];
      for (int i = 0; i < 3; ++i) tangent_u_.at(n, i + 3 * j) = quadratic_u[i] * cubic_v[j];
    }
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 4; ++i) tangent_v_.at(n, i + 4 * j) = cubic_u[i] * quadratic_v[j];
    }
  }
}

void AccBatchPattern::evaluate(const AccControlPoints<double>& patch,
                               techniques::BatchPoints& out) const {
  out.reset(pointCount());
  techniques::combineControlPoints(geometry_, patch.b.data(), out.position);
  if (output() == techniques::BatchOutput::kPositions) return;
  techniques::combineControlPoints(tangent_u_, patch.tu.data(), out.du);
  techniques::combineControlPoints(tangent_v_, patch.tv.data(), out.dv);
  out.has_derivatives = true;
  if (output() == techniques::BatchOutput::kWithNormals) {
    techniques::normalsFromTangents(out.du, out.dv, out.normal, out.count);
    out.has_normals = true;
  }
}

}  // namespace tb::acc
