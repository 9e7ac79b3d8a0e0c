// Collects the run context (host, CPU, compiler, library versions) for results.json.
#pragma once

#include <string>

#include "harness/results/results_model.h"

namespace tb::cli {

// device_name: --device substring; empty picks the best device (lavapipe here).
results::RunContext probeRunContext(const std::string& command_line,
                                    const std::string& device_name);

}  // namespace tb::cli
