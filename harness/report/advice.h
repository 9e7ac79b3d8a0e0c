// `tessbench advise`: ranks the technique × variant candidates of one asset under a reader's
// constraints (error, memory, watertightness, instructions). Pure over the results model:
// every figure is read through summarizeMeasure (summary.h) by metric name, so a candidate's
// figure is the worst value over the measure's summary scope.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

// What the reader asked for; an absent bound is no constraint.
struct AdviceConstraints {
  std::optional<double> max_error;         // worst hausdorff, fraction of the bbox diagonal
  std::optional<double> max_memory_ratio;  // worst technique bytes / plain mesh bytes
  // Every cracks row bitwise watertight (`advise` sets it unless --allow-cracks).
  bool watertight = false;
  std::optional<double> max_instructions;  // worst TES total instructions (spirv_O, vector)
  std::vector<std::string> techniques;     // only these techniques (empty: every one)
};

// The ranking rule, printed verbatim with every advice.
extern const char* const kAdviceRankingRule;
// What each figure is and its unit, printed with every advice.
std::string adviceFigureUnits(const results::Results& results);

enum class Watertightness {
  kNotMeasured,  // no cracks rows for the candidate
  kWatertight,   // every cracks row: points_not_equal == 0 and unpaired_points == 0
  kCracked,      // some row has a point not equal or unpaired
  kUnverified,   // the ok rows are watertight but some rows (the device's) were skipped or failed
};
const char* toString(Watertightness watertightness);  // "yes", "no", "unverified", "not measured"

// A candidate's figures, each the worst over the measure's summary scope; absent when the
// measure has no ok row for the candidate (`missing_*` says why).
struct CandidateFigures {
  std::optional<double> error;         // hausdorff, rel_diag (lower is better)
  std::optional<double> memory_ratio;  // 1 / plain_over_technique, ratio (lower is better)
  std::optional<double> instructions;  // total, count (lower is better)
  Watertightness watertight = Watertightness::kNotMeasured;
  double points_not_equal = 0;  // largest over the cracks rows (count); 0 when watertight
  double unpaired_points = 0;   // largest over the cracks rows (count); 0 when watertight
  std::string missing_error, missing_memory, missing_instructions, watertight_detail;
  bool memory_from_default = false;  // the default variant's figure (same patch data)
  bool error_from_default = false;   // the default variant's figure (same double surface)
};

struct Candidate {
  std::string technique;
  std::string variant;
  CandidateFigures figures;
  bool passes = false;
  std::vector<std::string> failures;  // every constraint failed, with by how much
  std::string verdict;                // "wins: ..." or "excluded: ..."
};

// A technique the run did not measure on the asset (Results::skipped), with its reason.
struct UnsupportedTechnique {
  std::string technique;
  std::string reason;
};

struct Advice {
  std::string asset;
  std::vector<Candidate> ranked;  // by kAdviceRankingRule: passing first
  std::string figure_units;       // adviceFigureUnits: what each figure is
  std::vector<UnsupportedTechnique> unsupported;
  // The report's recommendation for the asset (decision.h: default variants, kDecisionRule,
  // no constraints), its why and what the runner-up trades; empty without candidates.
  std::string recommendation, recommendation_why;
  bool anyPasses() const { return !ranked.empty() && ranked.front().passes; }
};

Advice rankCandidates(const results::Results& results, const std::string& asset,
                      const AdviceConstraints& constraints);

// A Markdown list: the constraints, the rule, the units, then one line per candidate and one
// per unsupported technique.
std::string renderAdviceMarkdown(const Advice& advice, const AdviceConstraints& constraints);

// Numbers as advice prints them: 4 significant digits, integers without a fraction.
std::string formatAdviceNumber(double value);

}  // namespace tb::report
