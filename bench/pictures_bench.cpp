// The default suite's pictures (harness/pictures/run_pictures.h): every technique × bundled
// asset with an ok `error` result on its default variant, at level 8 and 320 px, rendered
// on the default device. Their budget inside the suite's 120 s: at most 10 s wall on the
// 2-core reference machine and ~6 MB of PNG (the report embeds them). The records come
// from a suite run of the `error` measure alone (untimed: the same records carry an error
// result in the full default run). Counters: picture pairs, PNG bytes, wall seconds.
// Nothing is written to disk.
#include <benchmark/benchmark.h>

#include <ctime>

#include "bench/bench_main.h"
#include "harness/measures/measure.h"
#include "harness/pictures/run_pictures.h"
#include "harness/suite/suite.h"

namespace {

void defaultSuitePictures(benchmark::State& state) {
  tb::suite::SuiteSelection selection;
  selection.measures = {tb::measures::MeasureRegistry::instance().find("error")};
  tb::results::Results results;
  tb::suite::runSuite(selection, nullptr, &results);
  for (auto _ : state) {
    uint64_t bytes = 0;
    const std::clock_t cpu_start = std::clock();
    const tb::pictures::PicturesIndex index = tb::pictures::renderRunPictures(
        results, "", [&](const std::string&, const std::string& file) { bytes += file.size(); });
    state.SetIterationTime(index.wall_s);
    state.counters["pairs"] = double(index.pictures.size());
    state.counters["png_bytes"] = double(index.png_bytes);
    state.counters["bytes_with_index"] = double(bytes);
    state.counters["wall_s"] = index.wall_s;
    // Processor seconds of every thread (lavapipe's included): what an idle 2-core machine
    // needs at least half of as wall time.
    state.counters["cpu_s"] = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    if (index.status != "ok") state.SkipWithError(index.reason.c_str());
  }
}

BENCHMARK(defaultSuitePictures)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);

}  // namespace

TB_BENCHMARK_MAIN()
