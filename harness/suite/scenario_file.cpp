#include "harness/suite/scenario_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "core/mesh/input_error.h"
#include "harness/suite/asset_catalog.h"

namespace tb::suite {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr const char* kFormat = "tessbench-scenario-1";

Json parseScenarioText(const std::string& path, const std::string& shown) {
  if (!fs::is_regular_file(path)) throw mesh::InputError(shown, "", "no such file");
  std::ifstream stream(path);
  if (!stream) throw mesh::InputError(shown, "", "cannot be read");
  const std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  try {
    return Json::parse(text);
  } catch (const Json::exception& error) {
    // "[json.exception.parse_error.101] parse error at line 2, ...": one line, no prefix.
    std::string what = error.what();
    if (const size_t end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
    for (char& c : what) c = (c == '\n' || c == '\r') ? ' ' : c;
    // A number beyond double's range (1e999) is how a file writes infinity.
    if (error.id == 406) throw mesh::InputError(shown, "", "not a finite number: " + what);
    throw mesh::InputError(shown, "", "malformed JSON: " + what);
  }
}

// A key as a message shows it: JSON-quoted when it holds a control character.
std::string shownKey(const std::string& key) {
  for (unsigned char c : key) {
    if (c < 0x20) return Json(key).dump();
  }
  return key;
}

double finiteNumber(const Json& value, const std::string& shown, const std::string& field) {
  if (!value.is_number()) {
    throw mesh::InputError(shown, field,
                           std::string("expected a number, got ") + value.type_name());
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw mesh::InputError(shown, field, "not a finite number");
  return number;
}

std::string text(const Json& value, const std::string& shown, const std::string& field) {
  if (!value.is_string()) {
    throw mesh::InputError(shown, field,
                           std::string("expected a string, got ") + value.type_name());
  }
  return value.get<std::string>();
}

const Json& required(const Json& object, const std::string& shown, const char* key) {
  if (!object.contains(key)) throw mesh::InputError(shown, key, "missing");
  return object.at(key);
}

std::string resolveMesh(const std::string& mesh, const std::string& path,
                        const std::string& shown) {
  if (mesh.empty()) throw mesh::InputError(shown, "mesh", "empty");
  const fs::path relative = fs::path(path).parent_path() / mesh;
  if (fs::is_regular_file(relative)) return fs::absolute(relative).lexically_normal().string();
  try {
    return fs::absolute(resolveAsset(mesh).path).lexically_normal().string();
  } catch (const mesh::InputError&) {
    throw mesh::InputError(
        shown, "mesh", "'" + mesh + "' is neither a file beside the scenario nor a bundled asset");
  }
}

}  // namespace

techniques::Scenario loadScenarioFile(const std::string& path, const std::string& shown_path) {
  const std::string& shown = shown_path.empty() ? path : shown_path;
  const Json json = parseScenarioText(path, shown);
  if (!json.is_object()) throw mesh::InputError(shown, "", "expected a JSON object");
  if (text(required(json, shown, "format"), shown, "format") != kFormat) {
    throw mesh::InputError(shown, "format", std::string("expected \"") + kFormat + "\"");
  }
  techniques::Scenario scenario;
  scenario.path = fs::absolute(path).lexically_normal().string();
  scenario.name = text(required(json, shown, "name"), shown, "name");
  if (scenario.name.empty()) throw mesh::InputError(shown, "name", "empty");
  scenario.time_step_s = finiteNumber(required(json, shown, "time_step_s"), shown, "time_step_s");
  if (!(scenario.time_step_s > 0)) throw mesh::InputError(shown, "time_step_s", "must be > 0");
  scenario.duration_s = finiteNumber(required(json, shown, "duration_s"), shown, "duration_s");
  if (!(scenario.duration_s >= scenario.time_step_s)) {
    throw mesh::InputError(shown, "duration_s", "must be >= time_step_s");
  }
  for (const auto& item : json.items()) {
    const std::string& key = item.key();
    const Json& value = item.value();
    if (key == "format" || key == "name" || key == "time_step_s" || key == "duration_s") continue;
    if (key == "technique") {
      scenario.technique = text(value, shown, key);
    } else if (key == "mesh") {
      scenario.mesh_path = resolveMesh(text(value, shown, key), path, shown);
    } else if (key == "parameters") {
      if (!value.is_object()) throw mesh::InputError(shown, key, "expected an object of numbers");
      for (const auto& parameter : value.items()) {
        const std::string field = "parameters." + shownKey(parameter.key());
        scenario.parameters[parameter.key()] = finiteNumber(parameter.value(), shown, field);
      }
    } else if (value.is_object()) {
      scenario.sections[key] = value.dump();
    } else {
      throw mesh::InputError(
          shown, shownKey(key),
          "unknown field (known: format, name, technique, time_step_s, duration_s, "
          "parameters, mesh, and technique sections as objects)");
    }
  }
  return scenario;
}

std::string scenariosDirectory() { return (fs::path(assetsDirectory()) / "scenarios").string(); }

std::vector<std::string> bundledScenarioNames() {
  std::vector<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(scenariosDirectory(), error), end; !error && it != end;
       it.increment(error)) {
    if (it->is_regular_file() && it->path().extension() == ".json") {
      names.push_back(it->path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<techniques::Scenario> bundledScenarios() {
  std::vector<techniques::Scenario> scenarios;
  for (const std::string& name : bundledScenarioNames()) scenarios.push_back(resolveScenario(name));
  std::sort(
      scenarios.begin(), scenarios.end(),
      [](const techniques::Scenario& a, const techniques::Scenario& b) { return a.name < b.name; });
  return scenarios;
}

techniques::Scenario resolveScenario(const std::string& name_or_path) {
  const std::vector<std::string> bundled = bundledScenarioNames();
  if (std::find(bundled.begin(), bundled.end(), name_or_path) != bundled.end()) {
    // Named relative to the assets folder, so messages do not depend on the checkout.
    return loadScenarioFile((fs::path(scenariosDirectory()) / (name_or_path + ".json")).string(),
                            "assets/scenarios/" + name_or_path + ".json");
  }
  if (fs::is_regular_file(name_or_path)) return loadScenarioFile(name_or_path, name_or_path);
  std::string names;
  for (const std::string& name : bundled) names += (names.empty() ? "" : ", ") + name;
  throw mesh::InputError(name_or_path, "",
                         "no such file, and not a bundled scenario (bundled: " + names + ")");
}

}  // namespace tb::suite
