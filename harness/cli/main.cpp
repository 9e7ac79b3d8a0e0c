// tessbench: benchmark and validation harness for real-time GPU surface techniques.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <exception>

#include "harness/cli/advise_command.h"
#include "harness/cli/bake_command.h"
#include "harness/cli/commands.h"
#include "harness/cli/compare_command.h"
#include "harness/cli/merge_command.h"
#include "harness/cli/table_command.h"
#include "harness/cli/tessellate_run.h"
#include "techniques/registry.h"
#include "tb_build_info.h"

int main(int argc, char** argv) {
  CLI::App app{"tessbench: benchmark and validation harness for GPU surface techniques"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tessbench ") + TB_VERSION + " (git " +
                                        TB_GIT_SHA + "), plug-in ABI " +
                                        std::to_string(kTessbenchPluginAbi));
  std::vector<std::string> plugins;
  app.add_option("--plugin", plugins, "load techniques from a shared library (repeatable)");

  tb::cli::ListArgs list_args;
  CLI::App* list = app.add_subcommand("list", "list techniques, assets, scenarios or measures");
  list->add_option("what", list_args.what, "techniques | assets | scenarios | measures")
      ->required()
      ->check(CLI::IsMember({"techniques", "assets", "scenarios", "measures"}));
  list->add_flag("--json", list_args.json, "print JSON");

  tb::cli::RunArgs run_args;
  CLI::App* run = app.add_subcommand("run", "measure techniques on assets into a new results folder");
  run->add_option("--technique", run_args.techniques, "technique id (repeatable; default all)");
  run->add_option("--asset", run_args.assets, "bundled asset name or OBJ path (default all)");
  run->add_option("--scenario", run_args.scenarios,
                  "bundled scenario name or scenario .json path, for simulation techniques "
                  "(repeatable; default all)");
  run->add_option("--measure", run_args.measures, "measure id (repeatable; default all)");
  run->add_option("--out", run_args.out, "results root; each run gets a new folder in it")
      ->capture_default_str();
  run->add_option("--run-id", run_args.run_id, "folder name (must not exist yet)");
  run->add_flag("--quiet", run_args.quiet, "no progress output");
  run->add_option("--device", run_args.device, "Vulkan device name substring (default: best)");
  run->add_option("--threads", run_args.threads,
                  "worker threads (default 0: every core); results do not depend on it")
      ->check(CLI::Range(0, 4096));
  run->add_option("--shard", run_args.shard,
                  "I/N: run only shard I of N (numbered from 0) of the technique x variant x "
                  "asset x measure work list; join the N run folders with `merge`");
  run->add_option("--suite", run_args.suite,
                  "default | full: the measures' default grid (within the time budget) or "
                  "every level, camera path and policy they know")
      ->capture_default_str();
  run->add_option("--camera", run_args.cameras,
                  "camera path: a bundled name (orbit, dolly, flyby) or a .json file "
                  "(repeatable; default: the suite's paths)");
  run->add_option("--repetitions", run_args.repetitions,
                  "run each measure of each record N times: results.json from the first "
                  "(a record warns when a repeat differs), every sample in timings.json, "
                  "for compare's U test (9 or more recommended)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  run->add_flag_callback("--no-pictures", [&run_args] { run_args.pictures = false; },
                         "do not render the pictures of each surface (pictures/ in the run folder)");

  tb::cli::MergeArgs merge_args;
  CLI::App* merge = app.add_subcommand(
      "merge", "join the run folders of shards 0..N-1 (run --shard I/N) into one new run folder");
  merge->add_option("shards", merge_args.shards, "shard run folders (results/<run-id>), all N")
      ->required();
  merge->add_option("--out", merge_args.out, "the merged run's folder (must not exist yet)")
      ->required();
  merge->add_flag("--quiet", merge_args.quiet, "print only the merged folder");

  tb::cli::ReportArgs report_args;
  CLI::App* report = app.add_subcommand("report", "render a run's results.json to stdout");
  report->add_option("run_dir", report_args.run_dir, "results/<run-id>")->required();
  report->add_option("--format", report_args.format,
                     "md | html (one self-contained page of charts and pictures)")
      ->capture_default_str();

  tb::cli::CompareArgs compare_args;
  CLI::App* compare = app.add_subcommand(
      "compare",
      "compare two finished runs metric by metric by each metric's direction; exit 1 when the "
      "new run lost (skipped, failed, absent) or worsened a figure of the base");
  compare->add_option("base", compare_args.base, "the base run folder (results/<run-id>)")
      ->required();
  compare->add_option("new", compare_args.current, "the new run folder")->required();
  compare->add_option("--threshold", compare_args.threshold,
                      "relative change that counts: |new - base| > t * max(|base|, |new|); 0 = exact")
      ->capture_default_str();
  compare->add_option("--metric-threshold", compare_args.metric_thresholds,
                      "NAME=VALUE: the threshold for one metric name (repeatable)");
  compare->add_option("--limit", compare_args.limit, "changes listed in the table, worst first")
      ->capture_default_str();
  compare->add_option("--alpha", compare_args.alpha,
                      "timings: significance level of the two-sided Mann-Whitney U test on "
                      "the repeated samples of timings.json (run --repetitions >= 2)")
      ->capture_default_str();
  compare->add_option("--time-threshold", compare_args.time_threshold,
                      "timings: relative change of the median that counts, with p < alpha")
      ->capture_default_str();
  compare->add_flag("--no-timings", compare_args.no_timings,
                    "compare results.json only, not timings.json");

  tb::cli::TessellateArgs tessellate_args;
  tb::cli::addTessellateCommand(app, tessellate_args);
  CLI::App* tessellate = app.get_subcommand("tessellate");

  tb::cli::AdviseArgs advise_args;
  CLI::App* advise = tb::cli::addAdviseCommand(app, advise_args);
  tb::cli::TableArgs table_args;
  CLI::App* table = tb::cli::addTableCommand(app, table_args);
  tb::cli::BakeArgs bake_args;
  CLI::App* bake = tb::cli::addBakeCommand(app, bake_args);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help prints the usage and exits 0; any other parse error is bad input: one line
    // naming the option, exit 2, like every other bad input.
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);
    std::string what = error.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    fmt::print(stderr, "tessbench: error: {} (see --help)\n", what);
    return 2;
  }

  std::string command_line = "tessbench";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  try {
    for (const std::string& plugin : plugins) tb::loadPlugin(plugin);
    if (*list) return tb::cli::runList(list_args);
    if (*run) return tb::cli::runRun(run_args, command_line);
    if (*report) return tb::cli::runReport(report_args);
    if (*merge) return tb::cli::runMerge(merge_args, command_line);
    if (*compare) return tb::cli::runCompare(compare_args);
    if (*tessellate) return tb::cli::runTessellate(tessellate_args);
    if (*advise) return tb::cli::runAdvise(advise_args);
    if (*table) return tb::cli::runTable(table_args);
    if (*bake) return tb::cli::runBake(bake_args);
  } catch (const std::exception& error) {
    std::fflush(stdout);
    fmt::print(stderr, "tessbench: error: {}\n", error.what());
    return 2;
  }
  return 0;
}
