#include "harness/cli/advise_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/mesh/input_error.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/complete_declarations.h"
#include "harness/measures/measure.h"
#include "harness/report/advice.h"
#include "harness/report/decision.h"
#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/shard.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"

namespace tb::cli {
namespace {

std::optional<double> parseBound(const std::string& option, const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value) || value < 0) {
    throw UsageError(option, text, "a bound is a finite number >= 0");
  }
  return value;
}

std::vector<const techniques::Technique*> techniquesNamed(const std::vector<std::string>& ids) {
  std::vector<const techniques::Technique*> selected;
  for (const std::string& id : ids) {
    const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
    if (technique == nullptr) {
      std::string known;
      for (const techniques::Technique* t : techniques::TechniqueRegistry::instance().all()) {
        known += (known.empty() ? "" : ", ") + t->info().id;
      }
      throw UsageError("--technique", id, "unknown technique (known: " + known + ")");
    }
    selected.push_back(technique);
  }
  return selected;
}

// The advise measures of every (selected) technique on the one asset, default suite, no
// run folder: only what the ranking and the constraints read (no control variant, no
// compressed memory baseline, no cracks with --allow-cracks), progress on stderr.
results::Results measureInProcess(const AdviseArgs& args, std::string* asset_name) {
  suite::SuiteSelection selection;
  selection.techniques = techniquesNamed(args.techniques);
  suite::AssetRef asset = suite::resolveAsset(args.asset);
  if (args.refine > 0) asset = suite::refinedAsset(std::move(asset), args.refine);
  *asset_name = asset.name;
  selection.assets.push_back(asset);
  selection.skip_controls = true;
  selection.decision_figures_only = true;
  for (const std::string& id : adviseMeasureIds()) {
    if (id == "cracks" && args.allow_cracks) continue;  // only the watertight constraint reads it
    const measures::Measure* measure = measures::MeasureRegistry::instance().find(id);
    if (measure == nullptr) throw mesh::InputError("advise", id, "measure not registered");
    selection.measures.push_back(measure);
  }
  results::Results results;
  const bool quiet = args.json;
  suite::runSuite(
      selection,
      [quiet](size_t done, size_t total, const std::string& label) {
        if (!quiet) fmt::print(stderr, "advise: [{}/{}] {}\n", done, total, label);
      },
      &results);
  results.context.selection = suite::describeSelection(selection, results);
  return results;
}

// The run's name for `asked`: itself, or the one asset whose name ends in "/<asked>"
// ("catmark_cube" for "opensubdiv/catmark_cube", as `run --asset` takes it).
std::string assetInRun(const results::Results& results, const std::string& asked) {
  std::vector<std::string> names;
  for (const results::AssetSummary& a : results.assets) names.push_back(a.name);
  for (const results::Skip& s : results.skipped) names.push_back(s.asset);
  if (std::find(names.begin(), names.end(), asked) != names.end()) return asked;
  std::string found;
  for (const std::string& name : names) {
    if (name.size() > asked.size() && name.ends_with("/" + asked) && name != found) {
      if (!found.empty()) return asked;  // ambiguous: only the full name will do
      found = name;
    }
  }
  return found.empty() ? asked : found;
}

results::Results readRun(const AdviseArgs& args, std::string* asset_name) {
  techniquesNamed(args.techniques);  // an unknown id is bad input here too
  results::requireFinishedRunFolder(args.run_dir);
  results::Results results = results::readResultsFile(args.run_dir + "/results.json");
  measures::completeDeclarations(&results);
  *asset_name = assetInRun(results, args.asset);
  const bool named =
      std::any_of(results.records.begin(), results.records.end(),
                  [&](const results::Record& r) { return r.asset == *asset_name; }) ||
      std::any_of(results.skipped.begin(), results.skipped.end(),
                  [&](const results::Skip& s) { return s.asset == *asset_name; });
  if (!named) {
    std::string known;
    for (const results::AssetSummary& a : results.assets)
      known += (known.empty() ? "" : ", ") + a.name;
    throw mesh::InputError(args.run_dir + "/results.json", args.asset,
                           "no records for this asset in the run (assets: " + known + ")");
  }
  return results;
}

