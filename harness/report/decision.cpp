#include "harness/report/decision.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

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

const results::MeasureResult* measureOf(const results::Results& results,
                                        const std::string& technique, const std::string& variant,
                                        const std::string& asset, const std::string& measure) {
  for (const results::Record& record : results.records) {
    if (record.technique != technique || record.variant != variant || record.asset != asset)
      continue;
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure == measure) return &m;
    }
  }
  return nullptr;
}

bool endsWith(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() &&
         text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

void readError(const results::MeasureResult* m, DecisionFigures* f) {
  if (m == nullptr || m->status != results::MeasureStatus::kOk) return;
  for (const results::MetricRow& row : m->rows) {
    if (row.status != results::MeasureStatus::kOk) continue;
    if (const auto value = rowMetric(row, "hausdorff"))
      f->error = std::max(f->error.value_or(0), *value);
  }
}

// The fewest triangles at 1 px over the policies' summary rows; `declaration` (may be null)
// names the control rows, which never count.
void readTriangles(const results::MeasureResult* m, const results::MeasureDeclaration* declaration,
                   DecisionFigures* f) {
  if (m == nullptr || m->status != results::MeasureStatus::kOk) return;
  for (const results::MetricRow& row : m->rows) {
    if (row.status != results::MeasureStatus::kOk || rowKey(row, "summary") != "max_error_1px")
      continue;
    if (declaration != nullptr && results::isControlRow(*declaration, row.keys)) continue;
    const auto triangles = rowMetric(row, "triangles_per_frame_at_target");
    if (!triangles || rowMetric(row, "target_reached").value_or(1) == 0) continue;
    const std::string path = rowKey(row, "camera_path");
    if (f->camera_path.empty()) f->camera_path = path;  // the first path: the default one
    if (path != f->camera_path) continue;
    if (!f->triangles_1px || *triangles < *f->triangles_1px) {
      f->triangles_1px = *triangles;
      f->triangles_policy = rowKey(row, "policy");
    }
  }
}

// Whether a row belongs to `path`: its path key, or none (results before the compute path,
// measures without one) for the tessellator's.
bool onPath(const results::MetricRow& row, const std::string& path) {
  const std::string key = rowKey(row, "path");
  return key == path || (key.empty() && path == kTessellatorPath);
}

void readMemory(const results::MeasureResult* m, const std::string& path, DecisionFigures* f) {
  if (m == nullptr || m->status != results::MeasureStatus::kOk) return;
  for (const results::MetricRow& row : m->rows) {
    if (row.status != results::MeasureStatus::kOk || !onPath(row, path) ||
        rowKey(row, "level") != std::to_string(kDecisionMemoryLevel))
      continue;
    const auto plain = rowMetric(row, "plain_bytes");
    const auto technique = rowMetric(row, "technique_with_displacement_bytes");
    const double transient = rowMetric(row, "transient_vertex_bytes").value_or(0) +
                             rowMetric(row, "transient_index_bytes").value_or(0);
    if (plain && technique && *plain > 0) f->memory_ratio = (*technique + transient) / *plain;
  }
}

// Tessellator path: the TCS and TES; compute path: its build and evaluate passes.
void readInstructions(const results::MeasureResult* m, const std::string& path,
                      DecisionFigures* f) {
  if (m == nullptr || m->status != results::MeasureStatus::kOk) return;
  const bool compute = path == kComputePath;
  for (const results::MetricRow& row : m->rows) {
    const std::string stage = rowKey(row, "stage");
    const bool stage_of_path = compute ? endsWith(stage, "#build") || endsWith(stage, "#evaluate")
                                       : endsWith(stage, ".tesc") || endsWith(stage, ".tese");
    if (row.status != results::MeasureStatus::kOk || rowKey(row, "expansion") != "vector" ||
        rowKey(row, "source") != "spirv_O" || !stage_of_path)
      continue;
    if (const auto total = rowMetric(row, "total"))
      f->instructions = f->instructions.value_or(0) + *total;
  }
}

// One side (CPU or device) of the cracks rows.
struct Side {
  size_t ok = 0, not_ok = 0;
  double points = 0;
  Watertightness verdict() const {
    if (points > 0) return Watertightness::kCracked;
    if (not_ok > 0) return Watertightness::kUnverified;
    return ok > 0 ? Watertightness::kWatertight : Watertightness::kNotMeasured;
  }
};

void readCracks(const results::MeasureResult* m, const std::string& path, DecisionFigures* f) {
  if (m == nullptr) return;
  Side cpu, device;
  if (m->status != results::MeasureStatus::kOk) {
    f->cpu = f->device = Watertightness::kUnverified;
    return;
  }
  for (const results::MetricRow& row : m->rows) {
    const bool on_device = rowKey(row, "backend") == "gpu";
    if (on_device && !onPath(row, path)) continue;  // the CPU rows are every path's
    Side& side = on_device ? device : cpu;
    if (row.status != results::MeasureStatus::kOk) {
      ++side.not_ok;
      continue;
    }
    ++side.ok;
    side.points = std::max(side.points, rowMetric(row, "points_not_equal").value_or(0) +
                                            rowMetric(row, "unpaired_points").value_or(0));
  }
  f->cpu = cpu.verdict();
  f->device = device.verdict();
  f->cpu_points = cpu.points;
  f->device_points = device.points;
}

// Whether the run measured the record's cracks on the compute path (an ok row there).
bool measuredOnCompute(const results::MeasureResult* cracks) {
  if (cracks == nullptr || cracks->status != results::MeasureStatus::kOk) return false;
  return std::any_of(cracks->rows.begin(), cracks->rows.end(), [](const results::MetricRow& row) {
    return row.status == results::MeasureStatus::kOk && rowKey(row, "path") == kComputePath;
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
    text += fmt::format(", {} {} instructions", number(f.instructions),
                        c.path == kComputePath ? "build + evaluate" : "TCS + TES");
  }
  return text + ".";
}

// Where the runner-up is better and where worse than the recommendation.
std::string tradeSentence(const DecisionCandidate& first, const DecisionCandidate& second) {
  std::vector<std::string> better, worse;
  const auto compare = [&](const char* what, const std::optional<double>& mine,
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
  compare("error", a.error, b.error);
  compare("triangles at 1 px", a.triangles_1px, b.triangles_1px);
  compare("instructions", a.instructions, b.instructions);
  compare("memory ratio", a.memory_ratio, b.memory_ratio);
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
  const auto of = [&](const char* measure) {
    return measureOf(results, technique, variant, asset, measure);
  };
  readError(of("error"), &f);
  readTriangles(of("adaptivity"), results.findMeasure("adaptivity"), &f);
  readMemory(of("memory"), path, &f);
  readInstructions(of("instructions"), path, &f);
  readCracks(of("cracks"), path, &f);
  return f;
}

bool decisionBefore(const DecisionFigures& a, const DecisionFigures& b) {
  return ruleKey(a) < ruleKey(b);
}

AssetDecision decideAsset(const results::Results& results, const std::string& asset) {
  AssetDecision decision;
  decision.asset = asset;
  for (const auto& technique : techniquesOf(results)) {
    if (technique.variants.empty()) continue;
    const std::string& variant = technique.variants.front();
    if (isControl(results, technique.technique, variant)) continue;
    if (measureOf(results, technique.technique, variant, asset, "error") == nullptr) continue;
    decision.candidates.push_back({technique.technique, variant,
                                   decisionFigures(results, technique.technique, variant, asset)});
    if (measuredOnCompute(measureOf(results, technique.technique, variant, asset, "cracks"))) {
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
  decision.runner_up = decision.candidates.size() < 2
                           ? "No runner-up: one candidate."
                           : tradeSentence(decision.candidates[0], decision.candidates[1]);
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
