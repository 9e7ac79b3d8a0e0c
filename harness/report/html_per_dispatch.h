// report.html's convergence per dispatch: a solver's residual against the compute dispatches
// it has spent (iteration x dispatches_per_iteration), one chart per scenario, the goal
// springs off. A frame's budget is dispatches, so this is the chart a solver is chosen by
// (8 per frame); the declared chart per iteration favours the solvers whose iteration costs
// more dispatches. Internal to harness/report.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "harness/results/results_model.h"

namespace tb::report {

// Appends the section (canvases to `body`, data to `charts` in html_chart_script.h's format)
// when the run has convergence rows; nothing otherwise. Without Chart.js only the text.
void appendPerDispatchCharts(const results::Results& results, bool charts_available,
                             std::string* body, nlohmann::ordered_json* charts);

}  // namespace tb::report
