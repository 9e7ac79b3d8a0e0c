// Markdown rendering of the results model (report.md). Reads only the model.
#pragma once

#include <string>

#include "harness/results/results_model.h"

namespace tb::report {

std::string renderMarkdown(const results::Results& results);

// "1.50 MiB", "812 B": binary units, three significant digits past the integer part.
std::string formatBytes(double bytes);
// Integers print without a fraction; other values with 4 significant digits.
std::string formatMetricValue(const results::Metric& metric);

}  // namespace tb::report
