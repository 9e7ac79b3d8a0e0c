#include "harness/results/results_json.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tb {
namespace {

using Json = nlohmann::ordered_json;

Json metricRowToJson(const MetricRow& row) {
  Json keys = Json::object();
  for (const auto& [key, value] : row.keys) keys[key] = value;
  Json metrics = Json::array();
  for (const Metric& metric : row.metrics) {
    metrics.push_back({{"name", metric.name}, {"value", metric.value}, {"unit", metric.unit}});
  }
  Json json{{"keys", keys}, {"metrics", metrics}};
  // Most rows are ok; only the others spend bytes on saying so.
  if (row.status != MeasureStatus::kOk) {
    json["status"] = toString(row.status);
    json["reason"] = row.reason;
  }
  return json;
}

Json measureToJson(const MeasureResult& measure) {
  Json rows = Json::array();
  for (const MetricRow& row : measure.rows) rows.push_back(metricRowToJson(row));
  return {{"measure", measure.measure},
          {"status", toString(measure.status)},
          {"reason", measure.reason},
          {"notes", measure.notes},
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

// Reads a required field, naming the path to it when it is missing or mistyped.
template <class T>
T field(const Json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) {
    throw std::runtime_error(where + ": missing field '" + key + "'");
  }
  try {
    return object.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error(where + ": field '" + key + "' has the wrong type");
  }
}

MetricRow metricRowFromJson(const Json& json, const std::string& where) {
  MetricRow row;
  row.keys = field<std::map<std::string, std::string>>(json, "keys", where);
  const Json metrics = field<Json>(json, "metrics", where);
  for (size_t i = 0; i < metrics.size(); ++i) {
    const std::string at = where + ".metrics[" + std::to_string(i) + "]";
    row.metrics.push_back({field<std::string>(metrics[i], "name", at),
                           field<double>(metrics[i], "value", at),
                           field<std::string>(metrics[i], "unit", at)});
  }
  if (json.contains("status")) {
    const auto status = parseMeasureStatus(field<std::string>(json, "status", where));
    if (!status) throw std::runtime_error(where + ": unknown status");
    row.status = *status;
    row.reason = field<std::string>(json, "reason", where);
  }
  return row;
}

MeasureResult measureFromJson(const Json& json, const std::string& where) {
  MeasureResult measure;
  measure.measure = field<std::string>(json, "measure", where);
  const auto status = parseMeasureStatus(field<std::string>(json, "status", where));
  if (!status) throw std::runtime_error(where + ": unknown status");
  measure.status = *status;
  measure.reason = field<std::string>(json, "reason", where);
  measure.notes = field<std::vector<std::string>>(json, "notes", where);
  const Json rows = field<Json>(json, "rows", where);
  for (size_t i = 0; i < rows.size(); ++i) {
    measure.rows.push_back(metricRowFromJson(rows[i], where + ".rows[" + std::to_string(i) + "]"));
  }
  return measure;
}

}  // namespace

Json toJson(const MeasureDeclaration& declaration) {
  Json metrics = Json::array();
  for (const MetricSpec& spec : declaration.metrics) {
    metrics.push_back({{"name", spec.name},
                       {"unit", toString(spec.unit)},
                       {"direction", toString(spec.direction)}});
  }
  return {{"measure", declaration.measure},
          {"title", declaration.title},
          {"description", declaration.description},
          {"headline", declaration.headline},
          {"notes", declaration.notes},
          {"metrics", metrics}};
}

namespace {

MeasureDeclaration declarationFromJson(const Json& json, const std::string& where) {
  MeasureDeclaration declaration;
  declaration.measure = field<std::string>(json, "measure", where);
  declaration.title = field<std::string>(json, "title", where);
  declaration.description = field<std::string>(json, "description", where);
  declaration.headline = field<std::vector<std::string>>(json, "headline", where);
  declaration.notes = field<std::vector<std::string>>(json, "notes", where);
  const Json metrics = field<Json>(json, "metrics", where);
  for (size_t i = 0; i < metrics.size(); ++i) {
    const std::string at = where + ".metrics[" + std::to_string(i) + "]";
    const auto unit = parseUnit(field<std::string>(metrics[i], "unit", at));
    if (!unit) throw std::runtime_error(at + ": unknown unit");
    const auto direction = parseDirection(field<std::string>(metrics[i], "direction", at));
    if (!direction) throw std::runtime_error(at + ": unknown direction");
    declaration.metrics.push_back({field<std::string>(metrics[i], "name", at), *unit, *direction});
  }
  return declaration;
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
    techniques.push_back({{"technique", technique.technique}, {"variants", technique.variants}});
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
  shardFieldsToJson(c, &context);
  Json assets = Json::array();
  for (const AssetSummary& a : results.assets) {
    assets.push_back({{"name", a.name},
                      {"path", a.path},
                      {"faces", a.faces},
                      {"vertices", a.vertices},
                      {"face_kinds", a.face_kinds},
                      {"normals_computed", a.normals_computed}});
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
  shardFieldsFromJson(context, &c);

  const Json assets = field<Json>(document, "assets", "results");
  for (size_t i = 0; i < assets.size(); ++i) {
    const std::string at = "assets[" + std::to_string(i) + "]";
    results.assets.push_back(
        {field<std::string>(assets[i], "name", at), field<std::string>(assets[i], "path", at),
         field<size_t>(assets[i], "faces", at), field<size_t>(assets[i], "vertices", at),
         field<std::string>(assets[i], "face_kinds", at),
         field<bool>(assets[i], "normals_computed", at)});
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
  return results;
}

const MeasureDeclaration* Results::findMeasure(const std::string& id) const {
  for (const MeasureDeclaration& declaration : measures) {
    if (declaration.measure == id) return &declaration;
  }
  return nullptr;
}

std::string recordJsonLine(const Record& record) { return recordToJson(record).dump(); }

std::string serializeResults(const Results& results) { return toJson(results).dump(2) + "\n"; }

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

}  // namespace tb
