#include "harness/cli/commands.h"

#include <fmt/format.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "harness/cli/progress_estimate.h"
#include "harness/cli/html_assets.h"
#include "harness/cli/run_context.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/scenario_file.h"
#include "harness/suite/camera_path.h"
#include "harness/measures/measure.h"
#include "harness/suite/suite.h"
#include "harness/pictures/run_pictures.h"
#include "core/mesh/input_error.h"
#include "harness/report/csv_tables.h"
#include "harness/report/markdown.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "harness/results/timings_json.h"
#include "techniques/registry.h"

namespace tb::cli {
namespace {

std::string knownIds(const std::vector<std::string>& ids) {
  std::string text;
  for (const auto& id : ids) text += (text.empty() ? "" : ", ") + id;
  return text;
}

std::vector<const Technique*> selectTechniques(const std::vector<std::string>& ids) {
  std::vector<const Technique*> selected;
  std::vector<std::string> known;
  for (const Technique* t : TechniqueRegistry::instance().all()) known.push_back(t->info().id);
  for (const std::string& id : ids) {
    const Technique* technique = TechniqueRegistry::instance().find(id);
    if (technique == nullptr) {
      throw InputError("--technique", id, "unknown technique (known: " + knownIds(known) + ")");
    }
    selected.push_back(technique);
  }
  return selected;
}

std::vector<const Measure*> selectMeasures(const std::vector<std::string>& ids) {
  std::vector<const Measure*> selected;
  std::vector<std::string> known;
  for (const Measure* m : MeasureRegistry::instance().all()) known.push_back(m->info().id);
  for (const std::string& id : ids) {
    const Measure* measure = MeasureRegistry::instance().find(id);
    if (measure == nullptr) {
      throw InputError("--measure", id, "unknown measure (known: " + knownIds(known) + ")");
    }
    selected.push_back(measure);
  }
  return selected;
}

SuiteMode parseSuiteMode(const std::string& text) {
  if (text == toString(SuiteMode::kDefault)) return SuiteMode::kDefault;
  if (text == toString(SuiteMode::kFull)) return SuiteMode::kFull;
  throw InputError("--suite", text, "unknown suite (known: default, full)");
}

// Reads every --camera file before any work, so a bad one stops the run with nothing
// written; `shown` gets the files as results name them.
std::vector<CameraPathFn> selectCameraPaths(const std::vector<std::string>& names_or_paths,
                                            std::vector<std::string>* shown) {
  std::vector<CameraPathFn> paths;
  for (const std::string& name_or_path : names_or_paths) {
    CameraPathSpec spec = resolveCameraPath(name_or_path);
    shown->push_back(spec.shown_path);
    paths.push_back(cameraPathFn(std::move(spec)));
  }
  return paths;
}

// Wall seconds per record × measure, every repetition's, beside results.json: timings
// change run to run, the results must not (harness/results/timings_json.h).
std::string timingsJson(const SuiteTimings& timings) {
  RunTimings run{timings.wall_seconds, timings.threads, timings.repetitions, {}};
  for (const MeasureTiming& t : timings.measures) {
    run.measures.push_back({t.technique, t.variant, t.asset, t.measure,
                            t.samples.empty() ? std::vector<double>{t.seconds} : t.samples});
  }
  return serializeTimings(run);
}

// Suite wall time and each measure's summed time, the figures the suite budget is kept by.
void printTimingSummary(const SuiteTimings& timings) {
  std::map<std::string, double> per_measure;
  for (const MeasureTiming& t : timings.measures) per_measure[t.measure] += t.seconds;
  std::string parts;
  for (const auto& [measure, seconds] : per_measure) {
    parts += fmt::format("{}{} {:.1f} s", parts.empty() ? "" : ", ", measure, seconds);
  }
  fmt::print(stderr, "suite: {:.1f} s wall on {} threads; measure time: {}\n",
             timings.wall_seconds, timings.threads, parts);
}

}  // namespace

int runList(const ListArgs& args) {
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  if (args.what == "techniques") {
    for (const Technique* t : TechniqueRegistry::instance().all()) {
      const TechniqueInfo& info = t->info();
      nlohmann::ordered_json variants = nlohmann::ordered_json::array();
      for (const VariantInfo& v : t->variants()) variants.push_back(v.name);
      items.push_back({{"id", info.id},
                       {"family", toString(info.family)},
                       {"title", info.title},
                       {"citation", info.citation},
                       {"input", info.input},
                       {"variants", variants}});
      if (!args.json) fmt::print("{:<16} {:<10} {} — {}\n", info.id, toString(info.family), info.title, info.citation);
    }
  } else if (args.what == "assets") {
    for (const AssetRef& asset : bundledAssets()) {
      items.push_back({{"name", asset.name}, {"path", asset.path}});
      if (!args.json) fmt::print("{:<40} {}\n", asset.name, asset.path);
    }
  } else if (args.what == "scenarios") {
    for (const Scenario& scenario : bundledScenarios()) {
      items.push_back({{"name", scenario.name},
                       {"technique", scenario.technique},
                       {"path", scenario.path},
                       {"time_step_s", scenario.time_step_s},
                       {"duration_s", scenario.duration_s}});
      if (!args.json) fmt::print("{:<28} {:<16} {}\n", scenario.name, scenario.technique, scenario.path);
    }
  } else if (args.what == "measures") {
    for (const Measure* m : MeasureRegistry::instance().all()) {
      const MeasureInfo& info = m->info();
      // The declaration: id, title, description, headline, fixed notes, metrics (unit, direction).
      nlohmann::ordered_json item = toJson(declarationOf(info));
      item.erase("measure");
      items.push_back({{"id", info.id}});
      items.back().update(item);
      if (!args.json) fmt::print("{:<16} {} — {}\n", info.id, info.title, info.description);
    }
  } else {
    throw InputError("list", args.what, "expected techniques, assets, scenarios or measures");
  }
  if (args.json) fmt::print("{}\n", items.dump(2));
  return 0;
}

int runRun(const RunArgs& args, const std::string& command_line) {
  SuiteSelection selection;
  selection.techniques = selectTechniques(args.techniques);
  selection.measures = selectMeasures(args.measures);
  selection.device_name = args.device;
  selection.threads = args.threads;
  selection.repetitions = args.repetitions;
  for (const std::string& asset : args.assets) selection.assets.push_back(resolveAsset(asset));
  for (const std::string& scenario : args.scenarios) {
    selection.scenarios.push_back(resolveScenario(scenario));
  }
  if (!args.shard.empty()) selection.shard = parseShard(args.shard);
  selection.suite = parseSuiteMode(args.suite);
  std::vector<std::string> camera_files;
  selection.camera_paths = selectCameraPaths(args.cameras, &camera_files);

  // The folder is claimed before measuring, so an unwritable --out or a taken --run-id
  // fails at once. It stays `<run-id>.incomplete` until everything is written; a run that
  // fails removes it, a killed one leaves it marked unfinished (run_folder.h).
  PendingRunFolder folder = PendingRunFolder::forRun(args.out, args.run_id);
  Results results;
  // On a terminal the progress line rewrites itself; in a log, one line per step; each
  // with the time left as estimated from the steps so far (progress_estimate.h).
  const bool terminal = isatty(fileno(stderr)) != 0;
  ProgressEstimate estimate;
  const ProgressFn progress = [&](size_t done, size_t total, const std::string& label) {
    if (args.quiet) return;
    const std::string left = estimate.remainingText(done, total);
    if (terminal) {
      std::fprintf(stderr, "\r[%zu/%zu %s] %-56.56s", done, total, left.c_str(), label.c_str());
      if (done == total) std::fprintf(stderr, "\n");
    } else {
      std::fprintf(stderr, "[%zu/%zu %s] %s\n", done, total, left.c_str(), label.c_str());
    }
  };
  SuiteTimings timings;
  runSuite(selection, progress, &results, &timings,
           [&](const Record& record) { folder.journal(recordJsonLine(record)); });
  // Nothing measurable (e.g. a triangle mesh given to acc alone) is bad input, not an
  // empty run: one line with the first reason, non-zero exit, no run folder. A shard sees
  // only its slice; `merge` makes this check on the whole.
  if (!selection.shard.sharded() && results.records.empty() && !results.skipped.empty()) {
    const Skip& skip = results.skipped.front();
    throw InputError(skip.asset, "", skip.reason + " (nothing to measure)");
  }

  results.context = probeRunContext(command_line, args.device);
  results.context.date = utcTimestampIso8601();
  results.context.run_id = folder.runId();
  results.context.selection = describeSelection(selection, results);
  results.context.selection.camera_paths = camera_files;
  if (!args.shard.empty()) results.context.shard = toShardId(selection.shard);
  if (args.pictures) {  // pictures/: PNGs and pictures.json, on the run's device
    std::filesystem::create_directory(folder.pendingPath() + "/" + kPicturesFolder);
    const PicturesIndex pictures = renderRunPictures(
        results, args.device,
        [&](const std::string& path, const std::string& bytes) { folder.writeFile(path, bytes); });
    if (!args.quiet) fmt::print(stderr, "pictures: {}\n", picturesSummary(pictures));
  }
  folder.writeFile("report.md", renderMarkdown(results));
  for (const auto& [name, text] : renderCsvTables(results)) folder.writeFile(name, text);
  folder.writeFile("report.html", renderRunHtml(results, folder.pendingPath()));
  folder.writeFile("timings.json", timingsJson(timings));
  folder.writeFile("results.json", serializeResults(results));
  const std::string finished = folder.finish();
  if (!args.quiet) {
    printTimingSummary(timings);
    fmt::print("{} records, {} skipped: results written to {}/ (results.json, report.md, report.html)\n",
               results.records.size(), results.skipped.size(), finished);
  } else {
    fmt::print("{}\n", finished);
  }
  // A measure that threw (not bad input: that stops the run) failed its record only; the
  // run is complete but not clean, so it says which and exits 1.
  // Rows that failed (a GPU part of a measure: a device error, a plug-in's missing shader)
  // get one line per record and measure, with the first reason.
  size_t failed = 0;
  for (const Record& record : results.records) {
    for (const MeasureResult& measure : record.measures) {
      std::string reason = measure.reason;
      size_t failed_rows = 0;
      for (const MetricRow& row : measure.rows) {
        if (row.status != MeasureStatus::kFailed) continue;
        if (failed_rows++ == 0) reason = row.reason;
      }
      if (measure.status != MeasureStatus::kFailed && failed_rows == 0) continue;
      ++failed;
      const std::string rows =
          failed_rows == 0 ? "" : fmt::format("{} of {} rows: ", failed_rows, measure.rows.size());
      fmt::print(stderr, "tessbench: failed: {}/{} {} {}: {}{}\n", record.technique,
                 record.variant, record.asset, measure.measure, rows, reason);
    }
  }
  return failed == 0 ? 0 : 1;
}

int runReport(const ReportArgs& args) {
  requireFinishedRunFolder(args.run_dir);
  const Results results = readResultsFile(args.run_dir + "/results.json");
  if (args.format == "md") {
    fmt::print("{}", renderMarkdown(results));
  } else if (args.format == "html") {
    const HtmlAssets assets = loadHtmlAssets(args.run_dir);
    if (assets.chartjs_source.empty()) throw std::runtime_error(assets.chartjs_missing_reason);
    fmt::print("{}", renderHtml(results, assets));
  } else {
    throw InputError("--format", args.format, "unknown report format (known: md, html)");
  }
  return 0;
}

}  // namespace tb::cli
