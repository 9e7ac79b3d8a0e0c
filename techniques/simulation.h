// The simulation capability of a technique instance (TechniqueInstance::simulation()):
// what a simulation technique (wave particles, mass-spring) gives the harness. The
// scenario is its input, step(dt) advances it on the CPU twin, state() reads it back in
// named float channels, gpuPrograms() are its Vulkan compute passes as plain data, and
// footprint() the bytes it keeps resident. See docs/ARCHITECTURE.md.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/gpu/compute_program_desc.h"

namespace tb::techniques {

// The input of a simulation, in place of (or beside) a mesh asset, read from a scenario
// JSON file (format "tessbench-scenario-1", docs/FORMATS.md) or built in code. A
// technique reads only the fields it needs and throws UnsupportedInput naming the field
// it misses.
struct Scenario {
  std::string name;        // "point_impulse"; the record's asset column in results
  std::string path;        // the file it came from; empty for scenarios built in code
  double time_step_s = 0;  // simulated seconds per step; > 0
  double duration_s = 0;   // simulated seconds a run covers; >= time_step_s
  // Scalar settings, each documented with its unit by the scenario format
  // (e.g. {"domain_size_m": 10}); keys are snake_case with the unit as suffix.
  std::map<std::string, double> parameters;
  // The simulation technique the file is written for ("wave_particles", "mass_spring");
  // the suite pairs a simulation technique only with its own scenarios. Empty: any.
  std::string technique = {};
  // The file's technique-specific sections, verbatim JSON text keyed by technique name
  // (e.g. sections["wave_particles"] = "{\"walls\": [...], \"sources\": [...]}"); a
  // technique parses its own with nlohmann::json and throws InputError naming the file
  // and the field.
  std::map<std::string, std::string> sections = {};
  // The mesh the scenario simulates or renders (the mass-spring skin): an absolute path
  // resolved by the loader from the file's "mesh" field (relative to the scenario file,
  // or a bundled asset name). Empty when the scenario has none.
  std::string mesh_path = {};
  size_t stepCount() const { return time_step_s > 0 ? size_t(duration_s / time_step_s + 0.5) : 0; }
};

// One named array of the simulation state, element-major: element e's components are
// values[e * components .. e * components + components - 1].
struct StateChannel {
  std::string name;           // "position", "velocity", "amplitude"
  std::string unit;           // "m", "m/s", "1" (dimensionless)
  uint32_t components = 1;    // 3 for a position in 3-D, 2 for a particle origin
  std::vector<float> values;  // float: what the GPU holds, so CPU and GPU compare in ulp
};

// The state read back after a step: the same channels, in the same element order, from
// the CPU twin and from the GPU (the comparison's two sides).
struct SimulationState {
  double time_s = 0;         // simulated seconds since the scenario start
  size_t element_count = 0;  // particles alive, mass points; every channel has this many
  std::vector<StateChannel> channels;
  const StateChannel* find(const std::string& name) const {
    for (const StateChannel& channel : channels) {
      if (channel.name == name) return &channel;
    }
    return nullptr;
  }
};

// Bytes a simulation keeps resident on the GPU for its scenario.
struct SimulationFootprint {
  uint64_t state_bytes = 0;      // the per-element state (both ping-pong copies when it has two)
  uint64_t auxiliary_bytes = 0;  // topology, constraint batches, acceleration trees, counters
  // The alternative a user would pick for the same scenario and output resolution (wave
  // particles: a height-field grid solver), in bytes resident, and in words; 0 and empty
  // when the simulation names none. The memory measure sets the two side by side.
  uint64_t alternative_bytes = 0;
  std::string alternative;
  uint64_t total() const { return state_bytes + auxiliary_bytes; }
  bool operator==(const SimulationFootprint&) const = default;
};

class ConstraintSolver;  // techniques/constraint_solver.h
class WaveField;         // techniques/wave_field.h

// The optional capabilities a simulation technique declares before building
// (Technique::simulationCapabilities()), so a measure that needs one (MeasureNeed) is
// matched without building an instance; its simulations then return them non-null.
struct SimulationCapabilities {
  bool constraint_solver = false;  // Simulation::constraintSolver()
  bool wave_field = false;         // Simulation::waveField()
};

class Simulation {
 public:
  virtual ~Simulation() = default;
  virtual const Scenario& scenario() const = 0;
  // Advances the CPU twin by dt_s simulated seconds (> 0; usually scenario().time_step_s).
  virtual void step(double dt_s) = 0;
  virtual SimulationState state() const = 0;
  // The Vulkan compute programs of one step, run by core/gpu; empty when there is no GPU
  // path. They start from the state at time 0.
  virtual std::vector<gpu::GpuComputeProgram> gpuPrograms() const { return {}; }
  virtual SimulationFootprint footprint() const = 0;
  // Optional capabilities, null when absent: an iterative constraint solver at the end of
  // the step (the convergence and stability measures), a 2-D wave height field (wave_error).
  virtual ConstraintSolver* constraintSolver() { return nullptr; }
  const ConstraintSolver* constraintSolver() const {
    return const_cast<Simulation*>(this)->constraintSolver();
  }
  virtual const WaveField* waveField() const { return nullptr; }
  // Non-fatal notes gathered while building; none by default.
  virtual const std::vector<std::string>& warnings() const {
    static const std::vector<std::string> kNone;
    return kNone;
  }
};

}  // namespace tb::techniques
