// WaveParticleSimulation's compute programs: update (indirect, from the input counter),
// emit (later sources), prepare (the next dispatch's size), with ping-pong particle and
// counter buffers, run by core/gpu/compute_runner.h. No read-back inside the step loop.
#include <bit>
#include <cmath>
#include <cstring>

#include "techniques/wave_particles/wave_particles.h"

namespace tb::wave_particles {
namespace {

template <class T>
std::vector<uint32_t> words(const std::vector<T>& items) {
  std::vector<uint32_t> out(items.size() * sizeof(T) / 4);
  if (!items.empty()) std::memcpy(out.data(), items.data(), out.size() * 4);
  return out;
}

uint32_t bits(float value) { return std::bit_cast<uint32_t>(value); }

}  // namespace

std::string WaveParticleSimulation::particleBufferAfter(uint32_t steps) {
  return steps == 0 || (steps - 1) % 2 == 1 ? "particles_a" : "particles_b";
}

std::string WaveParticleSimulation::counterBufferAfter(uint32_t steps) {
  return steps == 0 || (steps - 1) % 2 == 1 ? "counter_a" : "counter_b";
}

std::vector<Particle> WaveParticleSimulation::decodeParticles(
    const std::vector<uint32_t>& particle_words, const std::vector<uint32_t>& counter_words,
    uint32_t capacity) {
  const uint32_t count = std::min(counter_words.at(3), capacity);
  std::vector<Particle> particles(count);
  if (count > 0) std::memcpy(particles.data(), particle_words.data(), count * sizeof(Particle));
  return particles;
}

// The output of each step: clear, splat (indirect, from the step's output counter), filter,
// normal. Splat sums are fixed-point (kSplatScaleBits below the largest amplitude) so the
// map does not depend on the order of the atomic adds.
gpu::GpuComputeProgram WaveParticleSimulation::heightFieldProgram(size_t) const {
  const uint32_t n = heightFieldNodes();
  const uint64_t nodes = uint64_t(n) * n;
  const double spacing = scene_.height_field_spacing_m, radius = scene_.particle_radius_m;
  const int reach = int(std::floor(radius / spacing));
  std::vector<uint32_t> kernel;
  for (int dj = -reach; dj <= reach; ++dj) {
    for (int di = -reach; di <= reach; ++di) {
      kernel.push_back(bits(float(particleShape(std::hypot(di * spacing, dj * spacing), radius))));
    }
  }
  const double scale = splatScale();
  const uint32_t groups = uint32_t((nodes + 63) / 64);
  const uint64_t particle_bytes = uint64_t(std::max(settings_.capacity, 1u)) * sizeof(Particle);
  gpu::GpuComputePass clear;
  clear.shader = "wave_particles/clear.comp";
  clear.buffers = {{0, "splat_accumulators", nodes * 4, {}, true, ""}};
  clear.push_constants = {uint32_t(nodes)};
  clear.groups_x = groups;
  gpu::GpuComputePass splat;
  splat.shader = "wave_particles/splat.comp";
  splat.buffers = {{0, "particles_b", particle_bytes, {}, true, "particles_a"},
                   {1, "counter_b", 16, {}, true, "counter_a"},
                   {2, "splat_accumulators", nodes * 4, {}, true, ""}};
  splat.push_constants = {bits(float(-scene_.domain_size_m / 2)), bits(float(spacing)),
                          bits(settings_.speed_m_per_s), bits(float(scale)), n};
  splat.indirect_buffer = "counter_b";
  gpu::GpuComputePass filter;
  filter.shader = "wave_particles/filter.comp";
  filter.buffers = {{0, "splat_accumulators", nodes * 4, {}, true, ""},
                    {1, "filter_kernel", kernel.size() * 4, kernel, true, ""},
                    {2, "height_map", nodes * 4, {}, true, ""}};
  filter.push_constants = {n, uint32_t(reach), bits(float(1.0 / scale))};
  filter.groups_x = groups;
  gpu::GpuComputePass normal;
  normal.shader = "wave_particles/normal.comp";
  normal.buffers = {{0, "height_map", nodes * 4, {}, true, ""},
                    {1, "displacement_map", nodes * 16, {}, true, ""}};
  normal.push_constants = {n, bits(float(spacing))};
  normal.groups_x = groups;
  return {"height_field", {clear, splat, filter, normal}};
}

std::vector<gpu::GpuComputeProgram> WaveParticleSimulation::gpuPrograms() const {
  // At time 0: the state the constructor built (a simulation already stepped still
  // describes its start, as Simulation::gpuPrograms says).
  WaveParticleSimulation start(scenario_, settings_.variant);
  const uint64_t particle_bytes = uint64_t(std::max(settings_.capacity, 1u)) * sizeof(Particle);
  const uint32_t count = uint32_t(start.particles_.size());
  std::vector<uint32_t> levels;
  for (size_t k = 0; k < table_.theta.size(); ++k) {
    levels.insert(levels.end(),
                  {bits(table_.theta[k]), bits(table_.child_cos[k]), bits(table_.child_sin[k])});
  }
  std::vector<uint32_t> tree_words = words(tree_);
  if (tree_words.empty()) tree_words.assign(8, 0);  // full: unused, but bound
  const std::vector<uint32_t> wall_words = words(walls_);
  using gpu::GpuComputeBuffer;
  const GpuComputeBuffer particles_in{0,    "particles_a", particle_bytes, words(start.particles_),
                                      true, "particles_b"};
  const GpuComputeBuffer particles_out{1, "particles_b", particle_bytes, {}, true, "particles_a"};
  const GpuComputeBuffer counter_in{2,    "counter_a", 16, {(count + 63) / 64, 1, 1, count},
                                    true, "counter_b"};
  const GpuComputeBuffer counter_out{3, "counter_b", 16, {}, true, "counter_a"};

  gpu::GpuComputePass update;
  update.shader = "wave_particles/update.comp";
  update.buffers = {particles_in,
                    particles_out,
                    counter_in,
                    counter_out,
                    {4, "walls", wall_words.size() * 4, wall_words, true, ""},
                    {5, "tree", tree_words.size() * 4, tree_words, true, ""},
                    {6, "subdivision_table", levels.size() * 4, levels, true, ""}};
  update.specialization = {settings_.variant == Variant::kLp2 ? 1u : 0u};
  update.push_constants = {bits(float(scenario_.time_step_s)),
                           bits(settings_.speed_m_per_s),
                           bits(settings_.decay_per_step),
                           bits(settings_.min_amplitude_m),
                           bits(settings_.subdivide_fraction),
                           settings_.capacity,
                           uint32_t(walls_.size()),
                           uint32_t(tree_.size()),
                           uint32_t(table_.theta.size())};
  update.indirect_buffer = "counter_a";

  gpu::GpuComputeProgram step{"step", {update}};
  if (!start.pending_.empty()) {
    gpu::GpuComputePass emit;
    emit.shader = "wave_particles/emit.comp";
    const std::vector<uint32_t> pending = words(start.pending_);
    emit.buffers = {{0, "pending", pending.size() * 4, pending, true, ""},
                    {1, "particles_b", particle_bytes, {}, true, "particles_a"},
                    {2, "counter_b", 16, {}, true, "counter_a"}};
    emit.push_constants = {0, uint32_t(start.pending_.size()), settings_.capacity};
    emit.step_index_word = 0;
    emit.groups_x = (uint32_t(start.pending_.size()) + 63) / 64;
    step.passes.push_back(emit);
  }
  gpu::GpuComputePass prepare;
  prepare.shader = "wave_particles/prepare.comp";
  prepare.buffers = {{0, "counter_a", 16, {}, true, "counter_b"},
                     {1, "counter_b", 16, {}, true, "counter_a"},
                     {2, "stats", 16, {count, 0, 0, 0}, true, ""}};
  prepare.push_constants = {settings_.capacity};
  step.passes.push_back(prepare);
  return {step, heightFieldProgram(start.particles_.size())};
}

}  // namespace tb::wave_particles
