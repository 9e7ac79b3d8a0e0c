#include "harness/cli/merge_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "core/mesh/input_error.h"
#include "harness/cli/html_assets.h"
#include "harness/report/csv_tables.h"
#include "harness/report/markdown.h"
#include "harness/results/merge.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"

namespace tb::cli {
namespace {

results::ShardRun readShard(const std::string& folder) {
  results::requireFinishedRunFolder(folder);
  const std::string path = folder + "/results.json";
  if (!std::filesystem::is_regular_file(path)) {
    throw std::runtime_error(folder + ": no results.json (not a tessbench run folder)");
  }
  return {folder, results::readResultsFile(path)};
}

std::string folderName(const std::string& path) {
  std::filesystem::path folder = std::filesystem::path(path).lexically_normal();
  if (folder.filename().empty()) folder = folder.parent_path();
  return folder.filename().string();
}

SubcommandRun addMerge(CLI::App& app) {
  auto args = std::make_shared<MergeArgs>();
  addMergeCommand(app, *args);
  return [args](const Invocation& invocation) { return runMerge(*args, invocation.command_line); };
}

}  // namespace

CLI::App* addMergeCommand(CLI::App& app, MergeArgs& args) {
  CLI::App* merge = app.add_subcommand(
      "merge", "join the run folders of shards 0..N-1 (run --shard I/N) into one new run folder");
  merge->add_option("shards", args.shards, "shard run folders (results/<run-id>), all N")
      ->required();
  merge->add_option("--out", args.out, "the merged run's folder (must not exist yet)")->required();
  merge->add_flag("--quiet", args.quiet, "print only the merged folder");
  return merge;
}

int runMerge(const MergeArgs& args, const std::string& command_line) {
  std::vector<results::ShardRun> shards;
  for (const std::string& folder : args.shards) shards.push_back(readShard(folder));
  results::Results merged = results::mergeShards(shards);
  // The check `run` makes on an unsharded run, which no single shard can make.
  if (merged.records.empty() && !merged.skipped.empty()) {
    const results::Skip& skip = merged.skipped.front();
    throw mesh::InputError(skip.asset, "", skip.reason + " (nothing to measure)");
  }
  // The folder is made only after the shards are known to fit, so a refused merge leaves
  // nothing behind; it is written as `<out>.incomplete` and renamed when complete.
  results::PendingRunFolder folder = results::PendingRunFolder::at(args.out);
  merged.context.date = results::utcTimestampIso8601();
  merged.context.run_id = folderName(args.out);
  merged.context.command_line = command_line;
  folder.writeFile("report.md", report::renderMarkdown(merged));
  for (const auto& [name, text] : report::renderCsvTables(merged)) folder.writeFile(name, text);
  // The charts of the merged run; the shards' pictures stay in their own folders.
  folder.writeFile("report.html", renderRunHtml(merged, folder.pendingPath()));
  folder.writeFile("results.json", results::serializeResults(merged));
  folder.finish();
  if (!args.quiet) {
    fmt::print(
        "{} records, {} skipped from {} shards: merged run written to {}/ "
        "(results.json, report.md, report.html)\n",
        merged.records.size(), merged.skipped.size(), shards.size(), args.out);
  } else {
    fmt::print("{}\n", args.out);
  }
  return 0;
}

const Subcommand kMergeSubcommand{"merge", addMerge};

}  // namespace tb::cli
