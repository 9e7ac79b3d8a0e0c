// A row's key and metric values by name (harness/report's readers of measure rows).
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

inline std::optional<double> rowMetric(const results::MetricRow& row, const std::string& name) {
  for (const results::Metric& metric : row.metrics) {
    if (metric.name == name) return metric.value;
  }
  return std::nullopt;
}

// The row's value of key `name`; empty when the row has no such key.
inline std::string rowKey(const results::MetricRow& row, const std::string& name) {
  const auto it = row.keys.find(name);
  return it == row.keys.end() ? std::string() : it->second;
}

// The middle value, or the mean of the two middle ones; 0 for none.
inline double medianValue(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace tb::report
