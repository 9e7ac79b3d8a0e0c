// Time per step of the simulations (sim_cost's timings, which results.json never holds):
// the CPU twin and the Vulkan compute path (core/gpu/compute_runner.h, every step of a run in
// one submission, timed by GPU timestamps when the queue has them, else submit to fence),
// per bundled scenario and variant. Counters: seconds_per_step, elements at the end. The CPU
// step is the particle update alone; the GPU step also splats, filters and makes the normal
// map (wave particles: 6 dispatches, the filter dominating on lavapipe).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "core/gpu/compute_runner.h"
#include "core/gpu/context.h"
#include "harness/suite/scenario_file.h"
#include "techniques/registry.h"

namespace {

struct Case {
  const tb::techniques::Technique* technique = nullptr;
  tb::techniques::VariantInfo variant;
  tb::techniques::Scenario scenario;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const tb::techniques::Scenario& scenario : tb::suite::bundledScenarios()) {
    const tb::techniques::Technique* technique =
        tb::techniques::TechniqueRegistry::instance().find(scenario.technique);
    if (technique == nullptr) continue;
    for (const tb::techniques::VariantInfo& variant : technique->variants()) {
      all.push_back({technique, variant, scenario});
    }
  }
  return all;
}

void cpuSteps(benchmark::State& state, const Case& c) {
  for (auto _ : state) {
    auto instance = c.technique->build({nullptr, &c.scenario}, c.variant);
    tb::techniques::Simulation& simulation = *instance->simulation();
    const size_t steps = c.scenario.stepCount();
    for (size_t s = 0; s < steps; ++s) simulation.step(c.scenario.time_step_s);
    state.counters["elements"] = double(simulation.state().element_count);
    state.counters["steps"] = double(steps);
  }
  state.counters["seconds_per_step"] = benchmark::Counter(
      double(c.scenario.stepCount()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void gpuSteps(benchmark::State& state, const Case& c) {
  static auto context = tb::gpu::Context::create();
  if (!context) {
    state.SkipWithError(("no usable Vulkan device: " + context.error()).c_str());
    return;
  }
  auto instance = c.technique->build({nullptr, &c.scenario}, c.variant);
  const auto programs = instance->simulation()->gpuPrograms();
  const uint32_t steps = uint32_t(c.scenario.stepCount());
  double seconds = 0;
  for (auto _ : state) {
    tb::gpu::ComputeRunner runner(*context.value(), programs);
    const tb::gpu::ComputeRunTiming timing = runner.run(steps);
    const double run_s =
        std::isnan(timing.gpu_ns) ? timing.submit_to_fence_s : timing.gpu_ns * 1e-9;
    state.SetIterationTime(run_s);
    seconds += run_s;
  }
  state.counters["seconds_per_step"] = seconds / double(state.iterations()) / double(steps);
  state.counters["dispatches_per_step"] = 0;
  for (const auto& program : programs) {
    for (const auto& pass : program.passes)
      state.counters["dispatches_per_step"] += pass.repeats_per_step;
  }
}

// Registered from main: the techniques register themselves from static initialisers, which
// may run after this file's.
void registerAll() {
  for (const Case& c : cases()) {
    const std::string name = c.technique->info().id + "/" + c.variant.name + "/" + c.scenario.name;
    benchmark::RegisterBenchmark(("BM_SimulationCpu/" + name).c_str(),
                                 [c](benchmark::State& state) { cpuSteps(state, c); })
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_SimulationGpu/" + name).c_str(),
                                 [c](benchmark::State& state) { gpuSteps(state, c); })
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  registerAll();
  return tb::bench::runBenchmarks(argc, argv);
}
