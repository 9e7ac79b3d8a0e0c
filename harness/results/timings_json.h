// timings.json, beside results.json in a run folder: wall seconds per record × measure.
// Timings change run to run, so they never enter results.json (which is byte-stable);
// `tessbench compare` tests them apart, with repeated samples (compare.h, mann_whitney.h).
//
//   {"wall_seconds": 91.2, "threads": 2, "repetitions": 5,
//    "device": "llvmpipe (LLVM 15.0.6, 256 bits) (Mesa 22.3.6 (LLVM 15.0.6), Vulkan 1.3.230)",
//    "measures": [{"technique": "acc", "variant": "default", "asset": "...",
//                  "measure": "error", "seconds": 0.41, "samples": [0.41, 0.39, ...]}]}
// `seconds` is the first sample; a file without `samples` reads as one sample per entry.
#pragma once

#include <string>
#include <vector>

namespace tb::results {

struct TimingEntry {
  std::string technique, variant, asset, measure;
  std::vector<double> samples;  // wall seconds of each repetition, in run order; never empty
};

struct RunTimings {
  double wall_seconds = 0;  // the whole suite, assets loading included
  int threads = 0;          // worker threads the run had
  int repetitions = 1;      // runs of each measure (`run --repetitions`)
  // The Vulkan device and driver the run measured on, as results.json's context names it
  // (gpu::describeDevice); empty in a file written before devices were recorded.
  std::string device;
  std::vector<TimingEntry> measures;  // in record order
};

std::string serializeTimings(const RunTimings& timings);  // 1-space indent, final newline
// Throws std::runtime_error naming the file and the field when it cannot be read.
RunTimings readTimingsFile(const std::string& path);

}  // namespace tb::results
