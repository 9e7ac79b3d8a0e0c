// Small builders of the results model for the report-layer tests (advice, tables).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::testing {

inline results::MeasureResult measureResult(const char* id) {
  results::MeasureResult m;
  m.measure = id;
  return m;
}

// An ok row with `keys` and unit-less metrics (the declaration gives units).
inline results::MetricRow row(std::map<std::string, std::string> keys,
                              std::vector<std::pair<std::string, double>> metrics) {
  results::MetricRow r;
  r.keys = std::move(keys);
  for (const auto& [name, value] : metrics) r.metrics.push_back({name, value, ""});
  return r;
}

}  // namespace tb::testing
