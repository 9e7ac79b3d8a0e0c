// What a wave-particle scenario describes (its "wave_particles" section and parameters),
// parsed and checked once: the square domain (its border reflects), the wave speed, the
// sources, the walls and the probe points. Shared by the simulation, the wave-equation
// reference setup (harness/measures/wave_error/wave_error.cpp) and the tests.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "techniques/simulation.h"

namespace tb::wave_particles {

using Point2 = std::array<double, 2>;  // metres

struct WaveSource {
  Point2 position_m{};
  double time_s = 0;       // emission time; emitted at the step nearest it
  double amplitude_m = 0;  // peak of the initial displacement blob (particle shape, radius r)
};

struct WaveWall {
  Point2 from_m{}, to_m{};  // a reflecting segment
};

struct WaveScene {
  double domain_size_m = 0;           // the domain is [-size/2, size/2]^2; its border reflects
  double wave_speed_m_per_s = 0;      // c: particles' speed and the reference's wave speed
  double particle_radius_m = 0;       // r of the particle shape (Yuksel et al. 2007, eq. 3)
  uint32_t particles_per_source = 0;  // ring of particles each source emits
  double particle_lifetime_s = 0;     // lp2: expiry age; default the duration
  uint32_t max_particles = 0;  // lp2: the fixed buffer; default particles_per_source x sources
  double damping_per_s = 0;    // full: amplitude decays as exp(-damping t); 0: none
  double height_field_spacing_m = 0;  // node spacing of the output height field
  double reference_spacing_m = 0;     // node spacing of the wave-equation reference
  std::vector<WaveSource> sources;
  std::vector<WaveWall> walls;  // the scenario's own walls (the border is added by borderWalls)
  std::vector<Point2> probes_m;
  double maxAmplitude() const;
  // The walls with the domain border's four segments appended (what particles reflect on).
  std::vector<WaveWall> allWalls() const;
};

// Reads the scenario's parameters and its "wave_particles" section. Throws InputError naming
// the scenario file and the field (UnsupportedInput when the section is absent).
// Parameters (all optional but the first two):
//   domain_size_m, wave_speed_m_per_s, particle_radius_m (0.25), particles_per_source (32),
//   particle_lifetime_s (duration_s), max_particles, damping_per_s (0),
//   height_field_spacing_m (0.05), reference_spacing_m (0.025)
// Section: {"sources": [{"position_m": [x, y], "time_s": t, "amplitude_m": a}],
//           "walls": [{"from_m": [x, y], "to_m": [x, y]}], "probes_m": [[x, y], ...]}
WaveScene parseWaveScene(const techniques::Scenario& scenario);

}  // namespace tb::wave_particles
