// Every benchmark's JSON names the device its figures came from: Google Benchmark's
// "context" gains vulkan_device (gpu::describeDevice: name, driver, Vulkan version; the
// identity results.json and timings.json use, so figures of two devices are never joined)
// and vulkan_driver. TB_BENCHMARK_MAIN() is BENCHMARK_MAIN() with that context.
#pragma once

#include <benchmark/benchmark.h>

#include <string>

#include "core/gpu/context.h"

namespace tb::bench {

// Opens the default device once (lavapipe here) to name it; "none: REASON" without one.
inline void addDeviceContext() {
  gpu::ContextOptions options;
  options.required = {};
  auto created = gpu::Context::create(options);
  if (!created) {
    benchmark::AddCustomContext("vulkan_device", "none: " + created.error());
    return;
  }
  const gpu::DeviceInfo& info = created.value()->info();
  benchmark::AddCustomContext("vulkan_device", gpu::describeDevice(info));
  benchmark::AddCustomContext("vulkan_driver", info.driver_name + " " + info.driver_info);
}

// The default device, opened once per program, for the benchmarks that run on it; null, with
// the benchmark skipped and the reason given, when no device is usable.
inline gpu::Context* benchContext(benchmark::State& state) {
  static auto context = gpu::Context::create();
  if (!context) {
    state.SkipWithError(("no usable Vulkan device: " + context.error()).c_str());
    return nullptr;
  }
  return context.value().get();
}

inline int runBenchmarks(int argc, char** argv) {
  addDeviceContext();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace tb::bench

#define TB_BENCHMARK_MAIN() \
  int main(int argc, char** argv) { return tb::bench::runBenchmarks(argc, argv); }
