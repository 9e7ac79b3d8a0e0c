#include "harness/cli/report_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <stdexcept>

#include "harness/cli/format_option.h"
#include "harness/cli/html_assets.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/complete_declarations.h"
#include "harness/report/markdown.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"

namespace tb::cli {

CLI::App* addReportCommand(CLI::App& app, ReportArgs& args) {
  CLI::App* report = app.add_subcommand("report", "render a run's results.json to stdout");
  report->add_option("run_dir", args.run_dir, "results/<run-id>")->required();
  report
      ->add_option("--format", args.format,
                   "markdown | html (one self-contained page of charts and pictures)")
      ->transform(markdownAlias())
      ->capture_default_str();
  return report;
}

int runReport(const ReportArgs& args) {
  results::requireFinishedRunFolder(args.run_dir);
  results::Results results = results::readResultsFile(args.run_dir + "/results.json");
  measures::completeDeclarations(&results);
  if (args.format == "markdown") {
    fmt::print("{}", report::renderMarkdown(results));
  } else if (args.format == "html") {
    const report::HtmlAssets assets = loadHtmlAssets(args.run_dir);
    if (assets.chartjs_source.empty()) throw std::runtime_error(assets.chartjs_missing_reason);
    fmt::print("{}", report::renderHtml(results, assets));
  } else {
    throw UsageError("--format", args.format, "unknown report format (known: markdown, html)");
  }
  return 0;
}

namespace {

SubcommandRun addReport(CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  addReportCommand(app, *args);
  return [args](const Invocation&) { return runReport(*args); };
}

}  // namespace

const Subcommand kReportSubcommand{"report", addReport};

}  // namespace tb::cli
