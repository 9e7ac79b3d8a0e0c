// Wave particles (Yuksel, House and Keyser, "Wave Particles", SIGGRAPH 2007) as a
// simulation technique, in two variants: `full`, the paper's method (constant speed,
// subdivision into three, wall reflection, amplitude decay), and `lp2`, seed 003's
// simplification (a fixed buffer and no subdivision, radial emission from points,
// reflection through a stackless AABB tree of boundary segments, expiry at the lifetime).
// The CPU twin steps here; gpuPrograms() are the same steps as Vulkan compute (ping-pong
// buffers, an atomic append counter, the update sized by vkCmdDispatchIndirect from it).
// The output is the height field (splat + filter, height_field.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "techniques/technique.h"
#include "techniques/wave_field.h"
#include "techniques/wave_particles/height_field.h"
#include "techniques/wave_particles/particles.h"
#include "techniques/wave_particles/wave_scene.h"

namespace tb::wave_particles {

// Levels of subdivision the `full` table holds (2*pi/N / 3^12 is far below any radius).
constexpr int kSubdivisionLevels = 12;

class WaveParticleSimulation final : public techniques::Simulation, public techniques::WaveField {
 public:
  WaveParticleSimulation(const techniques::Scenario& scenario, Variant variant);

  const techniques::Scenario& scenario() const override { return scenario_; }
  // Advances by dt_s; the GPU programs use scenario().time_step_s.
  void step(double dt_s) override;
  techniques::SimulationState state() const override;
  std::vector<gpu::GpuComputeProgram> gpuPrograms() const override;
  techniques::SimulationFootprint footprint() const override;
  const techniques::WaveField* waveField() const override { return this; }

  // WaveField (the scene, packets and height field, for the wave_error measure)
  techniques::WaveFieldScene waveScene() const override;
  techniques::WaveHeightGrid heightGrid() const override;
  std::vector<std::array<float, 2>> packetPositions() const override;

  const WaveScene& scene() const { return scene_; }
  Variant variant() const { return settings_.variant; }
  const std::vector<Particle>& particles() const { return particles_; }
  double timeS() const override { return time_s_; }
  uint32_t stepsDone() const { return steps_; }
  uint64_t dropped() const { return dropped_; }  // appends beyond the buffer, so far
  uint32_t capacity() const { return settings_.capacity; }
  const StepSettings& settings() const { return settings_; }
  // The output: particles splatted and filtered on the scene's height-field grid.
  HeightField heightField() const;
  // The exact particle sum at a point (probes).
  double heightAt(double x_m, double y_m) const override;

  // The GPU side of gpuPrograms(): which buffer holds the particles and the counter after
  // `steps` steps, and the particles decoded from those buffers' words.
  static std::string particleBufferAfter(uint32_t steps);
  static std::string counterBufferAfter(uint32_t steps);
  static std::vector<Particle> decodeParticles(const std::vector<uint32_t>& particle_words,
                                               const std::vector<uint32_t>& counter_words,
                                               uint32_t capacity);

  // The height-field grid: nodes per side, and the fixed-point scale of the GPU splat
  // (units per metre: 2^20 over the largest source amplitude).
  uint32_t heightFieldNodes() const;
  double splatScale() const;
  // The GPU height map (buffer "height_map" of gpuPrograms()) as a HeightField.
  HeightField heightFieldFromWords(const std::vector<uint32_t>& height_words) const;

 private:
  void emitPending(uint32_t step, std::vector<Particle>* out);
  gpu::GpuComputeProgram heightFieldProgram(size_t initial_count) const;

  techniques::Scenario scenario_;
  WaveScene scene_;
  StepSettings settings_;
  std::vector<WallSegment> walls_;
  std::vector<AabbNode> tree_;  // lp2 only
  SubdivisionTable table_;
  std::vector<Particle> particles_;
  std::vector<Particle> pending_;  // later emissions, with their emit_step
  double time_s_ = 0;
  uint32_t steps_ = 0;
  uint64_t dropped_ = 0;
};

class WaveParticlesTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override;
  std::vector<techniques::VariantInfo> variants() const override;
  std::string checkSupport(const mesh::Mesh& mesh) const override;
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input,
      const techniques::VariantInfo& variant) const override;
  techniques::SimulationCapabilities simulationCapabilities() const override {
    return {.constraint_solver = false, .wave_field = true};
  }
};

}  // namespace tb::wave_particles
