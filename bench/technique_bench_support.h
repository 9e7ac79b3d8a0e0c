// Shared by the per-technique benchmark suites: the default variant's patches of a
// bundled asset, and a main() that registers the cases at run time (from the technique
// registry, after every static registration has run).
#pragma once

#include <benchmark/benchmark.h>

#include <exception>
#include <memory>
#include <string>

#include "bench/bench_main.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/technique.h"

namespace tb::bench {

// Null, with the benchmark skipped and the technique's reason shown, when the technique
// does not take the asset.
inline techniques::BuiltSurface defaultVariantPatches(benchmark::State& state,
                                                      const techniques::Technique& technique,
                                                      const std::string& asset) {
  try {
    const mesh::Mesh mesh = suite::loadAsset(suite::resolveAsset(asset));
    return techniques::buildSurface(technique, mesh, technique.variants()[0]);
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
    return nullptr;
  }
}

inline int runAfterRegistering(int argc, char** argv, void (*register_benchmarks)()) {
  register_benchmarks();
  return runBenchmarks(argc, argv);
}

}  // namespace tb::bench
