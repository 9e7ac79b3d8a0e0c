#include "harness/measures/sim_cost/sim_cost.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/gpu/compute_runner.h"

namespace tb::measures {

SimCostFigures measureSimCost(techniques::Simulation& simulation, uint32_t sample_count,
                              gpu::Context* gpu, const std::string& gpu_unavailable,
                              uint64_t gpu_step_limit) {
  SimCostFigures figures;
  const techniques::Scenario& scenario = simulation.scenario();
  figures.footprint = simulation.footprint();
  const std::vector<gpu::GpuComputeProgram> programs = simulation.gpuPrograms();
  for (const gpu::GpuComputeProgram& program : programs) {
    for (const gpu::GpuComputePass& pass : program.passes) {
      ++figures.compute_passes;
      figures.dispatches_per_step += pass.repeats_per_step;
    }
  }
  const size_t steps = scenario.stepCount();
  figures.steps = steps;
  std::vector<size_t> sample_steps;
  for (uint32_t k = 1; k <= sample_count; ++k) {
    sample_steps.push_back(std::max<size_t>(1, steps * k / std::max(sample_count, 1u)));
  }
  figures.peak_elements = simulation.state().element_count;
  const auto start = std::chrono::steady_clock::now();
  for (size_t step = 1; step <= steps; ++step) {
    simulation.step(scenario.time_step_s);
    const techniques::SimulationState state = simulation.state();
    figures.peak_elements = std::max<uint64_t>(figures.peak_elements, state.element_count);
    if (std::find(sample_steps.begin(), sample_steps.end(), step) != sample_steps.end()) {
      figures.samples.push_back({state.time_s, state.element_count});
    }
  }
  figures.cpu_seconds_per_step =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
      double(std::max<size_t>(steps, 1));
  if (programs.empty()) {
    figures.gpu_skip_reason = "the simulation has no GPU path";
  } else if (gpu == nullptr) {
    figures.gpu_skip_reason = gpu_unavailable.empty()
                                  ? std::string("no Vulkan device")
                                  : "no Vulkan device (" + gpu_unavailable + ")";
  } else {
    gpu::ComputeRunner runner(*gpu, programs);
    const uint64_t gpu_steps = std::min<uint64_t>(steps, gpu_step_limit);
    const gpu::ComputeRunTiming timing = runner.run(uint32_t(gpu_steps));
    figures.gpu_steps = gpu_steps;
    figures.gpu_resident_bytes = runner.residentBytes();
    if (gpu_steps > 0) {
      const double seconds =
          std::isnan(timing.gpu_ns) ? timing.submit_to_fence_s : timing.gpu_ns * 1e-9;
      figures.gpu_seconds_per_step = seconds / double(gpu_steps);
    }
  }
  return figures;
}

}  // namespace tb::measures
