#include "harness/cli/history_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cassert>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "harness/cli/html_assets.h"
#include "harness/cli/usage_error.h"
#include "harness/history/history_render.h"
#include "harness/history/history_series.h"
#include "harness/history/history_store.h"

namespace tb::cli {
namespace {

namespace fs = std::filesystem;

int runAdd(const HistoryArgs& args) {
  history::HistoryDb db = history::openHistory(args.db, /*writable=*/true);
  for (const std::string& dir : args.run_dirs) {
    const history::AddSummary added = history::addRun(db, dir);
    fmt::print(
        "added {} (git {}, {}, suite {}): {} records, {} measure results ({} new), {} "
        "timings\n",
        added.run.run_id, added.run.git_sha.substr(0, 12), added.run.device, added.run.suite,
        added.records, added.measure_results, added.new_payloads, added.timings);
  }
  return 0;
}

int runList(const HistoryArgs& args) {
  history::HistoryDb db = history::openHistory(args.db, /*writable=*/false);
  const std::vector<history::RunInfo> runs = history::listRuns(db);
  if (args.json) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const history::RunInfo& r : runs) {
      list.push_back({{"git_sha", r.git_sha},
                      {"commit_time", r.commit_time},
                      {"date", r.date},
                      {"run_id", r.run_id},
                      {"device", r.device},
                      {"suite", r.suite},
                      {"folder", r.folder}});
    }
    fmt::print("{}\n", list.dump(1));
    return 0;
  }
  fmt::print(
      "| git sha | commit time | run date | run | device | suite |\n"
      "|---|---|---|---|---|---|\n");
  for (const history::RunInfo& r : runs) {
    fmt::print("| {} | {} | {} | {} | {} | {} |\n", r.git_sha.substr(0, 12),
               r.commit_time.empty() ? "-" : r.commit_time, r.date, r.run_id, r.device, r.suite);
  }
  fmt::print("\n{} runs in {}\n", runs.size(), args.db);
  return 0;
}

history::ChartScript readChartJs() {
  const std::string path = chartJsPath();
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  if (in) bytes << in.rdbuf();
  if (!in || bytes.str().empty()) {
    return {"", path +
                    ": cannot read Chart.js (Debian package libjs-chart.js; "
                    "TESSBENCH_CHARTJS=PATH names another file)"};
  }
  return {bytes.str(), ""};
}

// Writes `path` whole or not at all (a temporary file renamed over it).
void replaceFile(const fs::path& path, const std::string& contents) {
  const fs::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << contents;
    if (!out.flush()) throw std::runtime_error(temporary.string() + ": cannot write");
  }
  fs::rename(temporary, path);
}

int runReport(const HistoryArgs& args, const results::CompareOptions& compare) {
  history::ReportOptions options;
  options.assets = args.assets;
  if (args.aggregate != "median" && args.aggregate != "worst")
    throw UsageError("--aggregate", args.aggregate, "expected median or worst");
  options.aggregate =
      args.aggregate == "median" ? history::Aggregate::kMedian : history::Aggregate::kWorst;
  options.compare = compare;
  history::HistoryDb db = history::openHistory(args.db, /*writable=*/false);
  const history::HistoryView view = history::buildHistory(db, options);
  const history::ChartScript chartjs = readChartJs();
  if (chartjs.source.empty())
    fmt::print(stderr, "tessbench: warning: {}; history.html has no charts\n",
               chartjs.missing_reason);
  std::error_code error;
  fs::create_directories(args.out, error);
  if (!fs::is_directory(args.out))
    throw std::runtime_error(args.out + ": cannot create the report folder");
  replaceFile(fs::path(args.out) / "history.html", history::renderHistoryHtml(view, chartjs));
  replaceFile(fs::path(args.out) / "history.md", history::renderHistoryMarkdown(view));
  fmt::print("wrote {0}/history.html and {0}/history.md: {1} charts, {2} steps flagged\n", args.out,
             view.charts.size(), view.steps.size());
  return 0;
}

