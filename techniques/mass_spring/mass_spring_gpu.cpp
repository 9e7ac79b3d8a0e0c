// The mass-spring solvers as Vulkan compute programs (shaders/mass_spring/), plain data for
// core/gpu/compute_runner.h. Buffers hold the CPU twin's float values bit for bit: vec4 per
// position and anchor (w = 0), springs in colour-major order, Jacobi gather lists.
#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

#include "shaders/mass_spring/mass_spring_layout.h"
#include "techniques/mass_spring/mass_spring.h"

namespace tb::mass_spring {
namespace {

constexpr uint32_t kGroupSize = 64;  // local_size_x of every mass_spring shader
// Chebyshev weights tabulated (Wang's recurrence converges long before; later iterations
// take the last entry).
constexpr size_t kChebyshevTable = 1024;
// The stomp phase table of gpuPrograms() covers this many times the scenario's steps (the
// stability measure's --suite full run); later steps hold the last phase.
constexpr size_t kSineTableLength = 10;

uint32_t word(float f) { return std::bit_cast<uint32_t>(f); }

std::vector<uint32_t> vec4Words(const std::vector<mesh::Vec3f>& points) {
  std::vector<uint32_t> words;
  words.reserve(points.size() * 4);
  for (const mesh::Vec3f& p : points)
    words.insert(words.end(), {word(p.x), word(p.y), word(p.z), 0u});
  return words;
}

gpu::GpuComputeBuffer buffer(uint32_t binding, std::string name, std::vector<uint32_t> words,
                             std::string alternate = {}) {
  gpu::GpuComputeBuffer b;
  b.binding = binding;
  b.name = std::move(name);
  b.size_bytes = std::max<uint64_t>(16, words.size() * 4);  // the runner's least allocation
  b.initial_words = std::move(words);
  b.alternate_with = std::move(alternate);
  return b;
}

// A spring as gs_colour*.comp read it (shaders/mass_spring/mass_spring_layout.h).
gpu::layout::mass_spring::Spring springRecord(const Spring& spring) {
  return {spring.a, spring.b, float(spring.rest_m), float(spring.weight)};
}

uint32_t groups(size_t threads) { return uint32_t((threads + kGroupSize - 1) / kGroupSize); }

// The blasts for verlet.comp: centre, radius, speed and the step each fires on.
std::vector<uint32_t> blastWords(const std::vector<Blast>& input_blasts, const mesh::Vec3d& origin,
                                 double dt, size_t rows) {
  std::vector<uint32_t> blasts;
  for (const Blast& blast : input_blasts) {
    // The step it fires on (mass_spring.cpp, step()): the first whose end reaches time_s.
    size_t k = size_t(std::max(0.0, std::floor(blast.time_s / dt) - 2));
    while (k < rows && !(double(k + 1) * dt >= blast.time_s)) ++k;
    const mesh::Vec3f centre = vecCast<float>(blast.center_m - origin);
    const gpu::layout::mass_spring::Blast record{{centre.x, centre.y, centre.z, 0.0f},
                                                 float(blast.radius_m),
                                                 float(blast.speed_m_per_s),
                                                 k < rows ? uint32_t(k) : 0xffffffffu,
                                                 0u};
    gpu::layout::appendWords(blasts, record);
  }
  return blasts;
}

// Gauss-Seidel: `budget` coloured sweeps per step (gs_colour_step.comp).
void appendGaussSeidelSteps(const SpringSystem& system, const std::vector<uint32_t>& positions,
                            const std::vector<mesh::Vec3f>& anchors, uint32_t budget,
                            gpu::GpuComputeProgram& program) {
  std::vector<uint32_t> springs;
  for (uint32_t s : system.colour_order) {
    const Spring& spring = system.springs[s];
    gpu::layout::appendWords(springs, springRecord(spring));
  }
  uint32_t largest = 0;
  for (uint32_t c = 0; c < system.colour_count; ++c) {
    largest = std::max(largest, system.colour_start[c + 1] - system.colour_start[c]);
  }
  for (uint32_t d = 0; d < budget; ++d) {
    gpu::GpuComputePass pass;
    pass.shader = "mass_spring/gs_colour_step.comp";
    pass.buffers = {buffer(0, "positions", positions), buffer(1, "anchors", vec4Words(anchors)),
                    buffer(2, "springs", springs), buffer(3, "colour_start", system.colour_start)};
    pass.push_constants = {d, budget, system.colour_count, 0u};
    pass.step_index_word = 3;
    pass.groups_x = groups(largest);
    program.passes.push_back(std::move(pass));
  }
}

// Jacobi (Chebyshev or not): `budget` ping-pong iterations per step (jacobi.comp), then a
// copy back into "positions" after an odd count.
void appendJacobiSteps(size_t n, const std::vector<uint32_t>& positions,
                       const std::vector<mesh::Vec3f>& anchors,
                       const std::vector<uint32_t>& end_start, const std::vector<uint32_t>& ends,
                       const std::vector<uint32_t>& scale, const std::vector<uint32_t>& weights,
                       bool chebyshev, bool tiled, uint32_t budget,
                       gpu::GpuComputeProgram& program) {
  for (uint32_t d = 0; d < budget; ++d) {
    const bool even = d % 2 == 0;
    gpu::GpuComputePass pass;
    pass.shader = "mass_spring/jacobi.comp";
    pass.buffers = {buffer(0, even ? "positions" : "positions_other", positions),
                    buffer(1, even ? "positions_other" : "positions", positions),
                    buffer(2, "anchors", vec4Words(anchors)),
                    buffer(3, "end_start", end_start),
                    buffer(4, "ends", ends),
                    buffer(5, "vertex_scale", scale),
                    buffer(6, "chebyshev_weights", weights)};
    // Only the first declaration of a name uploads: every pass declares the same words.
    pass.specialization = {chebyshev ? 1u : 0u, tiled ? 1u : 0u};
    pass.push_constants = {uint32_t(n), uint32_t(kChebyshevTable), d};
    pass.groups_x = groups(n);
    program.passes.push_back(std::move(pass));
  }
  if (budget % 2 == 1) {
    gpu::GpuComputePass copy;
    copy.shader = "mass_spring/copy.comp";
    copy.buffers = {buffer(0, "positions", positions), buffer(1, "positions_other", positions)};
    copy.push_constants = {uint32_t(n)};
    copy.groups_x = groups(n);
    program.passes.push_back(std::move(copy));
  }
}

}  // namespace

std::vector<mesh::Vec3f> MassSpringSimulation::decodePositions(const std::vector<uint32_t>& words,
                                                               size_t count) {
  std::vector<mesh::Vec3f> out(count);
  for (size_t v = 0; v < count && 4 * v + 2 < words.size(); ++v) {
    out[v] = {std::bit_cast<float>(words[4 * v]), std::bit_cast<float>(words[4 * v + 1]),
              std::bit_cast<float>(words[4 * v + 2])};
  }
  return out;
}

MassSpringSimulation::JacobiBuffers MassSpringSimulation::jacobiBuffers() const {
  const SolverSettings& settings = solver_.settings();
  JacobiBuffers tables;
  tables.end_start.assign(system_.end_start.begin(), system_.end_start.end());
  for (const SpringEnd& end : system_.ends) {
    gpu::layout::appendWords(tables.ends, gpu::layout::mass_spring::End{
                                              end.other, float(end.rest_m), float(end.weight), 0u});
  }
  for (size_t v = 0; v < system_.vertex_count; ++v) {
    const uint32_t count = system_.end_start[v + 1] - system_.end_start[v];
    tables.scale.push_back(word(count == 0 ? 0.0f : float(settings.omega / double(count))));
  }
  double w = 1;
  for (size_t k = 0; k < kChebyshevTable; ++k) {
    w = chebyshevWeight(k, w, settings.rho, settings.delay);
    tables.weights.push_back(word(float(w)));
  }
  return tables;
}

std::vector<gpu::GpuComputeProgram> MassSpringSimulation::solverPrograms() const {
  const SolverSettings& settings = solver_.settings();
  const size_t n = system_.vertex_count;
  const std::vector<uint32_t> positions = vec4Words(state_.x);
  const std::vector<uint32_t> anchors = vec4Words(state_.anchors);
  gpu::GpuComputeProgram program;
  if (settings.kind == SolverKind::kGaussSeidelColoured) {
    program.name = "gs_colored";
    std::vector<uint32_t> springs;
    for (uint32_t s : system_.colour_order) {
      const Spring& spring = system_.springs[s];
      gpu::layout::appendWords(springs, springRecord(spring));
    }
    for (uint32_t c = 0; c < system_.colour_count; ++c) {
      gpu::GpuComputePass pass;
      pass.shader = "mass_spring/gs_colour.comp";
      pass.buffers = {buffer(0, solverPositionBuffer(), positions), buffer(1, "anchors", anchors),
                      buffer(2, "springs", springs)};
      pass.push_constants = {system_.colour_start[c], system_.colour_start[c + 1]};
      pass.groups_x = groups(system_.colour_start[c + 1] - system_.colour_start[c]);
      program.passes.push_back(std::move(pass));
    }
    return {program};
  }
  if (settings.kind == SolverKind::kGaussSeidelSerial) return {};

  const bool chebyshev = settings.kind == SolverKind::kJacobiChebyshev;
  program.name = chebyshev ? "jacobi_chebyshev" : "jacobi";
  const JacobiBuffers tables = jacobiBuffers();
  gpu::GpuComputePass pass;
  pass.shader = "mass_spring/jacobi.comp";
  // Ping-pong per runner step: even steps read "positions" and write "positions_other",
  // odd steps the reverse, so after an even number of steps "positions" holds the result.
  // Chebyshev: the output buffer holds x_{k-1} on entry (x_0 before the first iteration).
  pass.buffers = {buffer(0, solverPositionBuffer(), positions, "positions_other"),
                  buffer(1, "positions_other",
                         chebyshev ? positions : std::vector<uint32_t>(positions.size(), 0u),
                         solverPositionBuffer()),
                  buffer(2, "anchors", anchors),
                  buffer(3, "end_start", tables.end_start),
                  buffer(4, "ends", tables.ends),
                  buffer(5, "vertex_scale", tables.scale),
                  buffer(6, "chebyshev_weights", tables.weights)};
  pass.specialization = {chebyshev ? 1u : 0u, settings.tiled ? 1u : 0u};
  pass.push_constants = {uint32_t(n), uint32_t(kChebyshevTable), 0u};
  pass.step_index_word = 2;
  pass.groups_x = groups(n);
  program.passes.push_back(std::move(pass));
  return {program};
}

std::vector<gpu::GpuComputeProgram> MassSpringSimulation::gpuPrograms() const {
  if (solver_.settings().kind == SolverKind::kGaussSeidelSerial) return {};
  return stepPrograms(solver_.settings().kind);
}

techniques::SimulationFootprint MassSpringSimulation::footprint() const {
  // The buffers the compute runner allocates for the step programs (one per name, the
  // largest size declared); gs_serial, with no GPU path, as its coloured twin would.
  const SolverKind kind = solver_.settings().kind == SolverKind::kGaussSeidelSerial
                              ? SolverKind::kGaussSeidelColoured
                              : solver_.settings().kind;
  std::map<std::string, uint64_t> sizes;
  for (const gpu::GpuComputeProgram& program : stepPrograms(kind)) {
    for (const gpu::GpuComputePass& pass : program.passes) {
      for (const gpu::GpuComputeBuffer& b : pass.buffers) {
        sizes[b.name] = std::max(sizes[b.name], (b.size_bytes + 3) / 4 * 4);
      }
    }
  }
  techniques::SimulationFootprint footprint;
  for (const auto& [name, bytes] : sizes) {
    const bool state =
        name == "positions" || name == "previous_positions" || name == "positions_other";
    (state ? footprint.state_bytes : footprint.auxiliary_bytes) += bytes;
  }
  return footprint;
}

gpu::GpuComputePass MassSpringSimulation::renderPass() const {
  std::vector<uint32_t> bindings;
  for (const TetBinding& b : render_mesh_.bindings) {
    gpu::layout::appendWords(
        bindings, gpu::layout::mass_spring::Binding{b.v0, b.v1, b.v2, float(b.w0), float(b.w1),
                                                    float(b.w2), float(b.volume), 0u});
  }
  const size_t count = render_mesh_.bindings.size();
  gpu::GpuComputePass pass;
  pass.shader = "mass_spring/render.comp";
  pass.buffers = {buffer(0, "positions", vec4Words(state_.x)),
                  buffer(1, "render_bindings", bindings),
                  buffer(2, "render_positions", std::vector<uint32_t>(4 * count, 0u))};
  pass.push_constants = {uint32_t(count)};
  pass.groups_x = groups(count);
  return pass;
}

std::vector<gpu::GpuComputeProgram> MassSpringSimulation::stepPrograms(SolverKind kind) const {
  const size_t n = system_.vertex_count, stomps = input_->stomps.size();
  const double dt = scenario_.time_step_s;
  const std::vector<uint32_t> positions = vec4Words(state_.x);
  const bool chebyshev = kind == SolverKind::kJacobiChebyshev;
  const bool jacobi = chebyshev || kind == SolverKind::kJacobi;

  // The step's first pass: animation, blast, Verlet (verlet.comp).
  std::vector<uint32_t> sines;
  const size_t rows = kSineTableLength * std::max<size_t>(1, scenario_.stepCount()) + 2;
  for (size_t j = 0; j < rows; ++j) {
    for (size_t st = 0; st < stomps; ++st) sines.push_back(word(stompSine(st, j, dt)));
  }
  std::vector<uint32_t> amplitudes = vec4Words(stomp_amplitude_);
  std::vector<uint32_t> blasts = blastWords(input_->blasts, origin_, dt, rows);
  const mesh::Vec3f gravity_step = vecCast<float>((dt * dt) * input_->gravity_m_per_s2);
  gpu::GpuComputePass verlet;
  verlet.shader = "mass_spring/verlet.comp";
  verlet.buffers = {
      buffer(0, "positions", positions), buffer(1, "previous_positions", vec4Words(x_previous_)),
      buffer(2, "anchors", vec4Words(state_.anchors)), buffer(3, "rest", vec4Words(rest_f_)),
      buffer(4, "bone_rest", vec4Words(bone_f_)), buffer(5, "stomp_amplitudes", amplitudes),
      buffer(6, "stomp_sines", sines), buffer(7, "blasts", blasts),
      // Gauss-Seidel has no second position buffer: binding 8 aliases the
      // first and is never written (kCopyToOther = 0).
      jacobi ? buffer(8, "positions_other", std::vector<uint32_t>(positions.size(), 0u))
             : buffer(8, "positions", positions)};
  verlet.specialization = {chebyshev ? 1u : 0u};
  verlet.push_constants = {uint32_t(n),
                           uint32_t(stomps),
                           uint32_t(rows),
                           uint32_t(input_->blasts.size()),
                           word(float(1 - input_->damping)),
                           word(gravity_step.x),
                           word(gravity_step.y),
                           word(gravity_step.z),
                           word(float(dt)),
                           0u};
  verlet.step_index_word = 9;
  verlet.groups_x = groups(n);
  gpu::GpuComputeProgram program;
  program.name = "step";
  program.passes.push_back(std::move(verlet));

  const uint32_t budget = uint32_t(dispatches_per_step_);
  if (!jacobi) {
    appendGaussSeidelSteps(system_, positions, state_.anchors, budget, program);
    program.passes.push_back(renderPass());
    return {program};
  }
  const JacobiBuffers tables = jacobiBuffers();
  appendJacobiSteps(n, positions, state_.anchors, tables.end_start, tables.ends, tables.scale,
                    tables.weights, chebyshev, solver_.settings().tiled, budget, program);
  program.passes.push_back(renderPass());
  return {program};
}

}  // namespace tb::mass_spring
