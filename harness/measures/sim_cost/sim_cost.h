// The "sim_cost" measure's algorithm, generic over Simulation (wave particles, mass-spring):
// elements alive over the scenario, the peak, dispatches per step from gpuPrograms(), and
// the bytes the compute runner keeps resident when a device runs the programs. Wall times
// (CPU and device, per step) are measured too but never enter results.json, which is
// byte-stable: the caller logs or benchmarks them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/gpu/context.h"
#include "techniques/simulation.h"

namespace tb::measures {

struct SimCostSample {
  double time_s = 0;
  uint64_t elements = 0;  // particles alive, mass points: SimulationState::element_count
};

struct SimCostFigures {
  std::vector<SimCostSample> samples;         // evenly spaced, the last at the end of the scenario
  uint64_t steps = 0;                         // CPU steps run (the scenario's step count)
  uint64_t peak_elements = 0;                 // over every CPU step; best: what the scenario needs
  techniques::SimulationFootprint footprint;  // at the start (buffers are sized for the whole run)
  uint64_t compute_passes = 0;                // passes of one step, over its programs
  uint64_t dispatches_per_step = 0;           // sum over passes of repeats_per_step; 0: no GPU path
  // The device run (absent without a device or a GPU path): steps run in one submission,
  // and the bytes of every buffer the runner allocated.
  std::optional<uint64_t> gpu_steps, gpu_resident_bytes;
  std::string gpu_skip_reason;  // why there is no device run
  // Timings, never written to results.json.
  double cpu_seconds_per_step = 0;
  std::optional<double> gpu_seconds_per_step;  // device timestamps; else host submit-to-fence
};

// Steps `simulation` through its scenario on the CPU, sampling `sample_count` times, then
// (when `gpu` is non-null and the simulation has programs) runs min(steps, gpu_step_limit)
// steps of its programs through core/gpu/compute_runner.h.
SimCostFigures measureSimCost(techniques::Simulation& simulation, uint32_t sample_count,
                              gpu::Context* gpu, const std::string& gpu_unavailable,
                              uint64_t gpu_step_limit);

}  // namespace tb::measures
