#include "harness/cli/run_command.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "core/mesh/input_error.h"
#include "harness/cli/html_assets.h"
#include "harness/cli/progress_estimate.h"
#include "harness/cli/run_context.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/common/isa/isa_assembly.h"
#include "harness/measures/measure.h"
#include "harness/pictures/run_pictures.h"
#include "harness/report/csv_tables.h"
#include "harness/report/markdown.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "harness/results/timings_json.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/camera_path.h"
#include "harness/suite/displacement_file.h"
#include "harness/suite/scenario_file.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"

namespace tb::cli {
namespace {

std::string knownIds(const std::vector<std::string>& ids) {
  std::string text;
  for (const auto& id : ids) text += (text.empty() ? "" : ", ") + id;
  return text;
}

// --technique values: ID (every variant its suite runs) or ID/VARIANT (that variant alone;
// several may name one technique). ID and ID/VARIANT together: every variant.
void selectTechniques(const std::vector<std::string>& values, suite::SuiteSelection* selection) {
  std::vector<std::string> known;
  for (const techniques::Technique* t : techniques::TechniqueRegistry::instance().all())
    known.push_back(t->info().id);
  std::set<std::string> whole;
  for (const std::string& value : values) {
    const size_t slash = value.find('/');
    const std::string id = value.substr(0, slash);
    const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
    if (technique == nullptr) {
      throw UsageError("--technique", value, "unknown technique (known: " + knownIds(known) + ")");
    }
    if (std::find(selection->techniques.begin(), selection->techniques.end(), technique) ==
        selection->techniques.end()) {
      selection->techniques.push_back(technique);
    }
    if (slash == std::string::npos) {
      whole.insert(id);
      continue;
    }
    const std::string variant = value.substr(slash + 1);
    std::vector<std::string> names;
    for (const techniques::VariantInfo& v : technique->variants()) names.push_back(v.name);
    if (std::find(names.begin(), names.end(), variant) == names.end()) {
      throw UsageError("--technique", value,
                       "unknown variant of " + id + " (known: " + knownIds(names) + ")");
    }
    selection->variants[id].insert(variant);
  }
  for (const std::string& id : whole) selection->variants.erase(id);
}

std::vector<const measures::Measure*> selectMeasures(const std::vector<std::string>& ids) {
  std::vector<const measures::Measure*> selected;
  std::vector<std::string> known;
  for (const measures::Measure* m : measures::MeasureRegistry::instance().all())
    known.push_back(m->info().id);
  for (const std::string& id : ids) {
    const measures::Measure* measure = measures::MeasureRegistry::instance().find(id);
    if (measure == nullptr) {
      throw UsageError("--measure", id, "unknown measure (known: " + knownIds(known) + ")");
    }
    selected.push_back(measure);
  }
  return selected;
}

measures::SuiteMode parseSuiteMode(const std::string& text) {
  if (text == toString(measures::SuiteMode::kDefault)) return measures::SuiteMode::kDefault;
  if (text == toString(measures::SuiteMode::kFull)) return measures::SuiteMode::kFull;
  throw UsageError("--suite", text, "unknown suite (known: default, full)");
}

// Reads every --camera file before any work, so a bad one stops the run with nothing
// written; `shown` gets the files as results name them.
std::vector<suite::CameraPathFn> selectCameraPaths(const std::vector<std::string>& names_or_paths,
                                                   std::vector<std::string>* shown) {
  std::vector<suite::CameraPathFn> paths;
  for (const std::string& name_or_path : names_or_paths) {
    suite::CameraPathSpec spec = suite::resolveCameraPath(name_or_path);
    shown->push_back(spec.shown_path);
    paths.push_back(suite::cameraPathFn(std::move(spec)));
  }
  return paths;
}

// Wall seconds per record × measure, every repetition's, beside results.json: timings
// change run to run, the results must not (harness/results/timings_json.h).
std::string timingsJson(const suite::SuiteTimings& timings, const std::string& device) {
  results::RunTimings run{timings.wall_seconds, timings.threads, timings.repetitions, device, {}};
  for (const suite::MeasureTiming& t : timings.measures) {
    run.measures.push_back({t.technique, t.variant, t.asset, t.measure,
                            t.samples.empty() ? std::vector<double>{t.seconds} : t.samples});
  }
  return results::serializeTimings(run);
}

// Suite wall time and each measure's summed time, the figures the suite budget is kept by.
void printTimingSummary(const suite::SuiteTimings& timings) {
  std::map<std::string, double> per_measure;
  for (const suite::MeasureTiming& t : timings.measures) per_measure[t.measure] += t.seconds;
  std::string parts;
  for (const auto& [measure, seconds] : per_measure) {
    parts += fmt::format("{}{} {:.1f} s", parts.empty() ? "" : ", ", measure, seconds);
  }
  fmt::print(stderr, "suite: {:.1f} s wall on {} threads; measure time: {}\n", timings.wall_seconds,
             timings.threads, parts);
}

// The suite's selection from the options; `camera_files` gets the --camera files as
// results name them. Throws InputError on an unknown id, asset, scenario or map.
suite::SuiteSelection selectionOf(const RunArgs& args, std::vector<std::string>* camera_files) {
  suite::SuiteSelection selection;
  selectTechniques(args.techniques, &selection);
  selection.measures = selectMeasures(args.measures);
  selection.device_name = args.device;
  selection.threads = args.threads;
  selection.repetitions = args.repetitions;
  for (const std::string& asset : args.assets) {
    suite::AssetRef ref = suite::resolveAsset(asset);
    selection.assets.push_back(args.refine > 0 ? suite::refinedAsset(std::move(ref), args.refine)
                                               : std::move(ref));
  }
  if (args.refine > 0 && args.assets.empty()) {
    throw UsageError("--refine", std::to_string(args.refine),
                     "refines the assets named by --asset; name at least one");
  }
  for (const std::string& map : args.displacements) {
    selection.displacements.push_back(suite::loadDisplacementFile(map));
  }
  if (args.displacements.empty() && args.assets.empty()) {
    selection.displacements = suite::bundledDisplacements();
  }
  for (const std::string& scenario : args.scenarios) {
    selection.scenarios.push_back(suite::resolveScenario(scenario));
  }
  if (!args.shard.empty()) selection.shard = suite::parseShard(args.shard);
  selection.suite = parseSuiteMode(args.suite);
  selection.camera_paths = selectCameraPaths(args.cameras, camera_files);
  return selection;
}

// On a terminal the progress line rewrites itself; in a log, one line per step; each
// with the time left as estimated from the steps so far (progress_estimate.h).
suite::ProgressFn progressPrinter(const RunArgs& args, ProgressEstimate* estimate) {
  const bool terminal = isatty(fileno(stderr)) != 0;
  return [&args, estimate, terminal](size_t done, size_t total, const std::string& label) {
    if (args.quiet) return;
    const std::string left = estimate->remainingText(done, total);
    if (terminal) {
      std::fprintf(stderr, "\r[%zu/%zu %s] %-56.56s", done, total, left.c_str(), label.c_str());
      if (done == total) std::fprintf(stderr, "\n");
    } else {
      std::fprintf(stderr, "[%zu/%zu %s] %s\n", done, total, left.c_str(), label.c_str());
    }
  };
}

// Everything the run folder holds besides the journal: pictures/ (unless --no-pictures),
// report.md, tables/, report.html, timings.json and results.json.
void writeRunFiles(const RunArgs& args, const results::Results& results,
                   const suite::SuiteTimings& timings, results::PendingRunFolder* folder) {
  if (args.pictures) {  // pictures/: PNGs and pictures.json, on the run's device
    std::filesystem::create_directory(folder->pendingPath() + "/" + pictures::kPicturesFolder);
    const pictures::PicturesIndex pictures = pictures::renderRunPictures(
        results, args.device,
        [&](const std::string& path, const std::string& bytes) { folder->writeFile(path, bytes); });
    if (!args.quiet) fmt::print(stderr, "pictures: {}\n", pictures::picturesSummary(pictures));
  }
  // isa/: the assembly the ISA measure's compilers gave, one file per executable.
  const std::map<std::string, std::string> assembly = measures::isa::keptAssembly();
  if (!assembly.empty()) {
    std::filesystem::create_directory(folder->pendingPath() + "/isa");
    for (const auto& [name, text] : assembly) folder->writeFile("isa/" + name, text);
  }
  folder->writeFile("report.md", report::renderMarkdown(results));
  for (const auto& [name, text] : report::renderCsvTables(results)) folder->writeFile(name, text);
  folder->writeFile("report.html", renderRunHtml(results, folder->pendingPath()));
  folder->writeFile("timings.json", timingsJson(timings, results.context.vulkan_device));
  folder->writeFile("results.json", results::serializeResults(results));
}

// A measure that threw (not bad input: that stops the run) failed its record only; the
// run is complete but not clean, so it says which: one line per record and measure that
// failed or has failed rows (a GPU part of a measure: a device error, a plug-in's missing
// shader), with the first reason. Returns how many.
size_t printFailures(const results::Results& results) {
  size_t failed = 0;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& measure : record.measures) {
      std::string reason = measure.reason;
      size_t failed_rows = 0;
      for (const results::MetricRow& row : measure.rows) {
        if (row.status != results::MeasureStatus::kFailed) continue;
        if (failed_rows++ == 0) reason = row.reason;
      }
      if (measure.status != results::MeasureStatus::kFailed && failed_rows == 0) continue;
      ++failed;
      const std::string rows =
          failed_rows == 0 ? "" : fmt::format("{} of {} rows: ", failed_rows, measure.rows.size());
      fmt::print(stderr, "tessbench: failed: {}/{} {} {}: {}{}\n", record.technique, record.variant,
                 record.asset, measure.measure, rows, reason);
    }
  }
  return failed;
}

