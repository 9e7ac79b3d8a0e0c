#include "bench/fma_peak.h"

#include <immintrin.h>

#include <algorithm>
#include <ctime>

#include "techniques/common/basis_table.h"

namespace tb::bench {
namespace {

// 12 chains: FMA latency 4 cycles x 2 pipes = 8 in flight needed, with room to spare.
constexpr int kChains = 12;

__attribute__((target("avx512f"))) int64_t loopAvx512(int64_t iterations) {
  __m512d acc[kChains];
  for (int i = 0; i < kChains; ++i) acc[i] = _mm512_set1_pd(1.0 + i);
  const __m512d a = _mm512_set1_pd(0.999999), b = _mm512_set1_pd(1e-9);
  for (int64_t it = 0; it < iterations; ++it) {
    for (int i = 0; i < kChains; ++i) acc[i] = _mm512_fmadd_pd(acc[i], a, b);
  }
  __m512d sum = acc[0];
  for (int i = 1; i < kChains; ++i) sum = _mm512_add_pd(sum, acc[i]);
  alignas(64) double lanes[8];
  _mm512_store_pd(lanes, sum);
  volatile double sink = lanes[0] + lanes[7];
  (void)sink;
  return iterations * kChains * 8;
}

__attribute__((target("avx2,fma"))) int64_t loopAvx2(int64_t iterations) {
  __m256d acc[kChains];
  for (int i = 0; i < kChains; ++i) acc[i] = _mm256_set1_pd(1.0 + i);
  const __m256d a = _mm256_set1_pd(0.999999), b = _mm256_set1_pd(1e-9);
  for (int64_t it = 0; it < iterations; ++it) {
    for (int i = 0; i < kChains; ++i) acc[i] = _mm256_fmadd_pd(acc[i], a, b);
  }
  __m256d sum = acc[0];
  for (int i = 1; i < kChains; ++i) sum = _mm256_add_pd(sum, acc[i]);
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, sum);
  volatile double sink = lanes[0] + lanes[1] + lanes[2] + lanes[3];
  (void)sink;
  return iterations * kChains * 4;
}

int64_t loopSse2(int64_t iterations) {
  __m128d acc[kChains];
  for (int i = 0; i < kChains; ++i) acc[i] = _mm_set1_pd(1.0 + i);
  const __m128d a = _mm_set1_pd(0.999999), b = _mm_set1_pd(1e-9);
  for (int64_t it = 0; it < iterations; ++it) {
    for (int i = 0; i < kChains; ++i) acc[i] = _mm_add_pd(_mm_mul_pd(acc[i], a), b);
  }
  __m128d sum = acc[0];
  for (int i = 1; i < kChains; ++i) sum = _mm_add_pd(sum, acc[i]);
  alignas(16) double lanes[2];
  _mm_store_pd(lanes, sum);
  volatile double sink = lanes[0] + lanes[1];
  (void)sink;
  return iterations * kChains * 2;
}

}  // namespace

int64_t runFmaPeakLoop(int64_t iterations) {
  switch (techniques::fastestBatchKernel()) {
    case techniques::BatchKernel::kAvx512:
      return loopAvx512(iterations);
    case techniques::BatchKernel::kAvx2Fma:
      return loopAvx2(iterations);
    case techniques::BatchKernel::kPortable:
      break;
  }
  return loopSse2(iterations);
}

const char* fmaPeakKernel() {
  return techniques::fastestBatchKernel() == techniques::BatchKernel::kPortable
             ? "sse2"
             : toString(techniques::fastestBatchKernel());
}

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double fmaPeakPerSecond() {
  static const double kPeak = [] {
    double best = 0;
    // Thread CPU time, as Google Benchmark's rates use: on a shared machine the wall
    // clock also counts other processes' turns.
    for (int run = 0; run < 10; ++run) {
      const double start = threadCpuSeconds();
      const int64_t fmas = runFmaPeakLoop(2'000'000);
      best = std::max(best, double(fmas) / (threadCpuSeconds() - start));
    }
    return best;
  }();
  return kPeak;
}

}  // namespace tb::bench
