// The core's double fused multiply-add peak, measured: independent FMA chains in the
// widest registers this CPU has (AVX-512, else AVX2, else SSE2 multiply + add), enough of
// them to hide the FMA latency. The denominator of the evaluation benchmark's
// fma_peak_fraction.
#pragma once

#include <cstdint>

namespace tb::bench {

// Runs `iterations` rounds of the peak loop; returns the multiply-adds done.
int64_t runFmaPeakLoop(int64_t iterations);

// Multiply-adds per second of one core (per second of thread CPU time): the best of
// several short runs of the loop (~0.1 s in all, on the first call; later calls return
// the same figure).
double fmaPeakPerSecond();

// "avx512", "avx2_fma" or "sse2": the registers the loop uses.
const char* fmaPeakKernel();

// CPU time of the calling thread in seconds: what Google Benchmark's rates divide by.
double threadCpuSeconds();

}  // namespace tb::bench
