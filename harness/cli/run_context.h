// Collects the run context (host, CPU, compiler, library versions) for results.json.
#pragma once

#include <string>

#include "harness/results/results_model.h"

namespace tb::cli {

RunContext probeRunContext(const std::string& command_line);

}  // namespace tb::cli
