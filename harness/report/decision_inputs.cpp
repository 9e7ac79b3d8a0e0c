#include "harness/report/decision_inputs.h"

#include <fmt/format.h>

#include <algorithm>

#include "harness/report/row_values.h"

namespace tb::report {

using results::DecisionInput;
using results::DecisionReduce;
using results::MetricRow;

std::vector<DeclaredInput> inputsOf(const results::Results& results, results::DecisionRole role) {
  std::vector<DeclaredInput> found;
  for (const results::MeasureDeclaration& declaration : results.measures) {
    for (const DecisionInput& input : declaration.decision_inputs) {
      if (input.role == role) found.push_back({&declaration, &input});
    }
  }
  return found;
}

std::optional<DeclaredInput> inputFor(const results::Results& results, results::DecisionRole role,
                                      const std::string& path) {
  std::optional<DeclaredInput> best;
  for (const DeclaredInput& candidate : inputsOf(results, role)) {
    if (candidate.input->path != path) continue;
    if (!best || candidate.input->precedence > best->input->precedence) best = candidate;
  }
  if (!best && path != results::kTessellatorPath) return inputFor(results, role);
  return best;
}

const results::MeasureResult* resultOf(const results::Record& record, const DeclaredInput& input) {
  for (const results::MeasureResult& m : record.measures) {
    if (m.measure == input.measure()) return &m;
  }
  return nullptr;
}

const results::MeasureResult* resultOf(const results::Results& results,
                                       const std::string& technique, const std::string& variant,
                                       const std::string& asset, const DeclaredInput& input) {
  for (const results::Record& record : results.records) {
    if (record.technique == technique && record.variant == variant && record.asset == asset) {
      if (const results::MeasureResult* m = resultOf(record, input)) return m;
    }
  }
  return nullptr;
}

bool readsRow(const DecisionInput& input, const MetricRow& row, const std::string& path) {
  if (!results::rowInScope(input.where, row.keys)) return false;
  if (!input.any_of.empty() &&
      std::none_of(input.any_of.begin(), input.any_of.end(), [&](const results::RowScope& scope) {
        return results::rowInScope(scope, row.keys);
      }))
    return false;
  if (!input.valid_flag.empty() && rowMetric(row, input.valid_flag).value_or(1) == 0) return false;
  if (input.rows_on_path) {
    const std::string key = rowKey(row, results::kPathKey);
    if (key != path && !(key.empty() && path == results::kTessellatorPath)) return false;
  }
  return true;
}

std::optional<double> rowFigure(const DecisionInput& input, const MetricRow& row) {
  if (input.metrics.empty()) return std::nullopt;
  const auto first = rowMetric(row, input.metrics.front());
  if (!first) return std::nullopt;
  double sum = *first;
  for (size_t i = 1; i < input.metrics.size(); ++i)
    sum += rowMetric(row, input.metrics[i]).value_or(0);
  if (input.per.empty()) return sum;
  const auto per = rowMetric(row, input.per);
  if (!per || *per <= 0) return std::nullopt;
  return sum / *per;
}

std::optional<double> metricAt(const DecisionInput& input, const MetricRow& row, size_t i) {
  if (i >= input.metrics.size()) return std::nullopt;
  return rowMetric(row, input.metrics[i]);
}

InputFigure readInput(const DeclaredInput& declared, const results::MeasureResult& result,
                      const std::string& path) {
  InputFigure figure;
  if (result.status != results::MeasureStatus::kOk) return figure;
  const DecisionInput& input = *declared.input;
  for (const MetricRow& row : result.rows) {
    if (row.status != results::MeasureStatus::kOk || !readsRow(input, row, path)) continue;
    if (results::isControlRow(*declared.declaration, row.keys)) continue;
    const auto value = rowFigure(input, row);
    if (!value) continue;
    if (!input.first_of.empty()) {
      const std::string key = rowKey(row, input.first_of);
      if (figure.first.empty()) figure.first = key;
      if (key != figure.first) continue;
    }
    ++figure.rows;
    bool chosen = !figure.value;
    switch (input.reduce) {
      case DecisionReduce::kMax:
        chosen = chosen || *value > *figure.value;
        break;
      case DecisionReduce::kMin:
        chosen = chosen || *value < *figure.value;
        break;
      case DecisionReduce::kSum:
        figure.value = figure.value.value_or(0) + *value;
        continue;
      case DecisionReduce::kLast:
        chosen = true;
        break;
    }
    if (!chosen) continue;
    figure.value = value;
    if (!input.chosen_key.empty()) figure.chosen = rowKey(row, input.chosen_key);
  }
  return figure;
}

namespace {

std::string scopeText(const results::RowScope& scope) {
  std::string text;
  for (const auto& [key, value] : scope) {
    text += (text.empty() ? "" : ", ") + key + " = " + value;
  }
  return text;
}

}  // namespace

std::string sourceOf(const DeclaredInput& declared) {
  const DecisionInput& input = *declared.input;
  std::string metrics;
  for (const std::string& metric : input.metrics)
    metrics += (metrics.empty() ? "" : " + ") + metric;
  if (!input.per.empty()) metrics = "(" + metrics + ") / " + input.per;
  std::string text = declared.measure() + ": " + metrics;
  if (!input.where.empty()) text += ", rows " + scopeText(input.where);
  return text;
}

std::string unitOf(const DeclaredInput& declared) {
  if (declared.input->metrics.empty()) return "";
  const results::MetricSpec* spec = declared.declaration->find(declared.input->metrics.front());
  return spec == nullptr ? "" : std::string(results::toString(spec->unit));
}

std::string headerOf(const DeclaredInput& declared) {
  const DecisionInput& input = *declared.input;
  if (!input.column.empty()) return input.column;
  const std::string unit = input.per.empty() ? unitOf(declared) : "ratio";
  if (input.metrics.size() == 1 && input.per.empty()) {
    return fmt::format("{} ({}, {})", input.label, input.metrics.front(), unit);
  }
  return fmt::format("{} ({})", input.label, unit);
}

}  // namespace tb::report
