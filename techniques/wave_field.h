// An optional capability of a Simulation whose output is a 2-D wave height field driven by
// point sources in a walled square domain (wave particles). The wave_error measure
// (harness/measures/wave_error/) reads a simulation through it: Simulation::waveField()
// returns it, null when the simulation has none, and the technique declares it before
// building (Technique::simulationCapabilities().wave_field), so the measure knows no
// technique by name or type.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tb::techniques {

using WavePoint = std::array<double, 2>;  // metres

// A source: at time_s an initial displacement blob (the packet shape, radius
// packet_radius_m) of peak amplitude_m at position_m, at zero velocity.
struct WaveFieldSource {
  WavePoint position_m{};
  double time_s = 0;
  double amplitude_m = 0;
};

struct WaveFieldWall {
  WavePoint from_m{}, to_m{};  // a reflecting segment
};

// The scene as the simulation reads it from its scenario.
struct WaveFieldScene {
  double domain_size_m = 0;  // the domain is [-size/2, size/2]^2; its border reflects
  double wave_speed_m_per_s = 0;
  double packet_radius_m = 0;      // radius of the packet (particle) shape
  double damping_per_s = 0;        // amplitude decays as exp(-damping t); 0: none
  double reference_spacing_m = 0;  // node spacing the scenario asks of a grid reference
  std::vector<WaveFieldSource> sources;
  std::vector<WaveFieldWall> walls;  // the scenario's own walls (the border not included)
  std::vector<WavePoint> probes_m;
  // The largest |amplitude_m| of the sources (0 without sources).
  double maxAmplitude() const {
    double peak = 0;
    for (const WaveFieldSource& source : sources)
      peak = std::max(peak, std::abs(source.amplitude_m));
    return peak;
  }
};

// The output height field on a regular grid.
struct WaveHeightGrid {
  double origin_m = 0;           // the coordinate of node 0 on both axes
  double spacing_m = 0;          // node spacing
  uint32_t nodes = 0;            // per side
  std::vector<double> height_m;  // nodes x nodes, row-major (y rows)
  double at(uint32_t i, uint32_t j) const { return height_m[size_t(j) * nodes + i]; }
};

class WaveField {
 public:
  virtual ~WaveField() = default;
  virtual WaveFieldScene waveScene() const = 0;
  // Simulated seconds since the scenario start.
  virtual double timeS() const = 0;
  // The output height field at the current time.
  virtual WaveHeightGrid heightGrid() const = 0;
  // The exact height at one point (probes), in metres.
  virtual double heightAt(double x_m, double y_m) const = 0;
  // Where each wave packet (particle) alive now is, in metres (float, as the GPU holds it).
  virtual std::vector<std::array<float, 2>> packetPositions() const = 0;
};

}  // namespace tb::techniques
