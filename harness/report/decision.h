// The decision per surface asset (report.md's decision tables, report.html's trade-off charts
// and `tessbench advise`'s recommendation: one definition, here). The candidates are each
// technique's default variant (its first), never a control; each with the figures that trade
// off: error, triangles per frame for a 1 px tessellation error, memory against the plain
// triangle mesh, shader cost, watertightness on the CPU and on the device. The
// Pareto front is over error and triangles at 1 px (the trade-off chart's axes); the
// recommendation is the first candidate under kDecisionRule. Pure over the results model.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/report/advice.h"
#include "harness/results/results_model.h"

namespace tb::report {

// The error a candidate must stay within to compete on triangles: 1e-3 of the bounding-box
// diagonal (about 1 px on an object 1000 px across).
inline constexpr double kDecisionMaxError = 1e-3;
// The rule, printed with every decision.
extern const char* const kDecisionRule;

// A candidate's figures, each read through the input its measure declares for the role
// (results::DecisionInput, decision_inputs.h); none where no measure declares it.
struct DecisionFigures {
  // kError: the worst over the error rows (rel_diag; best 0, worst ~1).
  std::optional<double> error;
  // kTrianglesAtTarget: the fewest over the technique's factor policies on its first camera
  // path, control rows never (count per frame; best: few, worst: uniform's).
  std::optional<double> triangles_1px;
  std::string triangles_policy;  // the policy reaching it
  std::string camera_path;       // the path it was measured along
  // kMemoryRatio: the technique's bytes over the plain mesh's (ratio; 0.05: a twentieth of the
  // plain mesh's bytes; above 1: bigger than it); on the compute path with its transient
  // buffers.
  std::optional<double> memory_ratio;
  // kShaderCost: the rule's cost term, the highest-precedence input for the path (its unit).
  std::optional<double> instructions;
  std::string cost_label;  // the cost input's label ("TCS + TES instructions")
  Watertightness cpu = Watertightness::kNotMeasured;     // kCrackPoints rows of the CPU
  Watertightness device = Watertightness::kNotMeasured;  // and of the device
  double cpu_points = 0;     // largest figure of one CPU row (points that differ)
  double device_points = 0;  // the same over the device rows
};

// How the report names the rule's terms: the labels of the inputs the run declares.
struct DecisionLabels {
  std::string error, triangles, cost, memory;  // an undeclared role: its spelling
};
DecisionLabels decisionLabels(const results::Results& results);

// The pipeline's path a candidate is drawn through: the hardware tessellator (TCS/TES), or the
// compute path (core/gpu/compute_path.h), a candidate where the run measured it (cracks rows
// with path = compute).
using results::kComputePath;
using results::kTessellatorPath;

struct DecisionCandidate {
  std::string technique;
  std::string variant;
  DecisionFigures figures;
  bool on_front = false;  // no other candidate has lower-or-equal error and triangles, one lower
  std::string path = kTessellatorPath;
  // "acc/default", "acc/default (compute path)".
  std::string name() const {
    return technique + "/" + variant + (path == kComputePath ? " (compute path)" : "");
  }
};

struct AssetDecision {
  std::string asset;
  std::vector<DecisionCandidate> candidates;  // by kDecisionRule: the first is recommended
  std::string why;                            // one sentence: why the recommendation ranks first
  std::string runner_up;                      // one sentence: what the runner-up trades against it
  std::string error_axis;  // "error: hausdorff (rel_diag)": the error figure's label and unit
  std::string recommended() const { return candidates.empty() ? "" : candidates[0].name(); }
};

// The figures of one record (technique, variant, asset), read from its rows.
// On the compute path: memory adds its transient buffers (memory rows with path = compute),
// instructions are its compute shader's build and evaluate passes', the device's
// watertightness is its cracks rows'; error and triangles at 1 px are the same surface's and
// the same policies' levels as the tessellator path's.
DecisionFigures decisionFigures(const results::Results& results, const std::string& technique,
                                const std::string& variant, const std::string& asset,
                                const std::string& path = kTessellatorPath);

// kDecisionRule as an order: true when a ranks before b (names not compared).
bool decisionBefore(const DecisionFigures& a, const DecisionFigures& b);

// The candidates of `asset` (default, non-control variants of the techniques with an error
// result on it), ranked, with the front marked; no candidates for a simulation's scenario.
AssetDecision decideAsset(const results::Results& results, const std::string& asset);

// Every asset of the run with at least one candidate, in the run's asset order.
std::vector<AssetDecision> decideAssets(const results::Results& results);

// "yes", "no (208)", "unverified", "not measured": one side's watertightness.
std::string watertightText(Watertightness side, double points);

}  // namespace tb::report
