#include "techniques/gregory_acc/gregory_batch.h"

namespace tb::gregory_acc {

GregoryBatchPattern::GregoryBatchPattern(techniques::PatchDomain domain,
                                         std::vector<techniques::DomainCoord> coords,
                                         techniques::BatchOutput output, bool symmetric_edges)
    : techniques::BatchPattern(domain, std::move(coords), output),
      symmetric_edges_(symmetric_edges) {
  const size_t control_points =
      domain == techniques::PatchDomain::kQuad ? kPointsPerPatch : kPointsPerTriangle;
  position_ = techniques::BasisTable(pointCount(), control_points);
  if (output != techniques::BatchOutput::kPositions) {
    tangent_u_ = techniques::BasisTable(pointCount(), control_points);
    tangent_v_ = techniques::BasisTable(pointCount(), control_points);
  }
  // The evaluator's x, y and z are independent sums, so one run on the unit points
  // cp[k] = (1, 0, 0), cp[k + 1] = (0, 1, 0), cp[k + 2] = (0, 0, 1) (the rest zero)
  // yields the weights of three control points at once.
  for (size_t n = 0; n < pointCount(); ++n) {
    const techniques::DomainCoord& d = this->coords()[n];
    for (size_t first = 0; first < control_points; first += 3) {
      GregoryPoints<double> unit{};
      for (size_t axis = 0; axis < 3 && first + axis < control_points; ++axis) {
        unit[first + axis][int(axis)] = 1.0;
      }
      if (output == techniques::BatchOutput::kPositions) {
        const mesh::Vec3d p =
            domain == techniques::PatchDomain::kQuad
                ? evaluateGregoryPosition(unit, d[0], d[1], symmetric_edges)
                : evaluateGregoryTrianglePosition(unit, d[0], d[1], d[2], symmetric_edges);
        for (size_t axis = 0; axis < 3 && first + axis < control_points; ++axis) {
          position_.at(n, first + axis) = p[int(axis)];
        }
        continue;
      }
      const GregoryFrame<double> frame =
          domain == techniques::PatchDomain::kQuad
              ? evaluateGregoryFrame(unit, d[0], d[1], symmetric_edges)
              : evaluateGregoryTriangleFrame(unit, d[0], d[1], d[2], symmetric_edges);
      for (size_t axis = 0; axis < 3 && first + axis < control_points; ++axis) {
        position_.at(n, first + axis) = frame.position[int(axis)];
        tangent_u_.at(n, first + axis) = frame.tangent_u[int(axis)];
        tangent_v_.at(n, first + axis) = frame.tangent_v[int(axis)];
      }
    }
  }
}

void GregoryBatchPattern::evaluate(const GregoryPoints<double>& patch,
                                   techniques::BatchPoints& out) const {
  out.reset(pointCount());
  techniques::combineControlPoints(position_, patch.data(), out.position);
  if (output() == techniques::BatchOutput::kPositions) return;
  techniques::combineControlPoints(tangent_u_, patch.data(), out.du);
  techniques::combineControlPoints(tangent_v_, patch.data(), out.dv);
  out.has_derivatives = true;
  if (output() == techniques::BatchOutput::kWithNormals) {
    techniques::normalsFromTangents(out.du, out.dv, out.normal, out.count);
    out.has_normals = true;
  }
}

}  // namespace tb::gregory_acc
