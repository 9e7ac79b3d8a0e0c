// Wave particles on Vulkan compute (core/gpu/compute_runner.h) against the CPU twin: after
// 100 steps of each bundled scenario, the same particle count and every float of every
// particle within kUlpBound ulp. Oracle: the CPU twin (techniques/wave_particles/particles.cpp,
// the same operations in the same float order). The GPU appends in no fixed order, so both
// sides are sorted by particle id (ids survive reflection and are hashed on subdivision).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/gpu/compute_runner.h"
#include "core/mesh/float_ulp.h"
#include "harness/suite/scenario_file.h"
#include "techniques/wave_particles/wave_particles.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb::wave_particles {
namespace {

constexpr uint32_t kSteps = 100;
// The stated bound: `precise` keeps the shader's operations in the CPU's order, so the
// states agree bit for bit on lavapipe; 4 ulp leaves room for a device that rounds a
// product differently (a different order would show as thousands).
constexpr int64_t kUlpBound = 4;

void sortById(std::vector<Particle>* particles) {
  std::sort(particles->begin(), particles->end(),
            [](const Particle& a, const Particle& b) { return a.id < b.id; });
}

// Largest ulp distance over the float fields, particles paired in id order.
int64_t maxUlp(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  int64_t worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const float fa[] = {a[i].origin[0],    a[i].origin[1],      a[i].direction[0],
                        a[i].direction[1], a[i].age_s,          a[i].lifetime_s,
                        a[i].amplitude_m,  a[i].dispersion_rad, a[i].radius_m};
    const float fb[] = {b[i].origin[0],    b[i].origin[1],      b[i].direction[0],
                        b[i].direction[1], b[i].age_s,          b[i].lifetime_s,
                        b[i].amplitude_m,  b[i].dispersion_rad, b[i].radius_m};
    for (size_t k = 0; k < std::size(fa); ++k)
      worst = std::max(worst, int64_t(mesh::ulpDistance(fa[k], fb[k])));
  }
  return worst;
}

struct Compared {
  size_t cpu_count = 0, gpu_count = 0;
  int64_t max_ulp = -1;
  bool ids_match = false;
};

Compared runBoth(gpu::Context& context, const techniques::Scenario& scenario, Variant variant) {
  WaveParticleSimulation cpu(scenario, variant);
  const std::vector<gpu::GpuComputeProgram> programs = cpu.gpuPrograms();
  gpu::ComputeRunner runner(context, programs);
  runner.run(kSteps);  // one submission: no read-back inside the step loop
  for (uint32_t s = 0; s < kSteps; ++s) cpu.step(scenario.time_step_s);
  std::vector<Particle> gpu_particles = WaveParticleSimulation::decodeParticles(
      runner.read(WaveParticleSimulation::particleBufferAfter(kSteps)),
      runner.read(WaveParticleSimulation::counterBufferAfter(kSteps)), cpu.capacity());
  std::vector<Particle> cpu_particles = cpu.particles();
  sortById(&gpu_particles);
  sortById(&cpu_particles);
  Compared compared;
  compared.cpu_count = cpu_particles.size();
  compared.gpu_count = gpu_particles.size();
  if (compared.cpu_count != compared.gpu_count) return compared;
  compared.ids_match =
      std::equal(cpu_particles.begin(), cpu_particles.end(), gpu_particles.begin(),
                 [](const Particle& a, const Particle& b) { return a.id == b.id; });
  if (compared.ids_match) compared.max_ulp = maxUlp(cpu_particles, gpu_particles);
  return compared;
}

TEST(WaveParticlesGpu, CpuAndGpuStatesAgreeAfter100StepsOfEachBundledScenario) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const techniques::Scenario& scenario : suite::bundledScenarios()) {
    if (scenario.technique != "wave_particles") continue;
    for (Variant variant : {Variant::kFull, Variant::kLp2}) {
      const Compared c = runBoth(context, scenario, variant);
      std::printf("%s/%s after %u steps: %zu CPU, %zu GPU particles, max %lld ulp\n",
                  scenario.name.c_str(), variant == Variant::kFull ? "full" : "lp2", kSteps,
                  c.cpu_count, c.gpu_count, (long long)c.max_ulp);
      EXPECT_EQ(c.cpu_count, c.gpu_count) << scenario.name;
      EXPECT_TRUE(c.ids_match) << scenario.name;
      EXPECT_GE(c.max_ulp, 0);
      EXPECT_LE(c.max_ulp, kUlpBound) << scenario.name;
    }
  }
}

