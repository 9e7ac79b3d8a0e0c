#include "techniques/wave_particles/wave_particles.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include "techniques/registry.h"
#include "techniques/variant_param.h"

namespace tb::wave_particles {
namespace {

std::vector<WallSegment> wallSegments(const WaveScene& scene) {
  std::vector<WallSegment> segments;
  for (const WaveWall& wall : scene.allWalls()) {
    const double dx = wall.to_m[0] - wall.from_m[0], dy = wall.to_m[1] - wall.from_m[1];
    const double length = std::hypot(dx, dy);
    segments.push_back({{float(wall.from_m[0]), float(wall.from_m[1])},
                        {float(wall.to_m[0]), float(wall.to_m[1])},
                        {float(-dy / length), float(dx / length)}});
  }
  return segments;
}

// The `full` buffer: subdivision keeps neighbours more than r/6 apart (they split when more
// than r/2 apart), and a source's wavefront, however reflected, is at most 2 pi c T long.
uint32_t fullCapacity(const WaveScene& scene, double duration_s) {
  const double ring = 2 * std::numbers::pi * scene.wave_speed_m_per_s * duration_s;
  const double per_source =
      scene.particles_per_source + std::ceil(ring / (scene.particle_radius_m / 6)) + 3;
  return uint32_t(std::min(per_source * double(scene.sources.size()), 1e7));
}

}  // namespace

WaveParticleSimulation::WaveParticleSimulation(const techniques::Scenario& scenario,
                                               Variant variant)
    : scenario_(scenario), scene_(parseWaveScene(scenario)) {
  const double dt = scenario.time_step_s;
  settings_.dt_s = float(dt);
  settings_.speed_m_per_s = float(scene_.wave_speed_m_per_s);
  settings_.variant = variant;
  settings_.decay_per_step = float(std::exp(-scene_.damping_per_s * dt));
  settings_.min_amplitude_m = float(1e-6 * scene_.maxAmplitude());
  settings_.subdivide_fraction = 0.5f;
  settings_.capacity =
      variant == Variant::kLp2 ? scene_.max_particles : fullCapacity(scene_, scenario.duration_s);
  walls_ = wallSegments(scene_);
  if (variant == Variant::kLp2) tree_ = buildWallTree(walls_);
  const uint32_t n = scene_.particles_per_source;
  table_ = subdivisionTable(float(2 * std::numbers::pi / n), kSubdivisionLevels);
  for (size_t s = 0; s < scene_.sources.size(); ++s) {
    const WaveSource& source = scene_.sources[s];
    const uint32_t emit_step = uint32_t(std::lround(source.time_s / dt));
    for (uint32_t j = 0; j < n; ++j) {
      const double angle = 2 * std::numbers::pi * j / n;
      Particle p{};
      p.origin[0] = float(source.position_m[0]);
      p.origin[1] = float(source.position_m[1]);
      p.direction[0] = float(std::cos(angle));
      p.direction[1] = float(std::sin(angle));
      p.age_s = 0;
      p.lifetime_s = float(scene_.particle_lifetime_s);
      // The ring of n particles, all at the source, adds up to the source's blob.
      p.amplitude_m = float(source.amplitude_m / n);
      p.dispersion_rad = table_.theta[0];
      p.radius_m = float(scene_.particle_radius_m);
      p.id = hashId(uint32_t(s) << 16 | j);
      p.emit_step = emit_step;
      if (emit_step == 0) {
        p.emit_step = 0;
        if (particles_.size() < settings_.capacity) {
          particles_.push_back(p);
        } else {
          ++dropped_;
        }
      } else {
        pending_.push_back(p);
      }
    }
  }
}

void WaveParticleSimulation::emitPending(uint32_t step, std::vector<Particle>* out) {
  for (const Particle& p : pending_) {
    if (p.emit_step != step) continue;
    if (out->size() < settings_.capacity) {
      out->push_back(p);
    } else {
      ++dropped_;
    }
  }
}

void WaveParticleSimulation::step(double dt_s) {
  StepSettings settings = settings_;
  settings.dt_s = float(dt_s);
  std::vector<Particle> next;
  next.reserve(particles_.size() + 16);
  for (const Particle& p : particles_) {
    updateParticle(p, settings, walls_, tree_, table_, &next, &dropped_);
  }
  ++steps_;
  emitPending(steps_, &next);
  particles_ = std::move(next);
  time_s_ += dt_s;
}

techniques::SimulationState WaveParticleSimulation::state() const {
  techniques::SimulationState state;
  state.time_s = time_s_;
  state.element_count = particles_.size();
  techniques::StateChannel origin{"origin", "m", 2, {}}, direction{"direction", "1", 2, {}},
      position{"position", "m", 2, {}}, age{"age", "s", 1, {}}, lifetime{"lifetime", "s", 1, {}},
      amplitude{"amplitude", "m", 1, {}}, dispersion{"dispersion", "rad", 1, {}},
      radius{"radius", "m", 1, {}};
  for (const Particle& p : particles_) {
    origin.values.insert(origin.values.end(), {p.origin[0], p.origin[1]});
    direction.values.insert(direction.values.end(), {p.direction[0], p.direction[1]});
    float x, y;
    particlePosition(p, settings_.speed_m_per_s, &x, &y);
    position.values.insert(position.values.end(), {x, y});
    age.values.push_back(p.age_s);
    lifetime.values.push_back(p.lifetime_s);
    amplitude.values.push_back(p.amplitude_m);
    dispersion.values.push_back(p.dispersion_rad);
    radius.values.push_back(p.radius_m);
  }
  state.channels = {origin, direction, position, age, lifetime, amplitude, dispersion, radius};
  return state;
}

techniques::SimulationFootprint WaveParticleSimulation::footprint() const {
  techniques::SimulationFootprint footprint;
  // Both ping-pong buffers at full capacity.
  footprint.state_bytes = 2 * uint64_t(settings_.capacity) * sizeof(Particle);
  footprint.auxiliary_bytes = 2 * 16                                 // the two counters
                              + walls_.size() * sizeof(WallSegment)  // boundary segments
                              + tree_.size() * sizeof(AabbNode)      // lp2's tree
                              + table_.theta.size() * 3 * 4          // subdivision table
                              + pending_.size() * sizeof(Particle)   // later emissions
                              + 16;                                  // statistics
  // The output and its making: splat accumulators (int), the height map (float) and the
  // displacement map (normal xyz + height, 4 floats) per node, and the filter kernel.
  const uint64_t nodes = heightFieldNodes();
  const uint64_t reach =
      uint64_t(std::floor(scene_.particle_radius_m / scene_.height_field_spacing_m));
  footprint.auxiliary_bytes += nodes * nodes * (4 + 4 + 16) + (2 * reach + 1) * (2 * reach + 1) * 4;
  // The alternative: a leapfrog height-field solver on the same grid, whose current field is
  // the output: current and previous heights (float) and a wall mask (byte) per node.
  footprint.alternative_bytes = nodes * nodes * (4 + 4 + 1);
  footprint.alternative = "a height-field wave-equation grid solver at the output's resolution (" +
                          std::to_string(nodes) +
                          "^2 nodes: current and previous height in float, a wall byte)";
  return footprint;
}

HeightField WaveParticleSimulation::heightField() const {
  return splatAndFilter(particles_, settings_.speed_m_per_s, scene_.domain_size_m,
                        scene_.height_field_spacing_m, scene_.particle_radius_m);
}

uint32_t WaveParticleSimulation::heightFieldNodes() const {
  return uint32_t(std::lround(scene_.domain_size_m / scene_.height_field_spacing_m)) + 1;
}

double WaveParticleSimulation::splatScale() const {
  return std::ldexp(1.0, 20) / std::max(scene_.maxAmplitude(), 1e-30);
}

HeightField WaveParticleSimulation::heightFieldFromWords(const std::vector<uint32_t>& words) const {
  HeightField field;
  field.origin_m = -scene_.domain_size_m / 2;
  field.spacing_m = scene_.height_field_spacing_m;
  field.nodes = heightFieldNodes();
  field.height_m.resize(size_t(field.nodes) * field.nodes);
  for (size_t i = 0; i < field.height_m.size(); ++i) {
    field.height_m[i] = std::bit_cast<float>(words.at(i));
  }
  return field;
}

double WaveParticleSimulation::heightAt(double x_m, double y_m) const {
  return particleHeightAt(particles_, settings_.speed_m_per_s, x_m, y_m);
}

techniques::WaveFieldScene WaveParticleSimulation::waveScene() const {
  techniques::WaveFieldScene out;
  out.domain_size_m = scene_.domain_size_m;
  out.wave_speed_m_per_s = scene_.wave_speed_m_per_s;
  out.packet_radius_m = scene_.particle_radius_m;
  out.damping_per_s = scene_.damping_per_s;
  out.reference_spacing_m = scene_.reference_spacing_m;
  for (const WaveSource& source : scene_.sources) {
    out.sources.push_back({source.position_m, source.time_s, source.amplitude_m});
  }
  for (const WaveWall& wall : scene_.walls) out.walls.push_back({wall.from_m, wall.to_m});
  out.probes_m = scene_.probes_m;
  return out;
}

techniques::WaveHeightGrid WaveParticleSimulation::heightGrid() const {
  HeightField field = heightField();
  return {field.origin_m, field.spacing_m, field.nodes, std::move(field.height_m)};
}

std::vector<std::array<float, 2>> WaveParticleSimulation::packetPositions() const {
  std::vector<std::array<float, 2>> positions;
  positions.reserve(particles_.size());
  for (const Particle& p : particles_) {
    float x, y;
    particlePosition(p, settings_.speed_m_per_s, &x, &y);
    positions.push_back({x, y});
  }
  return positions;
}

const techniques::TechniqueInfo& WaveParticlesTechnique::info() const {
  static const techniques::TechniqueInfo kInfo{
      "wave_particles", techniques::TechniqueFamily::kSimulation, "Wave particles",
      "Yuksel, House and Keyser, Wave Particles, ACM TOG 26(3) (SIGGRAPH 2007)",
      "a scenario (tessbench-scenario-1) with a \"wave_particles\" section: point sources, "
      "wall segments, probes"};
  return kInfo;
}

std::vector<techniques::VariantInfo> WaveParticlesTechnique::variants() const {
  return {
      {"full",
       "the paper's method: constant speed, subdivision into three, wall reflection, amplitude "
       "decay",
       {{"lp2", 0.0}}},
      {"lp2",
       "the simplification of CAPCOM's Lost Planet 2 DirectX 11 talk: a fixed buffer with no "
       "subdivision, radial emission from points, reflection through an AABB tree of boundary "
       "segments, expiry at the lifetime",
       {{"lp2", 1.0}}},
  };
}

std::string WaveParticlesTechnique::checkSupport(const mesh::Mesh&) const {
  return "wave_particles: a simulation; it takes a scenario, not a mesh";
}

std::unique_ptr<techniques::TechniqueInstance> WaveParticlesTechnique::build(
    const techniques::TechniqueInput& input, const techniques::VariantInfo& variant) const {
  if (input.scenario == nullptr) {
    throw techniques::UnsupportedInput(
        "wave_particles: needs a scenario (tessbench run --scenario)");
  }
  const Variant v =
      techniques::paramOr<bool>(info(), variant, "lp2", false) ? Variant::kLp2 : Variant::kFull;
  return std::make_unique<techniques::SimulationInstance>(
      std::make_unique<WaveParticleSimulation>(*input.scenario, v));
}

TB_REGISTER_TECHNIQUE(WaveParticlesTechnique);

}  // namespace tb::wave_particles
