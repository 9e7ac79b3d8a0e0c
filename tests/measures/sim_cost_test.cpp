// The sim_cost measure's algorithm (harness/measures/sim_cost/sim_cost.h) on a simulation double
// whose figures are known by hand: a fixed element count, a footprint, and compute
// programs whose dispatches per step are counted by hand (1 + 3 + 2 = 6).
#include "harness/measures/sim_cost/sim_cost.h"

#include <gtest/gtest.h>

#include "tests/gpu/gpu_test_support.h"

namespace tb {
namespace {

// Grows by one element a step from 5; two programs: (1 pass, 1 repeat + 1 pass, 3 repeats)
// and (1 pass, 2 repeats), each adding 1 to a counter per dispatch.
class GrowingDouble final : public techniques::Simulation {
 public:
  GrowingDouble() {
    scenario_.name = "test/growing";
    scenario_.time_step_s = 0.5;
    scenario_.duration_s = 4.0;  // 8 steps
  }
  const techniques::Scenario& scenario() const override { return scenario_; }
  void step(double dt_s) override {
    time_s_ += dt_s;
    ++elements_;
  }
  techniques::SimulationState state() const override {
    techniques::SimulationState state;
    state.time_s = time_s_;
    state.element_count = elements_;
    return state;
  }
  std::vector<gpu::GpuComputeProgram> gpuPrograms() const override {
    auto pass = [](uint32_t repeats) {
      gpu::GpuComputePass p;
      p.shader = "gpu/test_runner_count.comp";
      p.buffers = {{0, "total", 4, {}, true, ""}};
      p.repeats_per_step = repeats;
      return p;
    };
    return {{"first", {pass(1), pass(3)}}, {"second", {pass(2)}}};
  }
  techniques::SimulationFootprint footprint() const override { return {400, 24, 0, ""}; }

 private:
  techniques::Scenario scenario_;
  double time_s_ = 0;
  uint64_t elements_ = 5;
};

TEST(SimCost, ElementsPeakAndDispatchesAreTheHandCountedOnes) {
  GrowingDouble simulation;
  const measures::SimCostFigures figures =
      measures::measureSimCost(simulation, 4, nullptr, "no device here", 100);
  EXPECT_EQ(figures.steps, 8u);
  ASSERT_EQ(figures.samples.size(), 4u);
  // Steps 2, 4, 6, 8: 5 + step elements at 0.5 s a step.
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(figures.samples[k].time_s, 1.0 * double(k + 1));
    EXPECT_EQ(figures.samples[k].elements, 5u + 2 * (k + 1));
  }
  EXPECT_EQ(figures.peak_elements, 13u);
  EXPECT_EQ(figures.compute_passes, 3u);
  EXPECT_EQ(figures.dispatches_per_step, 6u);
  EXPECT_EQ(figures.footprint.total(), 424u);
  EXPECT_FALSE(figures.gpu_steps.has_value());
  EXPECT_EQ(figures.gpu_skip_reason, "no Vulkan device (no device here)");
}

TEST(SimCost, TheDeviceRunDispatchesAsDeclared) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  GrowingDouble simulation;
  const measures::SimCostFigures figures = measures::measureSimCost(simulation, 2, &context, "", 3);
  ASSERT_TRUE(figures.gpu_steps.has_value());
  EXPECT_EQ(*figures.gpu_steps, 3u) << "limited to 3 of the 8 steps";
  EXPECT_EQ(*figures.gpu_resident_bytes, 16u) << "one buffer, 'total', at the 16-byte minimum";
  EXPECT_TRUE(figures.gpu_seconds_per_step.has_value());
}

}  // namespace
}  // namespace tb
