#include "harness/results/results_json.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "harness/results/json_field.h"

namespace tb::results {
namespace {

using Json = nlohmann::ordered_json;
using json_detail::field;

// A metric value as JSON: an integral value as an integer ("12", not "12.0"), anything
// else as a double in its shortest round-trip form.
Json metricValueToJson(double value) {
  constexpr double kLargestExactInteger = 9007199254740992.0;  // 2^53
  if (std::isfinite(value) && value == std::floor(value) &&
      std::fabs(value) < kLargestExactInteger && !(value == 0 && std::signbit(value))) {
    return static_cast<int64_t>(value);
  }
  return value;
}

// A measure's rows as a table (schema 4): the key names and metric names once, then one
// array per row, [[key values], [metric values]] in those orders, null where the row has
// no such key or metric; a row that is not ok appends its status and reason. Units live
// in the measure's declaration (results.json's "measures"), not in every row.
Json measureToJson(const MeasureResult& measure) {
  std::vector<std::string> key_names;
  std::vector<std::string> metric_names;
  std::map<std::string, size_t> metric_index;
  {
    std::set<std::string> keys;
    for (const MetricRow& row : measure.rows) {
      for (const auto& [key, value] : row.keys) keys.insert(key);
      for (const Metric& metric : row.metrics) {
        if (metric_index.emplace(metric.name, metric_names.size()).second) {
          metric_names.push_back(metric.name);
        }
      }
    }
    key_names.assign(keys.begin(), keys.end());
  }
  Json rows = Json::array();
  for (const MetricRow& row : measure.rows) {
    Json keys = Json::array();
    for (const std::string& key : key_names) {
      const auto it = row.keys.find(key);
      keys.push_back(it == row.keys.end() ? Json() : Json(it->second));
    }
    Json values(Json::value_t::array);
    values.get_ref<Json::array_t&>().resize(metric_names.size());
    for (const Metric& metric : row.metrics) {
      values[metric_index.at(metric.name)] = metricValueToJson(metric.value);
    }
    Json line = Json::array({keys, values});
    // Most rows are ok; only the others spend bytes on saying so.
    if (row.status != MeasureStatus::kOk) {
      line.push_back(toString(row.status));
      line.push_back(row.reason);
    }
    rows.push_back(std::move(line));
  }
  return {{"measure", measure.measure},
          {"status", toString(measure.status)},
          {"reason", measure.reason},
          {"notes", measure.notes},
          {"keys", key_names},
          {"metrics", metric_names},
          {"rows", rows}};
}

Json recordToJson(const Record& record) {
  Json parameters = Json::object();
  for (const auto& [key, value] : record.parameters) parameters[key] = value;
  Json measures = Json::array();
  for (const MeasureResult& measure : record.measures) measures.push_back(measureToJson(measure));
  return {{"technique", record.technique}, {"variant", record.variant},   {"asset", record.asset},
          {"parameters", parameters},      {"warnings", record.warnings}, {"measures", measures}};
}

MeasureResult measureFromJson(const Json& json, const std::string& where) {
  MeasureResult measure;
  measure.measure = field<std::string>(json, "measure", where);
  const auto status = parseMeasureStatus(field<std::string>(json, "status", where));
  if (!status) throw std::runtime_error(where + ": unknown status");
  measure.status = *status;
  measure.reason = field<std::string>(json, "reason", where);
  measure.notes = field<std::vector<std::string>>(json, "notes", where);
  const auto key_names = field<std::vector<std::string>>(json, "keys", where);
  const auto metric_names = field<std::vector<std::string>>(json, "metrics", where);
  const Json rows = field<Json>(json, "rows", where);
  if (!rows.is_array()) throw std::runtime_error(where + ": field 'rows' has the wrong type");
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string at = where + ".rows[" + std::to_string(i) + "]";
    const Json& line = rows[i];
    if (!line.is_array() || (line.size() != 2 && line.size() != 4) || !line[0].is_array() ||
        !line[1].is_array() || line[0].size() != key_names.size() ||
        line[1].size() != metric_names.size()) {
      throw std::runtime_error(at + ": expected [[" + std::to_string(key_names.size()) +
                               " keys], [" + std::to_string(metric_names.size()) +
                               " metrics]] (and a status and reason when not ok)");
    }
    MetricRow row;
    for (size_t k = 0; k < key_names.size(); ++k) {
      if (line[0][k].is_null()) continue;
      if (!line[0][k].is_string()) throw std::runtime_error(at + ": key values are strings");
      row.keys[key_names[k]] = line[0][k].get<std::string>();
    }
    for (size_t m = 0; m < metric_names.size(); ++m) {
      if (line[1][m].is_null()) continue;
      if (!line[1][m].is_number()) throw std::runtime_error(at + ": metric values are numbers");
      row.metrics.push_back({metric_names[m], line[1][m].get<double>(), ""});
    }
    if (line.size() == 4) {
      const auto row_status =
          line[2].is_string() ? parseMeasureStatus(line[2].get<std::string>()) : std::nullopt;
      if (!row_status || !line[3].is_string()) {
        throw std::runtime_error(at + ": expected a status and a reason after the metrics");
      }
      row.status = *row_status;
      row.reason = line[3].get<std::string>();
    }
    measure.rows.push_back(std::move(row));
  }
  return measure;
}

// Rows carry no units (schema 4): each metric takes its unit from its measure's declaration.
void assignDeclaredUnits(Results* results) {
  for (Record& record : results->records) {
    for (MeasureResult& measure : record.measures) {
      const MeasureDeclaration* declaration = results->findMeasure(measure.measure);
      if (declaration == nullptr) continue;
      for (MetricRow& row : measure.rows) {
        for (Metric& metric : row.metrics) {
          if (const MetricSpec* spec = declaration->find(metric.name)) {
            metric.unit = std::string(toString(spec->unit));
          }
        }
      }
    }
  }
}

Record recordFromJson(const Json& json, const std::string& where) {
  Record record;
  record.technique = field<std::string>(json, "technique", where);
  record.variant = field<std::string>(json, "variant", where);
  record.asset = field<std::string>(json, "asset", where);
  record.parameters = field<std::map<std::string, std::string>>(json, "parameters", where);
  record.warnings = field<std::vector<std::string>>(json, "warnings", where);
  const Json measures = field<Json>(json, "measures", where);
  for (size_t i = 0; i < measures.size(); ++i) {
    record.measures.push_back(
        measureFromJson(measures[i], where + ".measures[" + std::to_string(i) + "]"));
  }
  return record;
}

Json shardToJson(const ShardId& shard) { return {{"index", shard.index}, {"count", shard.count}}; }

ShardId shardFromJson(const Json& json, const std::string& where) {
  return {field<size_t>(json, "index", where), field<size_t>(json, "count", where)};
}

Json selectionToJson(const RunSelection& selection) {
  Json techniques = Json::array();
  for (const auto& technique : selection.techniques) {
    Json entry{{"technique", technique.technique}, {"variants", technique.variants}};
    if (!technique.controls.empty()) entry["controls"] = technique.controls;
    techniques.push_back(std::move(entry));
  }
  Json json{{"techniques", techniques},
            {"assets", selection.assets},
            {"measures", selection.measures},
            {"suite", selection.suite}};
  if (!selection.camera_paths.empty()) json["camera_paths"] = selection.camera_paths;
  return json;
}

RunSelection selectionFromJson(const Json& json) {
  RunSelection selection;
  const Json techniques = field<Json>(json, "techniques", "context.selection");
  for (size_t i = 0; i < techniques.size(); ++i) {
    const std::string at = "context.selection.techniques[" + std::to_string(i) + "]";
    selection.techniques.push_back(
        {field<std::string>(techniques[i], "technique", at),
         field<std::vector<std::string>>(techniques[i], "variants", at)});
    if (techniques[i].contains("controls")) {  // absent: none, or results before controls
      selection.techniques.back().controls =
          field<std::vector<std::string>>(techniques[i], "controls", at);
    }
  }
  selection.assets = field<std::vector<std::string>>(json, "assets", "context.selection");
  selection.measures = field<std::vector<std::string>>(json, "measures", "context.selection");
  // Optional: absent in results written before `run --suite` and `run --camera`.
  if (json.contains("suite")) {
    selection.suite = field<std::string>(json, "suite", "context.selection");
  }
  if (json.contains("camera_paths")) {
    selection.camera_paths =
        field<std::vector<std::string>>(json, "camera_paths", "context.selection");
  }
  return selection;
}

// The shard fields of the context: optional, so results written before sharding read as
// unsharded runs with an empty selection.
void shardFieldsToJson(const RunContext& c, Json* context) {
  (*context)["selection"] = selectionToJson(c.selection);
  if (c.shard.count > 0) (*context)["shard"] = shardToJson(c.shard);
  if (c.merged_from.empty()) return;
  Json sources = Json::array();
  for (const ShardSource& source : c.merged_from) {
    sources.push_back({{"shard", shardToJson(source.shard)},
                       {"run_id", source.run_id},
                       {"date", source.date},
                       {"host", source.host},
                       {"folder", source.folder}});
  }
  (*context)["merged_from"] = sources;
}

void shardFieldsFromJson(const Json& context, RunContext* c) {
  if (context.contains("selection")) c->selection = selectionFromJson(context.at("selection"));
  if (context.contains("shard")) c->shard = shardFromJson(context.at("shard"), "context.shard");
  if (!context.contains("merged_from")) return;
  const Json sources = field<Json>(context, "merged_from", "context");
  for (size_t i = 0; i < sources.size(); ++i) {
    const std::string at = "context.merged_from[" + std::to_string(i) + "]";
    c->merged_from.push_back(
        {shardFromJson(field<Json>(sources[i], "shard", at), at + ".shard"),
         field<std::string>(sources[i], "run_id", at), field<std::string>(sources[i], "date", at),
         field<std::string>(sources[i], "host", at), field<std::string>(sources[i], "folder", at)});
  }
}

}  // namespace