SubcommandRun addRun(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  addRunCommand(app, *args);
  return [args](const Invocation& invocation) { return runRun(*args, invocation.command_line); };
}

}  // namespace

CLI::App* addRunCommand(CLI::App& app, RunArgs& args) {
  CLI::App* run =
      app.add_subcommand("run", "measure techniques on assets into a new results folder");
  run->add_option("--technique", args.techniques,
                  "technique id, or ID/VARIANT for one of its variants (repeatable; default all)");
  run->add_option("--asset", args.assets,
                  "bundled asset name or OBJ, glTF or GLB path (default all)");
  run->add_option("--refine", args.refine,
                  "refine every --asset N times with OpenSubdiv at load (Loop for all-triangle "
                  "meshes, Catmull-Clark otherwise), keeping creases, corners and holes: a "
                  "production-size input with the same limit surface (4^N times the faces; "
                  "the asset is named NAME@refineN)")
      ->check(CLI::Range(0, suite::kMaxRefine));
  run->add_option("--displacement", args.displacements,
                  "a baked map (FILE.exr with its FILE.exr.json from `tessbench bake`): adds its "
                  "asset displaced by it, for the map's technique and variant, to cracks, error "
                  "and memory (default: the bundled maps, unless --asset narrows the run)");
  run->add_option("--scenario", args.scenarios,
                  "bundled scenario name or scenario .json path, for simulation techniques "
                  "(repeatable; default all)");
  run->add_option("--measure", args.measures, "measure id (repeatable; default all)");
  run->add_option("--out", args.out, "results root; each run gets a new folder in it")
      ->capture_default_str();
  run->add_option("--run-id", args.run_id, "folder name (must not exist yet)");
  run->add_flag("--quiet", args.quiet, "no progress output");
  run->add_option("--device", args.device, "Vulkan device name substring (default: best)");
  run->add_option("--threads", args.threads,
                  "worker threads (default 0: every core); results do not depend on it")
      ->check(CLI::Range(0, 4096));
  run->add_option("--shard", args.shard,
                  "I/N: run only shard I of N (numbered from 0) of the technique x variant x "
                  "asset x measure work list; join the N run folders with `merge`");
  run->add_option("--suite", args.suite,
                  "default | full: the measures' default grid (within the time budget) or "
                  "every level, camera path and policy they know")
      ->capture_default_str();
  run->add_option("--camera", args.cameras,
                  "camera path: a bundled name (orbit, dolly, flyby) or a .json file "
                  "(repeatable; default: the suite's paths)");
  run->add_option("--repetitions", args.repetitions,
                  "run each measure of each record N times: results.json from the first "
                  "(a record warns when a repeat differs), every sample in timings.json, "
                  "for compare's U test (9 or more recommended)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  run->add_flag_callback(
      "--no-pictures", [&args] { args.pictures = false; },
      "do not render the pictures of each surface (pictures/ in the run folder)");
  return run;
}

