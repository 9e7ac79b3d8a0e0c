// `tessbench history` on default runs: `history add` of the committed baseline
// (results/baseline/results.json: the default suite, 418 records, 775,168 figures) into a
// fresh database and into one that holds it already (under another sha), and `history
// report` (lines, steps, history.html and history.md, in memory) over 50 default runs.
// Counters: db_bytes, the database file after the adds (WAL checkpointed on close), and
// bytes_per_run. The 50 runs are the baseline under 50 synthetic shas and commit times, so
// their figures are the same and each stored measure result is shared (the content-addressed
// payloads table): the first run costs the most, each further one its rows of keys only.
// Writes into a temporary folder, removed at the end.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "bench/bench_main.h"
#include "harness/history/history_render.h"
#include "harness/history/history_series.h"
#include "harness/history/history_store.h"
#include "tb_build_info.h"

namespace {

namespace fs = std::filesystem;

const std::string& baselineText() {
  static const std::string text = [] {
    std::ifstream in(std::string(TB_SOURCE_DIR) + "/results/baseline/results.json");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }();
  return text;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("tessbench_history_bench_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The baseline as run `index`: its own git sha, commit time and run id.
std::string baselineAt(const fs::path& root, int index) {
  std::string text = baselineText();
  const std::string key = "\"git_sha\": \"";
  const size_t at = text.find(key);
  const size_t end = text.find('"', at + key.size());
  char sha[41];
  std::snprintf(sha, sizeof sha, "%040x", 0xbe000 + index);
  text.replace(at, end + 2 - at,
               key + sha + "\",\n    \"commit_time\": \"2026-01-01T00:00:" +
                   (index < 10 ? "0" : "") + std::to_string(index) + "+00:00\",");
  const fs::path folder = root / ("run" + std::to_string(index));
  fs::create_directories(folder);
  std::ofstream(folder / "results.json") << text;
  return folder.string();
}

void historyAddDefaultRun(benchmark::State& state) {
  const fs::path dir = scratch("add");
  const std::string run = baselineAt(dir, 0), again = baselineAt(dir, 1);
  const bool repeat = state.range(0) == 1;
  double bytes = 0, bytes_before = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const std::string db = (dir / "h.sqlite").string();
    fs::remove(db);
    tb::history::HistoryDb history = tb::history::openHistory(db, true);
    if (repeat) tb::history::addRun(history, run);
    history.db.reset();
    bytes_before = double(fs::file_size(db));
    history = tb::history::openHistory(db, true);
    state.ResumeTiming();
    tb::history::addRun(history, repeat ? again : run);
    state.PauseTiming();
    history.db.reset();
    bytes = double(fs::file_size(db));
    state.ResumeTiming();
  }
  state.counters["db_bytes"] = bytes;
  state.counters["bytes_per_run"] = bytes - bytes_before;
  fs::remove_all(dir);
}

void historyReport50Runs(benchmark::State& state) {
  const fs::path dir = scratch("report");
  const std::string db = (dir / "h.sqlite").string();
  {
    tb::history::HistoryDb history = tb::history::openHistory(db, true);
    for (int i = 0; i < 50; ++i) {
      const std::string run = baselineAt(dir, i);
      tb::history::addRun(history, run);
      fs::remove_all(run);
    }
  }
  size_t html_bytes = 0, charts = 0;
  for (auto _ : state) {
    tb::history::HistoryDb history = tb::history::openHistory(db, false);
    const tb::history::HistoryView view = tb::history::buildHistory(history, {});
    const std::string html = tb::history::renderHistoryHtml(view, {"/* Chart.js */", ""});
    const std::string markdown = tb::history::renderHistoryMarkdown(view);
    html_bytes = html.size();
    charts = view.charts.size();
    benchmark::DoNotOptimize(markdown);
  }
  state.counters["runs"] = 50;
  state.counters["charts"] = double(charts);
  state.counters["html_bytes"] = double(html_bytes);
  state.counters["db_bytes"] = double(fs::file_size(db));
  fs::remove_all(dir);
}

// Arg 0: into a new database; 1: into one that holds the same figures under another sha.
BENCHMARK(historyAddDefaultRun)
    ->ArgName("repeat")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(3)
    ->Unit(benchmark::kSecond);
BENCHMARK(historyReport50Runs)->Iterations(3)->Unit(benchmark::kSecond);

}  // namespace

TB_BENCHMARK_MAIN()