nlohmann::ordered_json optionalJson(const std::optional<double>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

std::string adviceJson(const report::Advice& advice, const report::AdviceConstraints& c) {
  nlohmann::ordered_json candidates = nlohmann::ordered_json::array();
  for (size_t i = 0; i < advice.ranked.size(); ++i) {
    const report::Candidate& candidate = advice.ranked[i];
    const report::CandidateFigures& f = candidate.figures;
    candidates.push_back({{"rank", i + 1},
                          {"technique", candidate.technique},
                          {"variant", candidate.variant},
                          {"passes", candidate.passes},
                          {"error", optionalJson(f.error)},
                          {"instructions", optionalJson(f.instructions)},
                          {"memory_ratio", optionalJson(f.memory_ratio)},
                          {"memory_from_default_variant", f.memory_from_default},
                          {"error_from_default_variant", f.error_from_default},
                          {"watertight", toString(f.watertight)},
                          {"points_not_equal", f.points_not_equal},
                          {"unpaired_points", f.unpaired_points},
                          {"failures", candidate.failures},
                          {"verdict", candidate.verdict}});
  }
  nlohmann::ordered_json unsupported = nlohmann::ordered_json::array();
  for (const report::UnsupportedTechnique& u : advice.unsupported) {
    unsupported.push_back({{"technique", u.technique},
                           {"verdict", "excluded: unsupported input: " + u.reason},
                           {"reason", u.reason}});
  }
  const nlohmann::ordered_json json{
      {"asset", advice.asset},
      {"constraints",
       {{"max_error", optionalJson(c.max_error)},
        {"max_memory_ratio", optionalJson(c.max_memory_ratio)},
        {"watertight", c.watertight},
        {"max_instructions", optionalJson(c.max_instructions)}}},
      {"units", {{"error", "rel_diag"}, {"instructions", "count"}, {"memory_ratio", "ratio"}}},
      {"ranking_rule", report::kAdviceRankingRule},
      {"figures", advice.figure_units},
      {"candidates", candidates},
      {"unsupported", unsupported},
      {"first_choice", advice.anyPasses()
                           ? nlohmann::ordered_json(advice.ranked.front().technique + "/" +
                                                    advice.ranked.front().variant)
                           : nlohmann::ordered_json(nullptr)},
      {"recommendation", advice.recommendation.empty()
                             ? nlohmann::ordered_json(nullptr)
                             : nlohmann::ordered_json(advice.recommendation)},
      {"recommendation_why", advice.recommendation_why},
      {"recommendation_rule", report::kDecisionRule}};
  return json.dump(2) + "\n";
}

}  // namespace

const std::vector<std::string>& adviseMeasureIds() {
  static const std::vector<std::string> kIds{"error", "cracks", "memory", "instructions"};
  return kIds;
}

CLI::App* addAdviseCommand(CLI::App& app, AdviseArgs& args) {
  CLI::App* advise = app.add_subcommand(
      "advise",
      "rank technique x variant on one asset under constraints (error, memory, watertightness, "
      "instructions), measuring error, cracks, memory and instructions in-process or reading a "
      "finished run; exit 0 when a candidate meets every constraint, 1 when none does, 2 on bad "
      "input");
  advise->add_option("asset", args.asset, "bundled asset name or OBJ, glTF or GLB path")
      ->required();
  advise->add_option("--run", args.run_dir,
                     "read a finished run folder (results/<run-id>) instead of measuring");
  advise->add_option("--max-error", args.max_error,
                     "largest worst hausdorff distance, fraction of the bounding-box diagonal");
  advise->add_option("--max-memory-ratio", args.max_memory_ratio,
                     "largest technique bytes (with displacement map) / plain triangle mesh bytes");
  advise->add_flag("--allow-cracks", args.allow_cracks,
                   "drop the default constraint that every cracks row is watertight, CPU and "
                   "device (skipped device rows fail it); cracks are then not measured");
  advise->add_flag("--watertight", args.watertight_flag,
                   "the default: every cracks row watertight (kept for scripts)");
  advise
      ->add_option("--refine", args.refine,
                   "refine the asset N times with OpenSubdiv at load, as `run --refine`")
      ->check(CLI::Range(0, suite::kMaxRefine));
  advise->add_option("--max-instructions", args.max_instructions,
                     "largest total SPIR-V instructions of the domain (.tese) stage, spirv-opt -O");
  advise->add_option("--technique", args.techniques, "only this technique (repeatable)");
  advise->add_flag("--json", args.json, "print JSON");
  return advise;
}

int runAdvise(const AdviseArgs& args) {
  report::AdviceConstraints constraints;
  constraints.max_error = parseBound("--max-error", args.max_error);
  constraints.max_memory_ratio = parseBound("--max-memory-ratio", args.max_memory_ratio);
  constraints.max_instructions = parseBound("--max-instructions", args.max_instructions);
  if (args.allow_cracks && args.watertight_flag) {
    throw UsageError("advise", "--allow-cracks", "contradicts --watertight; give one");
  }
  constraints.watertight = !args.allow_cracks;
  constraints.techniques = args.techniques;

  std::string asset = args.asset;
  const results::Results results =
      args.run_dir.empty() ? measureInProcess(args, &asset) : readRun(args, &asset);
  const report::Advice advice = report::rankCandidates(results, asset, constraints);
  fmt::print("{}", args.json ? adviceJson(advice, constraints)
                             : report::renderAdviceMarkdown(advice, constraints));
  return advice.anyPasses() ? 0 : 1;
}

namespace {

SubcommandRun addAdvise(CLI::App& app) {
  auto args = std::make_shared<AdviseArgs>();
  addAdviseCommand(app, *args);
  return [args](const Invocation&) { return runAdvise(*args); };
}

}  // namespace

const Subcommand kAdviseSubcommand{"advise", addAdvise};

}  // namespace tb::cli
