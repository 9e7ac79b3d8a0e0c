// Reading the figures measures declare for decisions (results::DecisionInput): the one place
// harness/report turns rows into a decision's figure. Readers ask for a role, never for a
// measure or a metric by name.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

// An input with the declaration that carries it (its measure's rows are the ones read).
struct DeclaredInput {
  const results::MeasureDeclaration* declaration = nullptr;
  const results::DecisionInput* input = nullptr;
  const std::string& measure() const { return declaration->measure; }
};

// Every declared input of `role`, in the run's declaration order.
std::vector<DeclaredInput> inputsOf(const results::Results& results, results::DecisionRole role);
// The input of `role` for candidates on `path`: the highest precedence of the run's inputs for
// that path (the first declared on a tie); a compute candidate falls back to the tessellator's.
std::optional<DeclaredInput> inputFor(const results::Results& results, results::DecisionRole role,
                                      const std::string& path = results::kTessellatorPath);

// The record's result of the input's measure; null when the record has none.
const results::MeasureResult* resultOf(const results::Record& record, const DeclaredInput& input);
const results::MeasureResult* resultOf(const results::Results& results,
                                       const std::string& technique, const std::string& variant,
                                       const std::string& asset, const DeclaredInput& input);

// Whether `row` (ok) is one the input reads on `path`: its scopes, valid flag and path.
bool readsRow(const results::DecisionInput& input, const results::MetricRow& row,
              const std::string& path = results::kTessellatorPath);
// The row's figure: the sum of the input's metrics (over `per`); none without the first.
std::optional<double> rowFigure(const results::DecisionInput& input, const results::MetricRow& row);
// The row's value of the input's i-th metric (kCrackPlace, kPublished*: metrics by position).
std::optional<double> metricAt(const results::DecisionInput& input, const results::MetricRow& row,
                               size_t i);

// One record's figure of an input: its rows reduced; control rows never read.
struct InputFigure {
  std::optional<double> value;
  std::string chosen;  // the chosen row's DecisionInput::chosen_key value
  std::string first;   // the DecisionInput::first_of value read
  size_t rows = 0;     // rows read
};
InputFigure readInput(const DeclaredInput& input, const results::MeasureResult& result,
                      const std::string& path = results::kTessellatorPath);

// "adaptivity: triangle_ratio_vs_uniform, summary rows (summary = max_error_1px)": where an
// input's figure comes from, for a report's source line.
std::string sourceOf(const DeclaredInput& input);
// "error (hausdorff, rel_diag)": a column header of the input's figure.
std::string headerOf(const DeclaredInput& input);
// The unit's spelling of the input's first metric ("rel_diag"); "" when undeclared.
std::string unitOf(const DeclaredInput& input);

}  // namespace tb::report