// The one run a sha names; throws naming the sha when none or several do.
history::RunInfo runBySha(history::HistoryDb& db, const std::string& sha) {
  const std::vector<history::RunInfo> found = history::findRuns(db, sha);
  if (found.empty())
    throw history::HistoryError(sha + ": no run of this git sha in " + db.db->path());
  if (found.size() > 1) {
    std::string ids;
    for (const history::RunInfo& r : found)
      ids += (ids.empty() ? "" : ", ") + r.run_id + " (" + r.device + ")";
    throw history::HistoryError(sha + ": " + std::to_string(found.size()) +
                                " runs have this sha, give a longer one: " + ids);
  }
  return found.front();
}

int runHistoryCompare(const HistoryArgs& args) {
  history::HistoryDb db = history::openHistory(args.db, /*writable=*/false);
  const history::RunInfo a = runBySha(db, args.sha_a);
  const history::RunInfo b = runBySha(db, args.sha_b);
  if (a.device != b.device) {
    throw history::HistoryError(fmt::format(
        "{} and {}: runs of different devices ('{}', '{}'); figures of two devices are not "
        "compared",
        args.sha_a, args.sha_b, a.device, b.device));
  }
  return printComparison(history::runLabel(a) + " (" + a.run_id + ")",
                         history::runLabel(b) + " (" + b.run_id + ")", history::loadRun(db, a.id),
                         history::loadRun(db, b.id), args.compare);
}

SubcommandRun addHistory(CLI::App& app) {
  auto args = std::make_shared<HistoryArgs>();
  CLI::App* history = app.add_subcommand(
      "history",
      "the results database across commits: add runs, list them, report every "
      "headline figure over commits with the steps flagged, compare two commits");
  history->require_subcommand(1);
  history->add_option("--db", args->db, "the history database (SQLite)")->capture_default_str();
  CLI::App* add = history->add_subcommand("add", "ingest finished run folders");
  add->add_option("run", args->run_dirs, "finished run folders (merged shard runs too)")
      ->required();
  CLI::App* list = history->add_subcommand("list", "the runs: sha, dates, run id, device, suite");
  list->add_flag("--json", args->json, "print the runs as JSON");
  CLI::App* report = history->add_subcommand(
      "report",
      "write history.html (a chart per headline figure over commits) and history.md "
      "(the flagged steps, worst first) into --out");
  report->add_option("--out", args->out, "the report's folder")->required();
  report->add_option("--asset", args->assets,
                     "a line per technique/variant and this asset "
                     "(repeatable); default: one line over every asset");
  report->add_option("--aggregate", args->aggregate, "median | worst: how a line joins its assets")
      ->capture_default_str();
  CLI::App* compare = history->add_subcommand(
      "compare", "compare's output for the two runs of two git shas (same device only)");
  compare->add_option("sha_a", args->sha_a, "the base run's git sha (4+ characters)")->required();
  compare->add_option("sha_b", args->sha_b, "the new run's git sha")->required();
  addCompareOptions(compare, args->compare);
  for (CLI::App* command : {add, list, report})
    command->add_option("--db", args->db, "the history database");
  compare->add_option("--db", args->db, "the history database");
  report->add_option("--threshold", args->compare.threshold,
                     "relative change of a figure that is a step");
  report->add_option("--metric-threshold", args->compare.metric_thresholds, "NAME=VALUE");
  report->add_option("--alpha", args->compare.alpha, "timings: the U test's significance level");
  report->add_option("--time-threshold", args->compare.time_threshold,
                     "timings: relative change of the median that is a step");
  return [args, add, list, report](const Invocation&) {
    if (*add) return runAdd(*args);
    if (*list) return runList(*args);
    if (*report) return runReport(*args, compareOptions(args->compare));
    return runHistoryCompare(*args);
  };
}

}  // namespace

const Subcommand kHistorySubcommand{"history", addHistory};

}  // namespace tb::cli