int runRun(const RunArgs& args, const std::string& command_line) {
  std::vector<std::string> camera_files;
  const suite::SuiteSelection selection = selectionOf(args, &camera_files);

  // The folder is claimed before measuring, so an unwritable --out or a taken --run-id
  // fails at once. It stays `<run-id>.incomplete` until everything is written; a run that
  // fails removes it, a killed one leaves it marked unfinished (run_folder.h).
  results::PendingRunFolder folder = results::PendingRunFolder::forRun(args.out, args.run_id);
  results::Results results;
  ProgressEstimate estimate;
  const suite::ProgressFn progress = progressPrinter(args, &estimate);
  suite::SuiteTimings timings;
  suite::runSuite(selection, progress, &results, &timings, [&](const results::Record& record) {
    folder.journal(results::recordJsonLine(record));
  });
  // Nothing measurable (e.g. a triangle mesh given to acc alone) is bad input, not an
  // empty run: one line with the first reason, non-zero exit, no run folder. A shard sees
  // only its slice; `merge` makes this check on the whole.
  if (!selection.shard.sharded() && results.records.empty() && !results.skipped.empty()) {
    const results::Skip& skip = results.skipped.front();
    throw mesh::InputError(skip.asset, "", skip.reason + " (nothing to measure)");
  }

  results.context = probeRunContext(command_line, args.device);
  results.context.date = results::utcTimestampIso8601();
  results.context.run_id = folder.runId();
  results.context.selection = suite::describeSelection(selection, results);
  results.context.selection.camera_paths = camera_files;
  if (!args.shard.empty()) results.context.shard = suite::toShardId(selection.shard);
  writeRunFiles(args, results, timings, &folder);
  const std::string finished = folder.finish();
  if (!args.quiet) {
    printTimingSummary(timings);
    fmt::print(
        "{} records, {} skipped: results written to {}/ (results.json, report.md, report.html)\n",
        results.records.size(), results.skipped.size(), finished);
  } else {
    fmt::print("{}\n", finished);
  }
  for (const results::AssetSummary& asset : results.assets) {  // even with --quiet
    for (const std::string& warning : asset.warnings) {
      fmt::print(stderr, "tessbench: warning: {}: {}\n", asset.path, warning);
    }
  }
  return printFailures(results) == 0 ? 0 : 1;
}

const Subcommand kRunSubcommand{"run", addRun};

}  // namespace tb::cli
