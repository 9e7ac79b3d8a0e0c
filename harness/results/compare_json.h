// `tessbench compare --json`: a comparison as one JSON document, for scripts. Key order is
// fixed; a p-value that was not computed (a deterministic figure) is null.
//
//   {"failed": false, "figures_compared": 120, "counts": {"missing": 0, ...},
//    "changes": [{"kind", "record", "measure", "row", "metric", "base", "new",
//                 "relative_change", "p_value", "why"}],
//    "timings": [{"kind", "record", "measure", "base_samples", "new_samples", "base", "new",
//                 "p_value"}], "timing_notes": [...], "context_notes": [...]}
#pragma once

#include <nlohmann/json.hpp>

#include "harness/results/compare.h"

namespace tb::results {

nlohmann::ordered_json comparisonToJson(const Comparison& comparison);

}  // namespace tb::results
