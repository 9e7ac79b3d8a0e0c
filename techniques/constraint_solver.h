// An optional capability of a Simulation whose step ends in an iterative constraint solver
// (position-based dynamics: the mass-spring soft body). The convergence and stability
// measures (harness/measures/convergence/, stability/) read a simulation through it, so
// they know no technique by name: Simulation::constraintSolver() returns it (null when
// absent), and a technique whose simulations have it declares so before building
// (Technique::simulationCapabilities().constraint_solver).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh/vec.h"

namespace tb::techniques {

// What one solver iteration costs, counted (not timed).
struct SolverCounts {
  // Dispatches one iteration takes on the GPU: 1 for Jacobi (one gather per vertex), the
  // colour count for graph-coloured Gauss-Seidel (one dispatch per independent batch). A
  // serial solver reports what the same sweep costs coloured.
  uint32_t dispatches_per_iteration = 1;
  uint32_t colours = 0;  // independent constraint batches; 0 when not coloured
  // The same greedy colouring of subsets, for the seed's "at most 8 batches" (its DX9
  // version had surface and goal springs only): surface springs alone, surface and goal.
  uint32_t colours_surface = 0;
  uint32_t colours_surface_goal = 0;
  // Jacobi: the fraction of gather reads of a neighbouring vertex that fall in the reader's
  // own tile of 64 consecutive vertices (served from shared memory by the tiled GPU gather);
  // 1 best, 0 for a solver without tiles.
  double tile_local_fraction = 0;
  uint64_t constraints = 0;      // constraints projected per iteration
  uint64_t vertices = 0;         // simulated mass points
  uint64_t constraint_ends = 0;  // vertex visits per iteration (2 per spring, 1 per anchor spring)
  // No GPU path: under a dispatch budget it runs whole iterations, max(1, round(budget /
  // dispatches_per_iteration)), instead of cutting one (serial Gauss-Seidel, the reference).
  bool whole_iterations_under_budget = false;
  // Solver iterations a budget of `dispatches` buys (below 1: part of an iteration).
  double iterationsFor(size_t dispatches) const {
    const double per = dispatches_per_iteration > 0 ? double(dispatches_per_iteration) : 1.0;
    if (!whole_iterations_under_budget) return double(dispatches) / per;
    const double whole = double((dispatches + dispatches_per_iteration / 2) /
                                (dispatches_per_iteration ? dispatches_per_iteration : 1));
    return whole < 1 ? 1.0 : whole;
  }
};

// The converged reference of the convergence frame (double, serial Gauss-Seidel).
struct ReferenceSolution {
  std::vector<mesh::Vec3d> positions;
  size_t iterations = 0;         // sweeps it took
  double relative_residual = 0;  // residual / initial residual when it stopped
  bool converged = false;        // relative_residual reached the requested tolerance
};

// Figures of the state after a step, for the stability measure.
struct StepDiagnostics {
  // Kinetic energy of the motion relative to the skinned (goal) motion, per unit mass and
  // per vertex (m^2/s^2): 0 when the skin follows its bones exactly.
  double relative_kinetic_energy = 0;
  double max_stretch = 0;  // largest |length - rest| / rest over the surface springs
  double rms_stretch = 0;  // RMS of the same
  bool finite = true;      // every position is finite
};

class ConstraintSolver {
 public:
  virtual ~ConstraintSolver() = default;
  virtual SolverCounts counts() const = 0;
  // Puts the simulation on its convergence frame: the constraints of the rest pose (every
  // spring at its rest length and every goal on its vertex, so the frame is satisfiable)
  // and positions displaced from it deterministically. Resets the solver's iteration count.
  virtual void setConvergenceFrame() = 0;
  // Runs `iterations` more solver iterations (in float, as the GPU) on the current state.
  virtual void iterate(size_t iterations) = 0;
  // Spends `dispatches` GPU dispatches of solver work on the current state: whole
  // iterations, or part of one when an iteration takes several dispatches (a Gauss-Seidel
  // sweep of more colours goes on where the last call stopped).
  virtual void iterateDispatches(size_t dispatches) = 0;
  // RMS relative stretch of the current positions over every active constraint
  // (dimensionless; anchor springs of rest length 0 measured against lengthScale()).
  virtual double residual() const = 0;
  virtual std::vector<mesh::Vec3d> positions() const = 0;
  // The length that makes position differences relative (mean surface rest length, m).
  virtual double lengthScale() const = 0;
  // The convergence frame solved in double by serial Gauss-Seidel in the reference order
  // until residual / initial residual <= relative_tolerance or max_iterations sweeps.
  virtual ReferenceSolution referenceSolution(double relative_tolerance,
                                              size_t max_iterations) const = 0;
  // Solver dispatches each step() spends (the frame's budget, as iterateDispatches).
  virtual void setDispatchesPerStep(size_t dispatches) = 0;
  virtual StepDiagnostics diagnostics() const = 0;
};

}  // namespace tb::techniques
