#include "harness/measures/convergence/convergence.h"

#include <algorithm>
#include <cmath>

namespace tb::measures {

double rmsDistance(const std::vector<mesh::Vec3d>& a, const std::vector<mesh::Vec3d>& b,
                   double scale) {
  if (a.empty() || a.size() != b.size()) return NAN;
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const mesh::Vec3d d = a[i] - b[i];
    sum += dot(d, d);
  }
  return std::sqrt(sum / double(a.size())) / scale;
}

ConvergenceFigures measureConvergence(techniques::ConstraintSolver& solver,
                                      const ConvergenceSettings& settings) {
  ConvergenceFigures figures;
  figures.counts = solver.counts();
  figures.iteration_budget = settings.max_iterations;
  const techniques::ReferenceSolution reference =
      solver.referenceSolution(settings.reference_tolerance, settings.reference_max_iterations);
  figures.reference_iterations = reference.iterations;
  figures.reference_relative_residual = reference.relative_residual;
  figures.reference_converged = reference.converged;
  const double scale = solver.lengthScale();

  solver.setConvergenceFrame();
  solver.iterateDispatches(settings.dispatch_budget);
  figures.residual_at_budget = solver.residual();
  figures.budget_iterations = figures.counts.iterationsFor(settings.dispatch_budget);

  solver.setConvergenceFrame();
  const double r0 = solver.residual();
  figures.initial_residual = r0;
  const size_t last = std::max(settings.rows, settings.max_iterations);
  double ratio = 1;
  for (size_t k = 1; k <= last; ++k) {
    solver.iterate(1);
    const double r = solver.residual();
    ratio = r0 > 0 ? r / r0 : 0;
    if (k <= settings.rows) {
      figures.iterations.push_back(
          {k, r, ratio, rmsDistance(solver.positions(), reference.positions, scale)});
    }
    if (!figures.iterations_to_1e3 && ratio <= 1e-3) figures.iterations_to_1e3 = k;
    if (!figures.iterations_to_1e5 && ratio <= 1e-5) figures.iterations_to_1e5 = k;
    // Past the rows, stop once both tolerances are met (or diverged).
    if (k >= settings.rows &&
        ((figures.iterations_to_1e3 && figures.iterations_to_1e5) || !std::isfinite(r))) {
      break;
    }
  }
  figures.final_residual_ratio = ratio;
  figures.final_position_error = rmsDistance(solver.positions(), reference.positions, scale);
  return figures;
}

}  // namespace tb::measures
