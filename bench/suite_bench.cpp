// The default suite's wall time (`tessbench run` with no narrowing: every technique,
// variant, bundled asset and measure), the figure the suite budget is kept by: at most
// 120 s on the 2-core reference machine, warm build. One iteration per thread count;
// counters give the records made and each measure's summed time (seconds, over every
// record; with 2 threads the sum exceeds the wall time). Nothing is written to disk.
#include <benchmark/benchmark.h>

#include <map>

#include "bench/bench_main.h"
#include "harness/suite/suite.h"

namespace {

void defaultSuite(benchmark::State& state) {
  tb::suite::SuiteSelection selection;
  selection.threads = int(state.range(0));
  for (auto _ : state) {
    tb::results::Results results;
    tb::suite::SuiteTimings timings;
    tb::suite::runSuite(selection, nullptr, &results, &timings);
    state.SetIterationTime(timings.wall_seconds);
    std::map<std::string, double> per_measure;
    for (const tb::suite::MeasureTiming& t : timings.measures) per_measure[t.measure] += t.seconds;
    for (const auto& [measure, seconds] : per_measure) state.counters[measure + "_s"] = seconds;
    state.counters["wall_s"] = timings.wall_seconds;
    state.counters["records"] = double(results.records.size());
    state.counters["threads"] = double(timings.threads);
  }
}

// 0 = every core (the default run); 1 shows what the parallel runner buys.
BENCHMARK(defaultSuite)
    ->ArgName("threads")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kSecond);

}  // namespace

TB_BENCHMARK_MAIN()
