// The mass-spring solvers as Vulkan compute programs (shaders/mass_spring/), plain data for
// core/gpu/compute_runner.h. Buffers hold the CPU twin's float values bit for bit: vec4 per
// position and anchor (w = 0), springs in colour-major order, Jacobi gather lists.
#include <bit>
#include <cmath>

#include "techniques/mass_spring/mass_spring.h"

namespace tb::mass_spring {
namespace {

constexpr uint32_t kGroupSize = 64;  // local_size_x of every mass_spring shader
// Chebyshev weights tabulated (Wang's recurrence converges long before; later iterations
// take the last entry).
constexpr size_t kChebyshevTable = 1024;

uint32_t word(float f) { return std::bit_cast<uint32_t>(f); }

std::vector<uint32_t> vec4Words(const std::vector<Vec3f>& points) {
  std::vector<uint32_t> words;
  words.reserve(points.size() * 4);
  for (const Vec3f& p : points) words.insert(words.end(), {word(p.x), word(p.y), word(p.z), 0u});
  return words;
}

gpu::GpuComputeBuffer buffer(uint32_t binding, std::string name, std::vector<uint32_t> words,
                             std::string alternate = {}) {
  gpu::GpuComputeBuffer b;
  b.binding = binding;
  b.name = std::move(name);
  b.size_bytes = std::max<uint64_t>(4, words.size() * 4);
  b.initial_words = std::move(words);
  b.alternate_with = std::move(alternate);
  return b;
}

uint32_t groups(size_t threads) { return uint32_t((threads + kGroupSize - 1) / kGroupSize); }

}  // namespace

std::vector<Vec3f> MassSpringSimulation::decodePositions(const std::vector<uint32_t>& words,
                                                         size_t count) {
  std::vector<Vec3f> out(count);
  for (size_t v = 0; v < count && 4 * v + 2 < words.size(); ++v) {
    out[v] = {std::bit_cast<float>(words[4 * v]), std::bit_cast<float>(words[4 * v + 1]),
              std::bit_cast<float>(words[4 * v + 2])};
  }
  return out;
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
      springs.insert(springs.end(), {spring.a, spring.b, word(float(spring.rest_m)),
                                     word(float(spring.weight))});
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
  std::vector<uint32_t> end_start(system_.end_start.begin(), system_.end_start.end());
  std::vector<uint32_t> ends;
  for (const SpringEnd& end : system_.ends) {
    ends.insert(ends.end(), {end.other, word(float(end.rest_m)), word(float(end.weight)), 0u});
  }
  std::vector<uint32_t> scale;
  for (size_t v = 0; v < n; ++v) {
    const uint32_t count = system_.end_start[v + 1] - system_.end_start[v];
    scale.push_back(word(count == 0 ? 0.0f : float(settings.omega / double(count))));
  }
  std::vector<uint32_t> weights;
  double w = 1;
  for (size_t k = 0; k < kChebyshevTable; ++k) {
    w = chebyshevWeight(k, w, settings.rho, settings.delay);
    weights.push_back(word(float(w)));
  }
  gpu::GpuComputePass pass;
  pass.shader = "mass_spring/jacobi.comp";
  // Ping-pong per runner step: even steps read "positions" and write "positions_other",
  // odd steps the reverse, so after an even number of steps "positions" holds the result.
  // Chebyshev: the output buffer holds x_{k-1} on entry (x_0 before the first iteration).
  pass.buffers = {buffer(0, solverPositionBuffer(), positions, "positions_other"),
                  buffer(1, "positions_other", chebyshev ? positions : std::vector<uint32_t>(positions.size(), 0u),
                         solverPositionBuffer()),
                  buffer(2, "anchors", anchors),
                  buffer(3, "end_start", end_start),
                  buffer(4, "ends", ends),
                  buffer(5, "vertex_scale", scale),
                  buffer(6, "chebyshev_weights", weights)};
  pass.specialization = {chebyshev ? 1u : 0u};
  pass.push_constants = {uint32_t(n), uint32_t(kChebyshevTable), 0u};
  pass.step_index_word = 2;
  pass.groups_x = groups(n);
  program.passes.push_back(std::move(pass));
  return {program};
}

std::vector<gpu::GpuComputeProgram> MassSpringSimulation::gpuPrograms() const { return {}; }

}  // namespace tb::mass_spring
