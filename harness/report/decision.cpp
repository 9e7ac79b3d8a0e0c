#include "harness/report/decision.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

#include "harness/report/decision_inputs.h"
#include "harness/report/row_values.h"
#include "harness/report/summary.h"

namespace tb::report {

const char* const kDecisionRule =
    "candidates are each technique's default variant (controls never); watertight on the CPU "
    "and on the device first (then watertight on the CPU with the device unverified, then "
    "cracked); then error within 1e-3 of the bounding-box diagonal before error over it; among "
    "those within it, fewest triangles per frame for a 1 px tessellation error, among those "
    "over it, lowest error; then fewest TCS + TES instructions, then lowest error, then "
    "smallest memory ratio, then name. A technique measured on the compute path too is listed "
    "twice: the pair ranks by its tessellator path's figures (the same surface at the same "
    "levels), the compute path right after the tessellator path (it adds transient buffers), "
    "ahead only when it is watertight on the device where the tessellator path is not";

namespace {

using results::DecisionRole;

// The figure of `role` for one record's candidate on `path`, or none.
InputFigure figureOf(const results::Results& results, DecisionRole role,
                     const std::string& technique, const std::string& variant,
                     const std::string& asset, const std::string& path) {
  const auto input = inputFor(results, role, path);
  if (!input) return {};
  const results::MeasureResult* m = resultOf(results, technique, variant, asset, *input);
  return m == nullptr ? InputFigure{} : readInput(*input, *m, path);
}

// One side (CPU or device) of the watertightness rows.
struct Side {
  size_t ok = 0, not_ok = 0;
  double points = 0;
  Watertightness verdict() const {
    if (points > 0) return Watertightness::kCracked;
    if (not_ok > 0) return Watertightness::kUnverified;
    return ok > 0 ? Watertightness::kWatertight : Watertightness::kNotMeasured;
  }
};

// The device side's rows are the candidate's path's (the input's rows_on_path); the CPU
// rows are every path's.
void readCracks(const DeclaredInput& input, const results::MeasureResult* m,
                const std::string& path, DecisionFigures* f) {
  if (m == nullptr) return;
  Side cpu, device;
  if (m->status != results::MeasureStatus::kOk) {
    f->cpu = f->device = Watertightness::kUnverified;
    return;
  }
  results::DecisionInput cpu_input = *input.input;
  cpu_input.rows_on_path = false;
  for (const results::MetricRow& row : m->rows) {
    const bool on_device = results::rowInScope(input.input->device_rows, row.keys) &&
                           !input.input->device_rows.empty();
    if (!readsRow(on_device ? *input.input : cpu_input, row, path)) continue;
    Side& side = on_device ? device : cpu;
    if (row.status != results::MeasureStatus::kOk) {
      ++side.not_ok;
      continue;
    }
    ++side.ok;
    side.points = std::max(side.points, rowFigure(*input.input, row).value_or(0));
  }
  f->cpu = cpu.verdict();
  f->device = device.verdict();
  f->cpu_points = cpu.points;
  f->device_points = device.points;
}

// Whether the run measured the record's watertightness on the compute path (an ok row there).
bool measuredOnCompute(const results::MeasureResult* cracks) {
  if (cracks == nullptr || cracks->status != results::MeasureStatus::kOk) return false;
  return std::any_of(cracks->rows.begin(), cracks->rows.end(), [](const results::MetricRow& row) {
    return row.status == results::MeasureStatus::kOk &&
           rowKey(row, results::kPathKey) == kComputePath;
  });
}

// 0: watertight on both; 1: on the CPU, the device not verified; 2: otherwise.
int watertightTier(const DecisionFigures& f) {
  if (f.cpu != Watertightness::kWatertight) return 2;
  return f.device == Watertightness::kWatertight ? 0 : 1;
}

double orInf(const std::optional<double>& value) {
  return value.value_or(std::numeric_limits<double>::infinity());
}

auto ruleKey(const DecisionFigures& f) {
  const bool within = f.error && *f.error <= kDecisionMaxError;
  return std::make_tuple(watertightTier(f), within ? 0 : 1,
                         within ? orInf(f.triangles_1px) : orInf(f.error), orInf(f.instructions),
                         orInf(f.error), orInf(f.memory_ratio));
}

std::string number(const std::optional<double>& value) {
  return value ? formatAdviceNumber(*value) : std::string("none");
}

// "error 7.9e-4 rel_diag (within 1e-3)", ...: the recommendation's figures in rule order.
std::string whySentence(const DecisionCandidate& c, size_t candidates) {
  const DecisionFigures& f = c.figures;
  const char* tier = watertightTier(f) == 0   ? "watertight on the CPU and the device"
                     : watertightTier(f) == 1 ? "watertight on the CPU (device unverified)"
                     : f.cpu == Watertightness::kCracked ? "cracked (no candidate is watertight)"
                                                         : "watertightness not measured";
  const bool within = f.error && *f.error <= kDecisionMaxError;
  std::string text = fmt::format("{} ranks first of {}: {}, error {} rel_diag ({} 1e-3)", c.name(),
                                 candidates, tier, number(f.error), within ? "within" : "over");
  if (f.triangles_1px) {
    text += fmt::format(", {} triangles per frame at 1 px ({})", number(f.triangles_1px),
                        f.triangles_policy);
  }
  if (f.instructions) {
    text += fmt::format(", {} {}", number(f.instructions), f.cost_label);
  }
  return text + ".";
}

// Where the runner-up is better and where worse than the recommendation.
std::string tradeSentence(const DecisionLabels& labels, const DecisionCandidate& first,
                          const DecisionCandidate& second) {
  std::vector<std::string> better, worse;
  const auto compare = [&](const std::string& what, const std::optional<double>& mine,
                           const std::optional<double>& theirs) {
    if (!mine || !theirs || number(mine) == number(theirs)) return;  // equal as shown
    (*mine < *theirs ? better : worse)
        .push_back(fmt::format("{} {} vs {}", what, number(mine), number(theirs)));
  };
  const DecisionFigures& a = second.figures;
  const DecisionFigures& b = first.figures;
  if (watertightTier(a) != watertightTier(b)) {
    (watertightTier(a) < watertightTier(b) ? better : worse)
        .push_back(fmt::format("watertight CPU/device {}/{}", watertightText(a.cpu, a.cpu_points),
                               watertightText(a.device, a.device_points)));
  }
  compare(labels.error, a.error, b.error);
  compare(labels.triangles, a.triangles_1px, b.triangles_1px);
  compare(labels.cost, a.instructions, b.instructions);
  compare(labels.memory, a.memory_ratio, b.memory_ratio);
  const auto list = [](const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
    return text.empty() ? std::string("nothing") : text;
  };
  return fmt::format("Runner-up {} is better in {}; worse in {}.", second.name(), list(better),
                     list(worse));
}

void markFront(std::vector<DecisionCandidate>* candidates) {
  for (DecisionCandidate& c : *candidates) {
    const DecisionFigures& f = c.figures;
    if (!f.error || !f.triangles_1px) continue;
    c.on_front =
        std::none_of(candidates->begin(), candidates->end(), [&](const DecisionCandidate& o) {
          const DecisionFigures& g = o.figures;
          return g.error && g.triangles_1px && *g.error <= *f.error &&
                 *g.triangles_1px <= *f.triangles_1px &&
                 (*g.error < *f.error || *g.triangles_1px < *f.triangles_1px);
        });
  }
}

}  // namespace

std::string watertightText(Watertightness side, double points) {
  if (side == Watertightness::kCracked) return "no (" + formatAdviceNumber(points) + ")";
  return toString(side);
}

DecisionFigures decisionFigures(const results::Results& results, const std::string& technique,
                                const std::string& variant, const std::string& asset,
                                const std::string& path) {
  DecisionFigures f;
  const auto figure = [&](DecisionRole role) {
    return figureOf(results, role, technique, variant, asset, path);
  };
  f.error = figure(DecisionRole::kError).value;
  const InputFigure triangles = figure(DecisionRole::kTrianglesAtTarget);
  f.triangles_1px = triangles.value;
  f.triangles_policy = triangles.chosen;
  f.camera_path = triangles.first;
  f.memory_ratio = figure(DecisionRole::kMemoryRatio).value;
  f.instructions = figure(DecisionRole::kShaderCost).value;
  if (const auto cost = inputFor(results, DecisionRole::kShaderCost, path)) {
    f.cost_label = cost->input->label;
  }
  if (const auto cracks = inputFor(results, DecisionRole::kCrackPoints, path)) {
    readCracks(*cracks, resultOf(results, technique, variant, asset, *cracks), path, &f);
  }
  return f;
}

DecisionLabels decisionLabels(const results::Results& results) {
  DecisionLabels labels;
  const auto label = [&](DecisionRole role, std::string* out) {
    const auto input = inputFor(results, role);
    *out = input ? input->input->label : std::string(results::toString(role));
  };
  label(DecisionRole::kError, &labels.error);
  label(DecisionRole::kTrianglesAtTarget, &labels.triangles);
  label(DecisionRole::kShaderCost, &labels.cost);
  label(DecisionRole::kMemoryRatio, &labels.memory);
  return labels;
}

bool decisionBefore(const DecisionFigures& a, const DecisionFigures& b) {
  return ruleKey(a) < ruleKey(b);
}

AssetDecision decideAsset(const results::Results& results, const std::string& asset) {
  AssetDecision decision;
  decision.asset = asset;
  const auto error = inputFor(results, DecisionRole::kError);
  if (error && !error->input->metrics.empty()) {
    decision.error_axis = fmt::format("{}: {} ({})", error->input->label,
                                      error->input->metrics.front(), unitOf(*error));
  }
  const auto cracks_input = inputFor(results, DecisionRole::kCrackPoints, kComputePath);
  for (const auto& technique : techniquesOf(results)) {
    if (technique.variants.empty()) continue;
    const std::string& variant = technique.variants.front();
    if (isControl(results, technique.technique, variant)) continue;
    if (!error || resultOf(results, technique.technique, variant, asset, *error) == nullptr)
      continue;
    decision.candidates.push_back({technique.technique, variant,
                                   decisionFigures(results, technique.technique, variant, asset)});
    const results::MeasureResult* cracks =
        cracks_input ? resultOf(results, technique.technique, variant, asset, *cracks_input)
                     : nullptr;
    if (measuredOnCompute(cracks)) {
      decision.candidates.push_back(
          {technique.technique, variant,
           decisionFigures(results, technique.technique, variant, asset, kComputePath), false,
           kComputePath});
    }
  }
  // A compute-path candidate ranks with its tessellator twin (pushed just before it).
  std::map<std::string, DecisionFigures> twin;
  for (const DecisionCandidate& c : decision.candidates) {
    if (c.path == kTessellatorPath) twin[c.technique + "/" + c.variant] = c.figures;
  }
  const auto pairFigures = [&](const DecisionCandidate& c) -> const DecisionFigures& {
    return twin.at(c.technique + "/" + c.variant);
  };
  std::stable_sort(decision.candidates.begin(), decision.candidates.end(),
                   [&](const DecisionCandidate& a, const DecisionCandidate& b) {
                     const DecisionFigures& pa = pairFigures(a);
                     const DecisionFigures& pb = pairFigures(b);
                     if (decisionBefore(pa, pb)) return true;
                     if (decisionBefore(pb, pa)) return false;
                     if (a.technique != b.technique || a.variant != b.variant) {
                       return a.technique + "/" + a.variant < b.technique + "/" + b.variant;
                     }
                     const int tier_a = watertightTier(a.figures),
                               tier_b = watertightTier(b.figures);
                     if (tier_a != tier_b) return tier_a < tier_b;
                     return a.path == kTessellatorPath && b.path != kTessellatorPath;
                   });
  markFront(&decision.candidates);
  if (!decision.candidates.empty()) {
    decision.why = whySentence(decision.candidates[0], decision.candidates.size());
  }
  decision.runner_up =
      decision.candidates.size() < 2
          ? "No runner-up: one candidate."
          : tradeSentence(decisionLabels(results), decision.candidates[0], decision.candidates[1]);
  return decision;
}

std::vector<AssetDecision> decideAssets(const results::Results& results) {
  std::vector<AssetDecision> decisions;
  for (const results::AssetSummary& asset : results.assets) {
    AssetDecision decision = decideAsset(results, asset.name);
    if (!decision.candidates.empty()) decisions.push_back(std::move(decision));
  }
  return decisions;
}

}  // namespace tb::report
