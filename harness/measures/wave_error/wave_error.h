// The "wave_error" measure's algorithm: steps a simulation with a wave field
// (techniques/wave_field.h; today wave particles) and the wave-equation reference
// (reference/wave_equation.h) side by side over the scenario and compares them: the height
// field at sample times, the wavefront's arrival at the scenario's probes, and how much of
// the ideal wavefront ring the particles still cover.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "reference/wave_equation.h"
#include "techniques/simulation.h"
#include "techniques/wave_field.h"

namespace tb::measures {

// One sample time.
struct WaveTimeFigures {
  double time_s = 0;
  // Height-field difference (particles' splat + filter against the reference at the same
  // nodes, wall nodes left out), over the largest source amplitude. Best 0; a field of
  // zeros against the reference scores the reference's own RMS / max.
  double rms_error = 0;
  double max_error = 0;
  // Fraction of the ideal wavefront rings (radius c (t - t_source) around each source,
  // points inside the domain and in sight of the source) within r/2 of a particle, where
  // the particle shape is at least half its peak. 1 when the ring is whole, 0 when no
  // particle is left on it. Absent before the front has left the source (t <= 2r/c).
  std::optional<double> coverage;
  double front_radius_m = 0;  // c t for the first source: coverage's distance axis
  uint64_t particles = 0;     // alive at this time
};

// One probe: the first time |height| exceeds 10% of the peak |height| the reference
// reaches at the probe, for the reference and for the particles (exact particle sum).
struct WaveProbeFigures {
  double x_m = 0, y_m = 0;
  double distance_m = 0;  // to the nearest source
  double reference_peak_m = 0;
  std::optional<double> reference_arrival_s, particle_arrival_s;
  // particle - reference; absent when either never arrives.
  std::optional<double> arrivalError() const;
};

struct WaveErrorFigures {
  std::vector<WaveTimeFigures> times;
  std::vector<WaveProbeFigures> probes;
  double time_step_s = 0;
  double arrival_tolerance_s = 0;  // one time step + particle radius / wave speed
};

// The reference set up from the same scene (sources as the particle-shape blob, walls).
ref::WaveEquationSetup referenceSetup(const techniques::WaveFieldScene& scene);

// Steps `simulation` (from its start) and the reference to the scenario's duration,
// sampling the height field at `sample_count` evenly spaced times (the last at the end).
// Throws std::invalid_argument when the simulation has no waveField().
WaveErrorFigures measureWaveError(techniques::Simulation& simulation, uint32_t sample_count);

// Coverage of the ideal rings at the simulation's current time (see WaveTimeFigures).
std::optional<double> ringCoverage(const techniques::WaveField& field);

}  // namespace tb::measures
