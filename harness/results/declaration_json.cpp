// A measure's declaration in results.json (results_json.h): its metrics, notes, summary
// scope, plots, control rows and comparisons.
#include <stdexcept>

#include "harness/results/json_field.h"
#include "harness/results/results_json.h"

namespace tb::results {
namespace {

using Json = nlohmann::ordered_json;
using json_detail::field;

Json plotsToJson(const std::vector<PlotSpec>& specs) {
  Json plots = Json::array();
  for (const PlotSpec& plot : specs) {
    plots.push_back({{"title", plot.title},
                     {"kind", toString(plot.kind)},
                     {"x", plot.x},
                     {"y", plot.y},
                     {"series", plot.series},
                     {"facet", plot.facet},
                     {"where", plot.where},
                     {"log_x", plot.log_x},
                     {"log_y", plot.log_y},
                     {"pareto_front", plot.pareto_front},
                     {"reduce", toString(plot.reduce)}});
  }
  return plots;
}

PlotSpec plotFromJson(const Json& json, const std::string& at) {
  PlotSpec plot;
  plot.title = field<std::string>(json, "title", at);
  const auto kind = parsePlotKind(field<std::string>(json, "kind", at));
  if (!kind) throw std::runtime_error(at + ": unknown plot kind");
  plot.kind = *kind;
  plot.x = field<std::string>(json, "x", at);
  plot.y = field<std::string>(json, "y", at);
  plot.series = field<std::string>(json, "series", at);
  plot.facet = field<std::string>(json, "facet", at);
  plot.where = field<RowScope>(json, "where", at);
  plot.log_x = field<bool>(json, "log_x", at);
  plot.log_y = field<bool>(json, "log_y", at);
  plot.pareto_front = field<bool>(json, "pareto_front", at);
  if (json.contains("reduce")) {
    const auto reduce = parsePlotReduce(field<std::string>(json, "reduce", at));
    if (!reduce) throw std::runtime_error(at + ": unknown plot reduce");
    plot.reduce = *reduce;
  }
  return plot;
}

Json comparisonsToJson(const std::vector<ComparisonSpec>& specs) {
  Json comparisons = Json::array();
  for (const ComparisonSpec& spec : specs) {
    Json extra = Json::array();
    for (const ComparisonColumn& column : spec.extra_columns) {
      extra.push_back({{"label", column.label}, {"metric", column.metric}});
    }
    comparisons.push_back({{"title", spec.title},
                           {"where", spec.where},
                           {"column_key", spec.column_key},
                           {"metric", spec.metric},
                           {"valid_flag", spec.valid_flag},
                           {"extra_columns", extra},
                           {"facets", spec.facets}});
    if (!spec.ignore_keys.empty()) comparisons.back()["ignore_keys"] = spec.ignore_keys;
    if (!spec.cell_metrics.empty()) comparisons.back()["cell_metrics"] = spec.cell_metrics;
  }
  return comparisons;
}

ComparisonSpec comparisonFromJson(const Json& json, const std::string& at) {
  ComparisonSpec spec;
  spec.title = field<std::string>(json, "title", at);
  spec.where = field<RowScope>(json, "where", at);
  spec.column_key = field<std::string>(json, "column_key", at);
  spec.metric = field<std::string>(json, "metric", at);
  spec.valid_flag = field<std::string>(json, "valid_flag", at);
  const Json extra = field<Json>(json, "extra_columns", at);
  for (size_t i = 0; i < extra.size(); ++i) {
    const std::string column_at = at + ".extra_columns[" + std::to_string(i) + "]";
    spec.extra_columns.push_back({field<std::string>(extra[i], "label", column_at),
                                  field<std::string>(extra[i], "metric", column_at)});
  }
  spec.facets = field<std::vector<std::string>>(json, "facets", at);
  if (json.contains("ignore_keys")) {
    spec.ignore_keys = field<std::vector<std::string>>(json, "ignore_keys", at);
  }
  if (json.contains("cell_metrics")) {
    spec.cell_metrics = field<std::vector<std::string>>(json, "cell_metrics", at);
  }
  return spec;
}

Json decisionInputsToJson(const std::vector<DecisionInput>& inputs) {
  Json out = Json::array();
  for (const DecisionInput& input : inputs) {
    out.push_back({{"role", toString(input.role)},
                   {"label", input.label},
                   {"column", input.column},
                   {"metrics", input.metrics},
                   {"per", input.per},
                   {"where", input.where},
                   {"any_of", input.any_of},
                   {"reduce", toString(input.reduce)},
                   {"valid_flag", input.valid_flag},
                   {"path", input.path},
                   {"rows_on_path", input.rows_on_path},
                   {"device_rows", input.device_rows},
                   {"first_of", input.first_of},
                   {"chosen_key", input.chosen_key},
                   {"precedence", input.precedence}});
  }
  return out;
}

DecisionInput decisionInputFromJson(const Json& json, const std::string& at) {
  DecisionInput input;
  const auto role = parseDecisionRole(field<std::string>(json, "role", at));
  if (!role) throw std::runtime_error(at + ": unknown decision role");
  input.role = *role;
  input.label = field<std::string>(json, "label", at);
  input.column = field<std::string>(json, "column", at);
  input.metrics = field<std::vector<std::string>>(json, "metrics", at);
  input.per = field<std::string>(json, "per", at);
  input.where = field<RowScope>(json, "where", at);
  input.any_of = field<std::vector<RowScope>>(json, "any_of", at);
  const auto reduce = parseDecisionReduce(field<std::string>(json, "reduce", at));
  if (!reduce) throw std::runtime_error(at + ": unknown decision reduce");
  input.reduce = *reduce;
  input.valid_flag = field<std::string>(json, "valid_flag", at);
  input.path = field<std::string>(json, "path", at);
  input.rows_on_path = field<bool>(json, "rows_on_path", at);
  input.device_rows = field<RowScope>(json, "device_rows", at);
  input.first_of = field<std::string>(json, "first_of", at);
  input.chosen_key = field<std::string>(json, "chosen_key", at);
  input.precedence = field<int>(json, "precedence", at);
  return input;
}

}  // namespace

Json toJson(const MeasureDeclaration& declaration) {
  Json metrics = Json::array();
  for (const MetricSpec& spec : declaration.metrics) {
    metrics.push_back({{"name", spec.name},
                       {"unit", toString(spec.unit)},
                       {"direction", toString(spec.direction)}});
  }
  Json json{{"measure", declaration.measure},
            {"title", declaration.title},
            {"description", declaration.description},
            {"headline", declaration.headline},
            {"notes", declaration.notes},
            {"metrics", metrics}};
  // Optional fields, absent when empty: files of measures without them keep their bytes.
  if (!declaration.summary_scope.empty()) json["summary_scope"] = declaration.summary_scope;
  if (!declaration.plots.empty()) json["plots"] = plotsToJson(declaration.plots);
  if (!declaration.control_rows.empty()) json["control_rows"] = declaration.control_rows;
  if (!declaration.comparisons.empty()) {
    json["comparisons"] = comparisonsToJson(declaration.comparisons);
  }
  if (!declaration.decision_inputs.empty()) {
    json["decision_inputs"] = decisionInputsToJson(declaration.decision_inputs);
  }
  if (!declaration.shader_db.group_key.empty()) {
    json["shader_db"] = {{"group_key", declaration.shader_db.group_key},
                         {"ignore_keys", declaration.shader_db.ignore_keys},
                         {"metrics", declaration.shader_db.metrics}};
  }
  return json;
}

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
  if (json.contains("summary_scope")) {
    declaration.summary_scope = field<RowScope>(json, "summary_scope", where);
  }
  if (json.contains("plots")) {
    const Json plots = field<Json>(json, "plots", where);
    for (size_t i = 0; i < plots.size(); ++i) {
      declaration.plots.push_back(
          plotFromJson(plots[i], where + ".plots[" + std::to_string(i) + "]"));
    }
  }
  // Absent in results written before controls per row and comparisons.
  if (json.contains("control_rows")) {
    declaration.control_rows = field<std::vector<RowScope>>(json, "control_rows", where);
  }
  if (json.contains("comparisons")) {
    const Json comparisons = field<Json>(json, "comparisons", where);
    for (size_t i = 0; i < comparisons.size(); ++i) {
      declaration.comparisons.push_back(
          comparisonFromJson(comparisons[i], where + ".comparisons[" + std::to_string(i) + "]"));
    }
  }
  // Absent in results written before decision inputs (harness/measures fills them in from
  // the registered measure: completeDeclarations).
  if (json.contains("decision_inputs")) {
    const Json inputs = field<Json>(json, "decision_inputs", where);
    for (size_t i = 0; i < inputs.size(); ++i) {
      declaration.decision_inputs.push_back(
          decisionInputFromJson(inputs[i], where + ".decision_inputs[" + std::to_string(i) + "]"));
    }
  }
  if (json.contains("shader_db")) {
    const Json db = field<Json>(json, "shader_db", where);
    const std::string at = where + ".shader_db";
    declaration.shader_db = {field<std::string>(db, "group_key", at),
                             field<std::vector<std::string>>(db, "ignore_keys", at),
                             field<std::vector<std::string>>(db, "metrics", at)};
  }
  return declaration;
}

}  // namespace tb::results