const char* toString(MeasureStatus status) {
  switch (status) {
    case MeasureStatus::kOk:
      return "ok";
    case MeasureStatus::kSkipped:
      return "skipped";
    case MeasureStatus::kFailed:
      return "failed";
  }
  return "unknown";
}

MetricRow unmeasuredRow(std::map<std::string, std::string> keys, MeasureStatus status,
                        std::string reason) {
  MetricRow row;
  row.keys = std::move(keys);
  row.status = status;
  row.reason = std::move(reason);
  return row;
}

std::optional<MeasureStatus> parseMeasureStatus(const std::string& text) {
  if (text == "ok") return MeasureStatus::kOk;
  if (text == "skipped") return MeasureStatus::kSkipped;
  if (text == "failed") return MeasureStatus::kFailed;
  return std::nullopt;
}

Json toJson(const Results& results) {
  const RunContext& c = results.context;
  Json libraries = Json::object();
  for (const auto& [name, version] : c.libraries) libraries[name] = version;
  Json context = {{"date", c.date},
                  {"run_id", c.run_id},
                  {"git_sha", c.git_sha},
                  {"host", c.host},
                  {"cpu", c.cpu},
                  {"compiler", c.compiler},
                  {"build_type", c.build_type},
                  {"libraries", libraries},
                  {"vulkan_device", c.vulkan_device},
                  {"command_line", c.command_line}};
  if (!c.commit_time.empty()) context["commit_time"] = c.commit_time;
  shardFieldsToJson(c, &context);
  Json assets = Json::array();
  for (const AssetSummary& a : results.assets) {
    Json asset = {{"name", a.name},
                  {"path", a.path},
                  {"faces", a.faces},
                  {"vertices", a.vertices},
                  {"face_kinds", a.face_kinds},
                  {"normals_computed", a.normals_computed}};
    if (!a.warnings.empty()) asset["warnings"] = a.warnings;
    assets.push_back(std::move(asset));
  }
  Json records = Json::array();
  for (const Record& record : results.records) records.push_back(recordToJson(record));
  Json skipped = Json::array();
  for (const Skip& skip : results.skipped) {
    skipped.push_back(
        {{"technique", skip.technique}, {"asset", skip.asset}, {"reason", skip.reason}});
  }
  Json measures = Json::array();
  for (const MeasureDeclaration& declaration : results.measures) {
    measures.push_back(toJson(declaration));
  }
  return {{"schema_version", results.schema_version},
          {"context", context},
          {"assets", assets},
          {"records", records},
          {"skipped", skipped},
          {"measures", measures}};
}

