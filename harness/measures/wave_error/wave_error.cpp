#include "harness/measures/wave_error/wave_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tb::measures {
namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Whether segment p -> q crosses wall w (proper or touching).
bool blocked(const techniques::WavePoint& p, const techniques::WavePoint& q,
             const techniques::WaveFieldWall& w) {
  const double rx = q[0] - p[0], ry = q[1] - p[1];
  const double sx = w.to_m[0] - w.from_m[0], sy = w.to_m[1] - w.from_m[1];
  const double den = cross(rx, ry, sx, sy);
  if (den == 0) return false;
  const double gx = w.from_m[0] - p[0], gy = w.from_m[1] - p[1];
  const double t = cross(gx, gy, sx, sy) / den, u = cross(gx, gy, rx, ry) / den;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

std::optional<double> firstAbove(const std::vector<double>& trace, double threshold, double dt) {
  for (size_t i = 0; i < trace.size(); ++i) {
    if (std::abs(trace[i]) > threshold) return dt * double(i + 1);
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> WaveProbeFigures::arrivalError() const {
  if (!reference_arrival_s || !particle_arrival_s) return std::nullopt;
  return *particle_arrival_s - *reference_arrival_s;
}

ref::WaveEquationSetup referenceSetup(const techniques::WaveFieldScene& scene) {
  ref::WaveEquationSetup setup;
  setup.domain_size_m = scene.domain_size_m;
  setup.wave_speed_m_per_s = scene.wave_speed_m_per_s;
  setup.spacing_m = scene.reference_spacing_m;
  setup.damping_per_s = scene.damping_per_s;
  for (const techniques::WaveFieldSource& source : scene.sources) {
    setup.sources.push_back({source.position_m[0], source.position_m[1], source.time_s,
                             source.amplitude_m, scene.packet_radius_m});
  }
  for (const techniques::WaveFieldWall& wall : scene.walls) {
    setup.walls.push_back({wall.from_m[0], wall.from_m[1], wall.to_m[0], wall.to_m[1]});
  }
  return setup;
}

std::optional<double> ringCoverage(const techniques::WaveField& field) {
  const techniques::WaveFieldScene scene = field.waveScene();
  const double r = scene.packet_radius_m, c = scene.wave_speed_m_per_s;
  const double t = field.timeS(), half = scene.domain_size_m / 2;
  const std::vector<std::array<float, 2>> positions = field.packetPositions();
  uint64_t kept = 0, covered = 0;
  for (const techniques::WaveFieldSource& source : scene.sources) {
    const double radius = c * (t - source.time_s);
    if (!(radius > 2 * r)) continue;  // the front has not left the source yet
    const uint32_t points =
        std::max(64u, uint32_t(std::ceil(2 * std::numbers::pi * radius / (r / 4))));
    for (uint32_t k = 0; k < points; ++k) {
      const double angle = 2 * std::numbers::pi * k / points;
      const techniques::WavePoint q{source.position_m[0] + radius * std::cos(angle),
                                    source.position_m[1] + radius * std::sin(angle)};
      if (std::abs(q[0]) > half - r || std::abs(q[1]) > half - r) continue;
      bool hidden = false;
      for (const techniques::WaveFieldWall& wall : scene.walls)
        hidden |= blocked(source.position_m, q, wall);
      if (hidden) continue;
      ++kept;
      for (const auto& p : positions) {
        if (std::hypot(p[0] - q[0], p[1] - q[1]) <= r / 2) {
          ++covered;
          break;
        }
      }
    }
  }
  if (kept == 0) return std::nullopt;
  return double(covered) / double(kept);
}

WaveErrorFigures measureWaveError(techniques::Simulation& simulation, uint32_t sample_count) {
  const techniques::WaveField* field = simulation.waveField();
  if (field == nullptr) {
    throw std::invalid_argument("wave_error: the simulation has no wave field");
  }
  const techniques::Scenario& scenario = simulation.scenario();
  const techniques::WaveFieldScene scene = field->waveScene();
  const double dt = scenario.time_step_s;
  const size_t steps = scenario.stepCount();
  ref::WaveEquationSolver reference(referenceSetup(scene), dt);
  WaveErrorFigures figures;
  figures.time_step_s = dt;
  figures.arrival_tolerance_s = dt + scene.packet_radius_m / scene.wave_speed_m_per_s;
  std::vector<size_t> sample_steps;
  for (uint32_t k = 1; k <= sample_count; ++k) {
    sample_steps.push_back(std::max<size_t>(1, steps * k / sample_count));
  }
  std::vector<std::vector<double>> particle_trace(scene.probes_m.size()),
      reference_trace(scene.probes_m.size());
  const double amplitude = std::max(scene.maxAmplitude(), 1e-300);
  for (size_t step = 1; step <= steps; ++step) {
    simulation.step(dt);
    reference.advance();
    for (size_t p = 0; p < scene.probes_m.size(); ++p) {
      const techniques::WavePoint& probe = scene.probes_m[p];
      particle_trace[p].push_back(field->heightAt(probe[0], probe[1]));
      reference_trace[p].push_back(reference.sample(probe[0], probe[1]));
    }
    if (std::find(sample_steps.begin(), sample_steps.end(), step) == sample_steps.end()) continue;
    WaveTimeFigures row;
    row.time_s = field->timeS();
    row.particles = field->packetPositions().size();
    row.front_radius_m = scene.wave_speed_m_per_s * (row.time_s - scene.sources[0].time_s);
    const techniques::WaveHeightGrid grid = field->heightGrid();
    double sum = 0;
    uint64_t count = 0;
    for (uint32_t j = 0; j < grid.nodes; ++j) {
      for (uint32_t i = 0; i < grid.nodes; ++i) {
        const double x = grid.origin_m + i * grid.spacing_m;
        const double y = grid.origin_m + j * grid.spacing_m;
        if (reference.solidAt(x, y)) continue;
        const double d = (grid.at(i, j) - reference.sample(x, y)) / amplitude;
        sum += d * d;
        row.max_error = std::max(row.max_error, std::abs(d));
        ++count;
      }
    }
    row.rms_error = count ? std::sqrt(sum / double(count)) : 0;
    row.coverage = ringCoverage(*field);
    figures.times.push_back(row);
  }
  for (size_t p = 0; p < scene.probes_m.size(); ++p) {
    WaveProbeFigures probe;
    probe.x_m = scene.probes_m[p][0];
    probe.y_m = scene.probes_m[p][1];
    probe.distance_m = INFINITY;
    for (const techniques::WaveFieldSource& source : scene.sources) {
      probe.distance_m = std::min(probe.distance_m, std::hypot(probe.x_m - source.position_m[0],
                                                               probe.y_m - source.position_m[1]));
    }
    for (double h : reference_trace[p])
      probe.reference_peak_m = std::max(probe.reference_peak_m, std::abs(h));
    if (probe.reference_peak_m > 0) {
      const double threshold = 0.1 * probe.reference_peak_m;
      probe.reference_arrival_s = firstAbove(reference_trace[p], threshold, dt);
      probe.particle_arrival_s = firstAbove(particle_trace[p], threshold, dt);
    }
    figures.probes.push_back(probe);
  }
  return figures;
}

}  // namespace tb::measures
