// The compute runner (core/gpu/compute_runner.h) end to end. Oracle: the same list rule
// run on the host (append every element + 100, then the step index), compared as sorted
// multisets since atomic appends have no fixed order.
#include "core/gpu/compute_runner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

constexpr uint32_t kAdd = 100;
constexpr uint64_t kListBytes = 4096 * 4;

std::vector<GpuComputeProgram> growProgram(uint32_t repeats) {
  GpuComputePass grow;
  grow.shader = "gpu/test_runner_grow.comp";
  grow.buffers = {{0, "list_a", kListBytes, {10, 20}, true, "list_b"},
                  {1, "list_b", kListBytes, {}, true, "list_a"},
                  {2, "count_a", 16, {1, 1, 1, 2}, true, "count_b"},
                  {3, "count_b", 16, {}, true, "count_a"}};
  grow.specialization = {kAdd};
  grow.push_constants = {0};
  grow.step_index_word = 0;
  grow.indirect_buffer = "count_a";
  GpuComputePass prepare;
  prepare.shader = "gpu/test_runner_prepare.comp";
  prepare.buffers = {{0, "count_a", 16, {}, true, "count_b"},
                     {1, "count_b", 16, {}, true, "count_a"}};
  GpuComputePass count;
  count.shader = "gpu/test_runner_count.comp";
  count.buffers = {{0, "total", 4, {}, true, ""}};
  count.repeats_per_step = repeats;
  return {{"grow", {grow, prepare}}, {"count", {count}}};
}

// The host twin: the list after `steps` steps, sorted.
std::vector<uint32_t> hostList(uint32_t steps) {
  std::vector<uint32_t> list = {10, 20};
  for (uint32_t step = 0; step < steps; ++step) {
    std::vector<uint32_t> next;
    for (uint32_t v : list) next.push_back(v + kAdd);
    next.push_back(step);
    list = next;
  }
  std::sort(list.begin(), list.end());
  return list;
}

// The list the runner holds after its last step: the output side of that step.
std::vector<uint32_t> deviceList(const ComputeRunner& runner) {
  const bool odd = runner.stepsDone() % 2 == 1;  // after an odd count, step s-1 was even
  const std::vector<uint32_t> counter = runner.read(odd ? "count_b" : "count_a");
  const std::vector<uint32_t> words = runner.read(odd ? "list_b" : "list_a");
  std::vector<uint32_t> list(words.begin(), words.begin() + counter[3]);
  std::sort(list.begin(), list.end());
  return list;
}

TEST(ComputeRunner, PingPongIndirectAppendMatchesTheHostRule) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  ComputeRunner runner(context, growProgram(3));
  EXPECT_EQ(runner.dispatchesPerStep(), 2u + 3u);
  const ComputeRunTiming timing = runner.run(7);  // 7 steps, one submission
  EXPECT_EQ(timing.steps, 7u);
  EXPECT_EQ(deviceList(runner), hostList(7));
  EXPECT_EQ(runner.read("total")[0], 3u * 7u) << "repeats_per_step";
  // The next run continues the step index and the parity.
  runner.run(4);
  EXPECT_EQ(runner.stepsDone(), 11u);
  EXPECT_EQ(deviceList(runner), hostList(11));
  // The indirect size the last prepare wrote covers the list (64 a group).
  const std::vector<uint32_t> counter = runner.read("count_b");
  EXPECT_EQ(counter[0], (counter[3] + 63) / 64);
  if (context.features().timestamps) {
    EXPECT_FALSE(std::isnan(timing.gpu_ns));
  }
}

TEST(ComputeRunner, BuffersArePerNameAndSizedByTheLargestDeclaration) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  ComputeRunner runner(context, growProgram(1));
  const std::vector<std::string> names = runner.bufferNames();
  EXPECT_EQ(names, (std::vector<std::string>{"count_a", "count_b", "list_a", "list_b", "total"}));
  EXPECT_EQ(runner.read("list_b").size() * 4, kListBytes);
  EXPECT_EQ(runner.residentBytes(), 2 * kListBytes + 2 * 16 + 16);
  EXPECT_EQ(runner.read("list_a")[1], 20u) << "initial words uploaded";
}

TEST(ComputeRunner, InconsistentDescriptionsThrow) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  std::vector<GpuComputeProgram> programs = growProgram(1);
  programs[0].passes[0].indirect_buffer = "nowhere";
  EXPECT_THROW(ComputeRunner(context, programs), GpuError);
  programs = growProgram(0);
  EXPECT_THROW(ComputeRunner(context, programs), GpuError);
  programs = growProgram(1);
  programs[0].passes[0].step_index_word = 3;
  EXPECT_THROW(ComputeRunner(context, programs), GpuError);
  ComputeRunner runner(context, growProgram(1));
  EXPECT_THROW(runner.read("nowhere"), GpuError);
}

}  // namespace
}  // namespace tb::gpu