Results resultsFromJson(const Json& document) {
  Results results;
  results.schema_version = field<int>(document, "schema_version", "results");
  if (results.schema_version != kResultsSchemaVersion) {
    throw std::runtime_error("results: schema_version " + std::to_string(results.schema_version) +
                             " is not the supported " + std::to_string(kResultsSchemaVersion));
  }
  const Json context = field<Json>(document, "context", "results");
  RunContext& c = results.context;
  c.date = field<std::string>(context, "date", "context");
  c.run_id = field<std::string>(context, "run_id", "context");
  c.git_sha = field<std::string>(context, "git_sha", "context");
  c.host = field<std::string>(context, "host", "context");
  c.cpu = field<std::string>(context, "cpu", "context");
  c.compiler = field<std::string>(context, "compiler", "context");
  c.build_type = field<std::string>(context, "build_type", "context");
  c.libraries = field<std::map<std::string, std::string>>(context, "libraries", "context");
  c.vulkan_device = field<std::string>(context, "vulkan_device", "context");
  c.command_line = field<std::string>(context, "command_line", "context");
  if (context.contains("commit_time"))
    c.commit_time = field<std::string>(context, "commit_time", "context");
  shardFieldsFromJson(context, &c);

  const Json assets = field<Json>(document, "assets", "results");
  for (size_t i = 0; i < assets.size(); ++i) {
    const std::string at = "assets[" + std::to_string(i) + "]";
    results.assets.push_back(
        {field<std::string>(assets[i], "name", at), field<std::string>(assets[i], "path", at),
         field<size_t>(assets[i], "faces", at), field<size_t>(assets[i], "vertices", at),
         field<std::string>(assets[i], "face_kinds", at),
         field<bool>(assets[i], "normals_computed", at)});
    if (assets[i].contains("warnings")) {
      results.assets.back().warnings = field<std::vector<std::string>>(assets[i], "warnings", at);
    }
  }
  const Json records = field<Json>(document, "records", "results");
  for (size_t i = 0; i < records.size(); ++i) {
    results.records.push_back(recordFromJson(records[i], "records[" + std::to_string(i) + "]"));
  }
  const Json skipped = field<Json>(document, "skipped", "results");
  for (size_t i = 0; i < skipped.size(); ++i) {
    const std::string at = "skipped[" + std::to_string(i) + "]";
    results.skipped.push_back({field<std::string>(skipped[i], "technique", at),
                               field<std::string>(skipped[i], "asset", at),
                               field<std::string>(skipped[i], "reason", at)});
  }
  const Json measures = field<Json>(document, "measures", "results");
  for (size_t i = 0; i < measures.size(); ++i) {
    results.measures.push_back(
        declarationFromJson(measures[i], "measures[" + std::to_string(i) + "]"));
  }
  assignDeclaredUnits(&results);
  return results;
}

