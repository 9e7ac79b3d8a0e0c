#include "core/tess/tessellator.h"

namespace tb::tess {

uint64_t quadPointCount(uint32_t n) { return uint64_t(n + 1) * (n + 1); }

uint64_t quadTriangleCount(uint32_t n) { return 2ull * n * n; }

// The triangle domain is tessellated in concentric rings of 3(n - 2k) points; an
// odd level ends in a 3-point ring, an even one in the centre point.
uint64_t trianglePointCount(uint32_t n) {
  if (n % 2 == 1) {
    const uint64_t half = (n + 1) / 2;
    return 3 * half * half;
  }
  const uint64_t half = n / 2;
  return 3 * half * (half + 1) + 1;
}

uint64_t triangleTriangleCount(uint32_t n) { return (3ull * n * n) / 2; }

}  // namespace tb::tess
