// Scenario files (JSON, format "tessbench-scenario-1"): the inputs of simulation
// techniques (techniques/simulation.h), bundled in assets/scenarios/*.json or given by
// path (`tessbench run --scenario NAME|PATH`). The format is in docs/FORMATS.md,
// "Scenario files". Every broken rule is one InputError naming the file and field.
#pragma once

#include <string>
#include <vector>

#include "techniques/simulation.h"

namespace tb::suite {

// Reads one scenario file. `shown_path` is how messages name the file (the path as given,
// or "assets/scenarios/<name>.json" for a bundled one); empty: `path`. The fields (format,
// name, technique, time_step_s, duration_s, parameters, mesh, technique sections) and their
// rules are in docs/FORMATS.md, "Scenario files"; any field the format does not know is
// refused.
techniques::Scenario loadScenarioFile(const std::string& path, const std::string& shown_path = "");

// The scenarios folder: <assetsDirectory()>/scenarios.
std::string scenariosDirectory();

// Names (file stems) of the bundled scenarios, sorted.
std::vector<std::string> bundledScenarioNames();

// Every bundled scenario, loaded, sorted by name. Throws InputError when one is bad.
std::vector<techniques::Scenario> bundledScenarios();

// A bundled scenario name or a path to a scenario file. Throws InputError naming the
// argument when it is neither.
techniques::Scenario resolveScenario(const std::string& name_or_path);

}  // namespace tb::suite
