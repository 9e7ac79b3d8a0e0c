// The convergence of an iterative constraint solver (techniques/constraint_solver.h) on its
// convergence frame: the residual (RMS relative stretch) after each iteration, the
// iterations to a relative tolerance, the residual a fixed budget of GPU dispatches per
// frame reaches, and the distance of the positions from a converged double reference
// (serial Gauss-Seidel in double to a relative residual of 1e-12). Seed 003 claims
// Gauss-Seidel converges faster than Jacobi, "but with goal springs it matters little".
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "techniques/constraint_solver.h"

namespace tb::measures {

struct ConvergenceSettings {
  size_t rows = 32;                    // iterations reported one by one (k = 1..rows)
  size_t max_iterations = 2000;        // iteration budget for the tolerances
  size_t dispatch_budget = 8;          // GPU dispatches per frame for the summary
  double reference_tolerance = 1e-12;  // relative residual of the double reference
  size_t reference_max_iterations = 200000;
};

struct ConvergenceIteration {
  size_t k = 0;               // iterations done
  double residual = 0;        // RMS relative stretch (1); 0 when every constraint holds
  double residual_ratio = 0;  // residual / initial residual; best 0, 1 = no progress
  // RMS distance of the positions from the double reference, over the mean spring length
  // (1); 0 at the reference. Without goal springs the constraints have many solutions and a
  // solver may settle on another one: the error then stays above 0 while the residual falls.
  double position_error = 0;
};

struct ConvergenceFigures {
  techniques::SolverCounts counts;
  double initial_residual = 0;                   // residual of the frame's start (1)
  std::vector<ConvergenceIteration> iterations;  // k = 1..rows
  // Iterations until residual / initial <= 1e-3 and 1e-5; nullopt: not reached within
  // max_iterations (recorded as not reached, never as 0).
  std::optional<size_t> iterations_to_1e3, iterations_to_1e5;
  size_t iteration_budget = 0;  // max_iterations
  // The summary an engineer chooses from: the residual dispatch_budget dispatches reach from
  // the frame's start (1), and the solver iterations they are (dispatch_budget / dispatches
  // per iteration; below 1 for a Gauss-Seidel sweep of more colours: a partial sweep).
  double budget_iterations = 0;
  double residual_at_budget = 0;
  double final_residual_ratio = 0;  // after the last iteration run
  double final_position_error = 0;  // after the last iteration run (as position_error)
  size_t reference_iterations = 0;  // sweeps the double reference took
  double reference_relative_residual = 0;
  bool reference_converged = false;
};

// Runs `solver` on its convergence frame. It resets the frame itself.
ConvergenceFigures measureConvergence(techniques::ConstraintSolver& solver,
                                      const ConvergenceSettings& settings);

// RMS of |a_i - b_i| over `scale`.
double rmsDistance(const std::vector<mesh::Vec3d>& a, const std::vector<mesh::Vec3d>& b,
                   double scale);

}  // namespace tb::measures
