// Random tessellation level sets for the tessellator sweeps (tess_sweep_test.cpp against
// lavapipe, compute_tessellator_test.cpp against the CPU model), from a fixed seed.
#pragma once

#include <cstdint>
#include <limits>
#include <random>

#include "core/tess/tessellator.h"

namespace tb::gpu::testing {

// Levels uniform in [-1, 70), and one time in four a special value from the D3D11 rules:
// culling (0, NaN), the minimum (1), just above it, just above an odd integer (parity
// flips in fractional spacing), just below / at / above the 64 clamp.
class LevelGenerator {
 public:
  explicit LevelGenerator(uint32_t seed) : rng_(seed) {}

  tess::Levels next() {
    tess::Levels levels;
    for (float& l : levels.outer) l = level();
    for (float& l : levels.inner) l = level();
    return levels;
  }

 private:
  float level() {
    if (rng_() % 4 == 0) return special();
    // mt19937's output is fully specified, unlike std::uniform_real_distribution's.
    return -1.0f + 71.0f * static_cast<float>(rng_() >> 8) * 0x1p-24f;
  }
  float special() {
    switch (rng_() % 8) {
      case 0:
        return 0.0f;
      case 1:
        return 1.0f;
      case 2:
        return 1.0f + 0x1p-18f;
      case 3:
        return static_cast<float>(2 * (rng_() % 32) + 1) + 0x1p-17f;
      case 4:
        return 63.9f;
      case 5:
        return 64.0f;
      case 6:
        return 65.0f;
      default:
        return std::numeric_limits<float>::quiet_NaN();
    }
  }
  std::mt19937 rng_;
};

}  // namespace tb::gpu::testing
