// Small builders of the results model for the report-layer tests (advice, tables).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "harness/measures/complete_declarations.h"
#include "harness/measures/measure.h"
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

// What a run of the registered measures declares: every measure the records name but `r`
// does not declare gets the registered measure's declaration, and every declaration its
// decision inputs (measures::completeDeclarations), as `tessbench report` reads a run.
inline void withRegisteredDeclarations(results::Results* r) {
  for (const results::Record& record : r->records) {
    for (const results::MeasureResult& m : record.measures) {
      if (r->findMeasure(m.measure) != nullptr) continue;
      if (const measures::Measure* measure = measures::MeasureRegistry::instance().find(m.measure))
        r->measures.push_back(measures::declarationOf(measure->info()));
    }
  }
  measures::completeDeclarations(r);
}

}  // namespace tb::testing
