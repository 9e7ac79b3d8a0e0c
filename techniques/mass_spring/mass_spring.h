// The `mass_spring` technique: seed 003's soft-body boss skin. A mass-spring model with
// surface, inner and goal springs, Verlet integration, and position-based projection by one
// of four solvers (the variants): serial Gauss-Seidel, graph-coloured Gauss-Seidel, Jacobi,
// and Jacobi with Chebyshev acceleration (Wang, SIGGRAPH Asia 2015). Family simulation: it
// builds from a scenario (soft_body.h) and also implements ConstraintSolver, which the
// convergence and stability measures read.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "techniques/constraint_solver.h"
#include "techniques/mass_spring/soft_body.h"
#include "techniques/mass_spring/spring_solvers.h"
#include "techniques/mass_spring/tet_binding.h"
#include "techniques/technique.h"

namespace tb::mass_spring {

// The render mesh's tessellation level of each simulated face (points bound by
// tet_binding.h); the apex height of its virtual tetrahedra is the mean spring length.
inline constexpr uint32_t kRenderLevel = 3;

class MassSpringSimulation final : public techniques::Simulation,
                                   public techniques::ConstraintSolver {
 public:
  MassSpringSimulation(const techniques::Scenario& scenario, const SolverSettings& settings,
                       bool goal_springs);

  // Simulation
  const techniques::Scenario& scenario() const override { return scenario_; }
  void step(double dt_s) override;
  techniques::SimulationState state() const override;
  std::vector<gpu::GpuComputeProgram> gpuPrograms() const override;
  techniques::SimulationFootprint footprint() const override;
  techniques::ConstraintSolver* constraintSolver() override { return this; }

  // ConstraintSolver
  techniques::SolverCounts counts() const override;
  void setConvergenceFrame() override;
  void iterate(size_t iterations) override;
  double residual() const override;
  std::vector<mesh::Vec3d> positions() const override;
  double lengthScale() const override { return system_.length_scale_m; }
  techniques::ReferenceSolution referenceSolution(double relative_tolerance,
                                                  size_t max_iterations) const override;
  void iterateDispatches(size_t dispatches) override {
    solver_.iterateDispatches(state_, dispatches);
  }
  void setDispatchesPerStep(size_t dispatches) override { dispatches_per_step_ = dispatches; }
  techniques::StepDiagnostics diagnostics() const override;

  const SpringSystem& springs() const { return system_; }
  const SolverSettings& settings() const { return solver_.settings(); }
  size_t dispatchesPerStep() const { return dispatches_per_step_; }
  // The solver's float state (positions relative to origin()), for the GPU comparison.
  const SolverState<float>& solverState() const { return state_; }
  SolverState<float>& solverState() { return state_; }
  // Simulated positions are stored relative to this point (the skin's bounding-box centre)
  // so float resolves the springs' lengths; positions() adds it back.
  const mesh::Vec3d& origin() const { return origin_; }
  const RenderMesh& renderMesh() const { return render_mesh_; }
  // The solver alone on Vulkan compute (mass_spring_gpu.cpp): programs whose one runner
  // step is one solver iteration from the current state (positions and anchors), for the
  // GPU-against-CPU comparison. Empty for gs_serial (no GPU path). After N steps the
  // positions are in buffer solverPositionBuffer() as vec4 per vertex (decodePositions).
  std::vector<gpu::GpuComputeProgram> solverPrograms() const;
  static std::string solverPositionBuffer() { return "positions"; }
  static std::vector<mesh::Vec3f> decodePositions(const std::vector<uint32_t>& words, size_t count);
  // gpuPrograms(): one step (verlet.comp, then the solver's dispatches_per_step dispatches),
  // from the state at time 0; the positions after N steps are in "positions" (gs_serial:
  // none, it has no GPU path).
  // The render vertices for the current simulated positions (DrawVertex, in double).
  std::vector<mesh::Vec3d> renderPositions() const;
  // The same in float relative to origin(), as gpuPrograms()' render pass writes
  // "render_positions" (drawVertexFloat).
  std::vector<mesh::Vec3f> renderPositionsFloat() const;

 private:
  // Anchors at time j dt (j = steps done; 0: the rest pose), in the float operations of
  // shaders/mass_spring/verlet.comp.
  struct JacobiBuffers {
    std::vector<uint32_t> end_start, ends, scale, weights;
  };
  JacobiBuffers jacobiBuffers() const;
  // One step's programs for the solver `kind` (gpuPrograms(), and the footprint's layout).
  std::vector<gpu::GpuComputeProgram> stepPrograms(SolverKind kind) const;
  // The step's last pass: render vertices from the simulated ones (render.comp).
  gpu::GpuComputePass renderPass() const;
  void setAnchors(size_t j, double dt_s);
  std::vector<mesh::Vec3f> anchorsAt(size_t j, double dt_s) const;
  // float(sin(2 pi f_s j dt)): stomp s's phase at time index j (the GPU's table holds these).
  float stompSine(size_t s, size_t j, double dt_s) const;
  // The convergence frame's start: rest positions displaced by a hashed jitter.
  std::vector<mesh::Vec3f> convergenceStart() const;

  techniques::Scenario scenario_;
  std::unique_ptr<SoftBodyInput> input_;  // stable address: rig_ refers to it
  SoftBodyRig rig_;
  SpringSystem system_;
  SpringSolver<float> solver_;
  SolverState<float> state_;
  std::vector<mesh::Vec3f> x_previous_;     // Verlet: positions of the step before
  std::vector<mesh::Vec3d> goal_previous_;  // goal anchors of the step before (diagnostics)
  mesh::Vec3d origin_{0, 0, 0};
  RenderMesh render_mesh_;
  double time_s_ = 0;
  double last_dt_s_ = 0;
  size_t steps_done_ = 0;
  std::vector<mesh::Vec3f> rest_f_, bone_f_;  // rest positions and bone points (float, local)
  std::vector<mesh::Vec3f> stomp_amplitude_;  // [v * stomps + s]: rig_.stompAmplitude in float
  size_t dispatches_per_step_ = 8;
  bool goal_springs_ = true;
};

class MassSpringTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  // Variant parameters: "goal_springs" (1 default, 0 without), "omega", "rho", "delay",
  // "colour_major" (gs_serial's order).
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
  techniques::SimulationCapabilities simulationCapabilities() const override {
    return {.constraint_solver = true, .wave_field = false};
  }
};

// The solver settings a variant names (its name picks the solver, its parameters the rest).
SolverSettings settingsOf(const techniques::TechniqueInfo& info,
                          const techniques::VariantInfo& variant);

}  // namespace tb::mass_spring