const MeasureDeclaration* Results::findMeasure(const std::string& id) const {
  for (const MeasureDeclaration& declaration : measures) {
    if (declaration.measure == id) return &declaration;
  }
  return nullptr;
}

Json toJson(const MeasureResult& measure) { return measureToJson(measure); }

MeasureResult measureResultFromJson(const Json& json, const std::string& where) {
  return measureFromJson(json, where);
}

std::string recordJsonLine(const Record& record) { return recordToJson(record).dump(); }

namespace {

// Nesting depth of arrays in `json` (a scalar 0, [1, 2] 1, [[a], [1]] 2); an object
// counts as too deep to inline.
int arrayDepth(const Json& json) {
  constexpr int kObject = 1000;
  if (json.is_object()) return kObject;
  if (!json.is_array()) return 0;
  int deepest = 0;
  for (const Json& item : json) deepest = std::max(deepest, arrayDepth(item));
  return deepest + 1;
}

// Pretty-prints like dump(2), except that an array of at most two levels holding no object
// goes on one line (a row [[keys], [metrics]], a list of names): one row per line, a few
// MB for the default suite.
void dumpCompactLeaves(const Json& json, int depth, std::string* out) {
  const std::string indent(static_cast<size_t>(2 * (depth + 1)), ' ');
  const std::string closing(static_cast<size_t>(2 * depth), ' ');
  if (json.is_object() && !json.empty()) {
    *out += "{\n";
    size_t i = 0;
    for (const auto& [key, value] : json.items()) {
      *out += indent + Json(key).dump() + ": ";
      dumpCompactLeaves(value, depth + 1, out);
      *out += ++i < json.size() ? ",\n" : "\n";
    }
    *out += closing + "}";
    return;
  }
  if (!json.is_array() || json.empty() || arrayDepth(json) <= 2) {
    *out += json.dump();
    return;
  }
  *out += "[\n";
  for (size_t i = 0; i < json.size(); ++i) {
    *out += indent;
    dumpCompactLeaves(json[i], depth + 1, out);
    *out += i + 1 < json.size() ? ",\n" : "\n";
  }
  *out += closing + "]";
}

}  // namespace

std::string serializeResults(const Results& results) {
  std::string out;
  dumpCompactLeaves(toJson(results), 0, &out);
  return out + "\n";
}

Results readResultsFile(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error(path + ": cannot open results file");
  Json document;
  try {
    document = Json::parse(file);
  } catch (const nlohmann::json::parse_error& error) {
    throw std::runtime_error(path + ": not valid JSON (" + std::string(error.what()) + ")");
  }
  try {
    return resultsFromJson(document);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
}

}  // namespace tb::results