TEST(WaveParticlesGpu, LaterEmissionsAndTheGpuCounterFollowTheCpu) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  techniques::Scenario scenario = suite::resolveScenario("wave_straight_wall");
  scenario.sections["wave_particles"] =
      R"({"sources": [{"position_m": [0.0, 0.0], "amplitude_m": 0.1},
                      {"position_m": [-1.0, 0.5], "time_s": 0.5, "amplitude_m": 0.05}],
          "walls": [{"from_m": [1.0, -4.0], "to_m": [1.0, 4.0]},
                    {"from_m": [-2.0, -1.0], "to_m": [-1.5, 1.0]}]})";
  for (Variant variant : {Variant::kFull, Variant::kLp2}) {
    const Compared c = runBoth(context, scenario, variant);
    EXPECT_EQ(c.cpu_count, c.gpu_count);
    EXPECT_GT(c.cpu_count, 32u) << "the second source emitted";
    EXPECT_TRUE(c.ids_match);
    EXPECT_LE(c.max_ulp, kUlpBound);
  }
}

TEST(WaveParticlesGpu, TheGpuHeightMapMatchesTheCpuSplatAndFilter) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (const char* name : {"wave_point_impulse", "wave_straight_wall"}) {
    const techniques::Scenario scenario = suite::resolveScenario(name);
    WaveParticleSimulation cpu(scenario, Variant::kFull);
    gpu::ComputeRunner runner(context, cpu.gpuPrograms());
    runner.run(kSteps);
    for (uint32_t s = 0; s < kSteps; ++s) cpu.step(scenario.time_step_s);
    const HeightField expected = cpu.heightField();
    const HeightField actual = cpu.heightFieldFromWords(runner.read("height_map"));
    ASSERT_EQ(actual.height_m.size(), expected.height_m.size());
    double worst = 0, peak = 0;
    for (size_t i = 0; i < expected.height_m.size(); ++i) {
      worst = std::max(worst, std::abs(actual.height_m[i] - expected.height_m[i]));
      peak = std::max(peak, std::abs(expected.height_m[i]));
    }
    // Fixed-point splat (2^-20 of the amplitude per contribution) and float filter sums.
    const double amplitude = cpu.scene().maxAmplitude();
    std::printf("%s: GPU height map vs CPU: max |dh| = %.3g m (peak %.3g m, amplitude %.3g m)\n",
                name, worst, peak, amplitude);
    EXPECT_GT(peak, 1e-3 * amplitude);
    EXPECT_LT(worst, 1e-5 * amplitude);
    // The displacement map: height in w, unit normals, flat (0, 0, 1) where the water is still.
    const std::vector<uint32_t> words = runner.read("displacement_map");
    const uint32_t n = actual.nodes;
    for (uint32_t c : {0u, n * n / 2 + n / 3, n * n - 1}) {
      const float* v = reinterpret_cast<const float*>(&words[size_t(c) * 4]);
      EXPECT_EQ(v[3], float(actual.height_m[c]));
      EXPECT_NEAR(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 1.0, 1e-6);
    }
    const float* corner = reinterpret_cast<const float*>(&words[0]);
    EXPECT_EQ(corner[2], 1.0f);
    // What the runner allocated is what the simulation says it keeps resident (each buffer
    // rounded up to 16 bytes; full binds a placeholder tree).
    const uint64_t footprint = cpu.footprint().total();
    EXPECT_GE(runner.residentBytes(), footprint);
    EXPECT_LE(runner.residentBytes(), footprint + 256);
  }
}

TEST(WaveParticlesGpu, TheUpdateIsSizedByAnIndirectDispatchFromTheCounter) {
  const techniques::Scenario scenario = suite::resolveScenario("wave_point_impulse");
  const WaveParticleSimulation simulation(scenario, Variant::kLp2);
  const std::vector<gpu::GpuComputeProgram> programs = simulation.gpuPrograms();
  ASSERT_EQ(programs.size(), 2u);  // the step, then the height field
  const gpu::GpuComputePass& update = programs[0].passes.front();
  const gpu::GpuComputePass& splat = programs[1].passes[1];
  EXPECT_EQ(splat.shader, "wave_particles/splat.comp");
  EXPECT_EQ(splat.indirect_buffer, "counter_b") << "the step's output counter";
  EXPECT_EQ(update.shader, "wave_particles/update.comp");
  EXPECT_EQ(update.indirect_buffer, "counter_a");
  EXPECT_EQ(update.indirect_offset_bytes, 0u);
  // The counter ping-pongs with the particles.
  bool alternates = false;
  for (const gpu::GpuComputeBuffer& buffer : update.buffers) {
    alternates |= buffer.name == "counter_a" && buffer.alternate_with == "counter_b";
  }
  EXPECT_TRUE(alternates);
}

}  // namespace
}  // namespace tb::wave_particles
