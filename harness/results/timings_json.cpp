#include "harness/results/timings_json.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace tb::results {
namespace {

using Json = nlohmann::ordered_json;

const Json& field(const Json& object, const char* name) {
  if (!object.is_object() || !object.contains(name)) {
    throw std::runtime_error(std::string("missing field '") + name + "'");
  }
  return object.at(name);
}

TimingEntry entryFromJson(const Json& item) {
  TimingEntry entry;
  entry.technique = field(item, "technique").get<std::string>();
  entry.variant = field(item, "variant").get<std::string>();
  entry.asset = field(item, "asset").get<std::string>();
  entry.measure = field(item, "measure").get<std::string>();
  if (item.contains("samples")) {
    entry.samples = item.at("samples").get<std::vector<double>>();
  } else {
    entry.samples = {field(item, "seconds").get<double>()};
  }
  if (entry.samples.empty()) throw std::runtime_error("an entry has no samples");
  return entry;
}

}  // namespace

std::string serializeTimings(const RunTimings& timings) {
  Json rows = Json::array();
  for (const TimingEntry& t : timings.measures) {
    rows.push_back({{"technique", t.technique},
                    {"variant", t.variant},
                    {"asset", t.asset},
                    {"measure", t.measure},
                    {"seconds", t.samples.empty() ? 0.0 : t.samples.front()},
                    {"samples", t.samples}});
  }
  const Json json{{"wall_seconds", timings.wall_seconds},
                  {"threads", timings.threads},
                  {"repetitions", timings.repetitions},
                  {"device", timings.device},
                  {"measures", rows}};
  return json.dump(1) + "\n";
}

RunTimings readTimingsFile(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot open timings file");
  try {
    const Json document = Json::parse(file);
    RunTimings timings;
    timings.wall_seconds = field(document, "wall_seconds").get<double>();
    timings.threads = field(document, "threads").get<int>();
    timings.repetitions = document.value("repetitions", 1);
    timings.device = document.value("device", std::string());
    for (const Json& item : field(document, "measures")) {
      timings.measures.push_back(entryFromJson(item));
    }
    return timings;
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(path + ": not a timings file (" + std::string(error.what()) + ")");
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
}

}  // namespace tb::results
