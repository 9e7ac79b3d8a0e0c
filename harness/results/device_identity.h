// A figure's device is part of its identity: results.json's context.vulkan_device names the
// Vulkan device and its driver ("NAME (DRIVER_INFO, Vulkan X.Y.Z)", gpu::describeDevice), and
// figures measured on two different ones are never joined (compare, history, table).
// A run without a device ("none: REASON", or empty in old files) measured no GPU figure; it
// may be compared with any run: its GPU rows are skipped, so they read as missing.
#pragma once

#include <optional>
#include <string>

#include "harness/results/results_model.h"

namespace tb::results {

// True when the run opened a Vulkan device (its GPU figures exist).
bool measuredOnDevice(const RunContext& context);

// Why figures of these two runs may not be joined ("base measured on 'A', new on 'B'"), or
// nothing when they may: the same device, or at most one of them had a device.
std::optional<std::string> deviceMismatch(const RunContext& base, const RunContext& current);

// What a reader must know beside the timings of this device, or empty: a data-centre GPU
// (NVIDIA H100, H200, A100, B200, ...) exposes few graphics-capable units (an H100: two TPCs),
// so its tessellation timings are a lower bound, not a gaming GPU's.
std::string deviceCaveat(const std::string& vulkan_device);

}  // namespace tb::results
