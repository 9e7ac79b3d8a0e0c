#include "harness/cli/table_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>

#include "core/mesh/input_error.h"
#include "harness/cli/format_option.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/complete_declarations.h"
#include "harness/report/summary.h"
#include "harness/report/table.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"

namespace tb::cli {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

bool ran(const results::Results& results, const std::string& measure) {
  return std::any_of(results.records.begin(), results.records.end(), [&](const results::Record& r) {
    return std::any_of(r.measures.begin(), r.measures.end(),
                       [&](const results::MeasureResult& m) { return m.measure == measure; });
  });
}

}  // namespace

CLI::App* addTableCommand(CLI::App& app, TableArgs& args) {
  CLI::App* table = app.add_subcommand(
      "table",
      "render a measure's summary (median and worst per technique x variant) or the published "
      "figures beside ours (--published) as Markdown, CSV or LaTeX (booktabs), with the run's "
      "context as a footnote");
  table->add_option("run_dir", args.run_dir, "results/<run-id>")->required();
  table->add_option("--measure", args.measure, "measure id (required unless --published)");
  table->add_option("--metric", args.metrics,
                    "metric name (repeatable; default: the measure's headline metrics)");
  table
      ->add_option("--format", args.format,
                   "markdown | csv (footnote as leading '# ' lines) | latex (booktabs fragment)")
      ->transform(markdownAlias())
      ->capture_default_str();
  table->add_flag("--per-asset", args.per_asset, "a line per technique x variant x asset");
  table->add_flag("--comparisons", args.comparisons,
                  "the measure's side-by-side tables (one column per policy, family ...), as "
                  "report.md opens its section");
  table->add_flag(
      "--published", args.published,
      "the published tables beside ours: memory (NVIDIA's displacement subdivision "
      "surfaces talk) and published_figures (its Bezier instruction counts, the DirectX "
      "SDK SubD10 sample's ACC costs); with --measure, that one only");
  return table;
}

int runTable(const TableArgs& args) {
  const std::optional<report::TableFormat> format = report::parseTableFormat(args.format);
  if (!format) {
    throw UsageError("--format", args.format, "unknown table format (known: markdown, csv, latex)");
  }
  if (args.measure.empty() && !args.published) {
    throw UsageError("--measure", "", "a measure is required (or --published)");
  }
  results::requireFinishedRunFolder(args.run_dir);
  results::Results results = results::readResultsFile(args.run_dir + "/results.json");
  measures::completeDeclarations(&results);
  const std::vector<std::string> ids = report::measureIds(results);
  if (!args.measure.empty() && std::find(ids.begin(), ids.end(), args.measure) == ids.end()) {
    throw mesh::InputError(args.run_dir + "/results.json", "--measure " + args.measure,
                           "the run has no such measure (measures: " + joined(ids) + ")");
  }

  if (args.published) {
    std::vector<std::string> measures;
    if (!args.measure.empty()) {
      if (!report::hasPublishedTable(results, args.measure)) {
        throw UsageError("--measure", args.measure,
                         "no published table for this measure (known: memory, published_figures)");
      }
      measures.push_back(args.measure);
    } else {
      for (const char* id : {"memory", "published_figures"}) {
        if (ran(results, id)) measures.push_back(id);
      }
      if (measures.empty()) {
        throw mesh::InputError(args.run_dir + "/results.json", "--published",
                               "the run has neither memory nor published_figures results");
      }
    }
    for (size_t i = 0; i < measures.size(); ++i) {
      fmt::print("{}{}", i > 0 ? "\n" : "",
                 report::renderTable(report::publishedTable(results, measures[i]), *format));
    }
    return 0;
  }

  const results::MeasureDeclaration* declaration = results.findMeasure(args.measure);
  for (const std::string& metric : args.metrics) {
    if (declaration != nullptr && declaration->find(metric) == nullptr) {
      std::vector<std::string> known;
      for (const results::MetricSpec& spec : declaration->metrics) known.push_back(spec.name);
      throw UsageError("--metric", metric,
                       "not a metric of " + args.measure + " (metrics: " + joined(known) + ")");
    }
  }
  if (args.comparisons) {
    const std::vector<report::TextTable> tables = report::comparisonTables(results, *declaration);
    if (tables.empty()) {
      throw mesh::InputError(args.run_dir + "/results.json", "--comparisons",
                             args.measure + " declares no comparison the run has rows for");
    }
    for (size_t i = 0; i < tables.size(); ++i) {
      fmt::print("{}{}", i > 0 ? "\n" : "", report::renderTable(tables[i], *format));
    }
    return 0;
  }
  report::SummaryTableOptions options;
  options.measure = args.measure;
  options.metrics = args.metrics;
  options.per_asset = args.per_asset;
  fmt::print("{}", report::renderTable(report::summaryTable(results, options), *format));
  return 0;
}

namespace {

SubcommandRun addTable(CLI::App& app) {
  auto args = std::make_shared<TableArgs>();
  addTableCommand(app, *args);
  return [args](const Invocation&) { return runTable(*args); };
}

}  // namespace

const Subcommand kTableSubcommand{"table", addTable};

}  // namespace tb::cli
