#include "harness/results/results_json.h"

#include <gtest/gtest.h>

#include <set>
#include <string_view>

namespace tb {
namespace {

results::Results sampleResults() {
  results::Results results;
  results.context.date = "2026-11-22T00:00:00Z";
  results.context.run_id = "r1";
  results.context.libraries = {{"OpenSubdiv", "v3_5_0"}};
  results.assets.push_back({"opensubdiv/catmark_cube", "assets/x.obj", 6, 8, "quads", false});
  results::Record record{"phong", "alpha0.75", "opensubdiv/catmark_cube", {{"alpha", "0.75"}},
                         {"w"},   {}};
  results::MeasureResult memory;
  memory.measure = "memory";
  memory.rows.push_back(
      {{{"level", "8"}}, {{"plain_bytes", 1234, "bytes"}, {"ratio", 0.1, "ratio"}}});
  memory.rows.push_back(results::unmeasuredRow({{"level", "16"}}, results::MeasureStatus::kFailed,
                                               "device lost at level 16"));
  record.measures.push_back(memory);
  results::MeasureResult skipped{
      "gpu", results::MeasureStatus::kSkipped, "no Vulkan device", {}, {}};
  record.measures.push_back(skipped);
  results.records.push_back(record);
  results.skipped.push_back({"acc", "loop_cube", "acc: face 0 has 3 vertices; ACC needs quads"});
  results.measures.push_back(
      {"memory",
       "Memory",
       "bytes",
       {{"plain_bytes", results::Unit::kBytes, results::Direction::kNone},
        {"ratio", results::Unit::kRatio, results::Direction::kHigherIsBetter}},
       {"ratio"},
       {"a fixed note"}});
  results.measures.back().summary_scope = {{"level", "1*"}};
  results::PlotSpec plot;
  plot.title = "Ratio against level";
  plot.kind = results::PlotKind::kLine;
  plot.x = "level";
  plot.y = "ratio";
  plot.where = {{"level", "*"}};
  plot.log_y = true;
  plot.reduce = results::PlotReduce::kMax;
  results.measures.back().plots.push_back(plot);
  return results;
}

TEST(ResultsJson, RoundTripsEveryField) {
  const results::Results original = sampleResults();
  const std::string text = results::serializeResults(original);
  const results::Results parsed = results::resultsFromJson(nlohmann::ordered_json::parse(text));
  EXPECT_EQ(results::serializeResults(parsed), text);
  EXPECT_EQ(parsed.records[0].measures[1].status, results::MeasureStatus::kSkipped);
  EXPECT_EQ(parsed.records[0].measures[0].rows[0].metrics[1].value, 0.1);
  EXPECT_EQ(parsed.skipped[0].reason, original.skipped[0].reason);
  const results::MetricRow& failed = parsed.records[0].measures[0].rows[1];
  EXPECT_EQ(failed.status, results::MeasureStatus::kFailed);
  EXPECT_EQ(failed.reason, "device lost at level 16");
  EXPECT_TRUE(failed.metrics.empty());
  EXPECT_EQ(parsed.measures[0].summary_scope, original.measures[0].summary_scope);
  EXPECT_EQ(parsed.measures[0].plots, original.measures[0].plots);
}

TEST(ResultsJson, RowScopeMatchesExactlyOrByGlob) {
  EXPECT_TRUE(results::rowInScope({}, {{"stage", "acc/acc.tese"}}));
  EXPECT_TRUE(results::rowInScope({{"stage", "*.tese"}}, {{"stage", "acc/acc.tese"}}));
  EXPECT_FALSE(results::rowInScope({{"stage", "*.tese"}}, {{"stage", "acc/acc.tesc"}}));
  EXPECT_TRUE(results::rowInScope({{"stage", "acc/*.te*"}}, {{"stage", "acc/acc.tese"}}));
  EXPECT_FALSE(results::rowInScope({{"source", "spirv_O"}}, {{"stage", "acc/acc.tese"}}));
  EXPECT_FALSE(results::rowInScope({{"source", "spirv_O"}}, {{"source", "spirv_O2"}}));
}

// A skip or failure is a status a reader can filter on; an ok row spends no bytes on it.
TEST(ResultsJson, RowStatusIsWrittenOnlyWhenNotOk) {
  const auto json = results::toJson(sampleResults());
  const auto& rows = json["records"][0]["measures"][0]["rows"];
  // Schema 4: [[keys], [metrics]] for an ok row, then status and reason for the others.
  EXPECT_EQ(rows[0].size(), 2u);
  ASSERT_EQ(rows[1].size(), 4u);
  EXPECT_EQ(rows[1][2], "failed");
  EXPECT_EQ(rows[1][3], "device lost at level 16");
  auto broken = json;
  broken["records"][0]["measures"][0]["rows"][1][2] = "maybe";
  EXPECT_THROW(results::resultsFromJson(broken), std::runtime_error);
}

TEST(ResultsJson, RowsAreOneLineEachWithUnitsFromTheDeclaration) {
  const results::Results results = sampleResults();
  const std::string text = results::serializeResults(results);
  const results::Results read = results::resultsFromJson(nlohmann::ordered_json::parse(text));
  ASSERT_EQ(read.records.size(), results.records.size());
  const auto& rows = results.records[0].measures[0].rows;
  const auto& read_rows = read.records[0].measures[0].rows;
  ASSERT_EQ(read_rows.size(), rows.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    EXPECT_EQ(read_rows[r].keys, rows[r].keys);
    EXPECT_EQ(read_rows[r].status, rows[r].status);
    ASSERT_EQ(read_rows[r].metrics.size(), rows[r].metrics.size());
    for (size_t m = 0; m < rows[r].metrics.size(); ++m) {
      EXPECT_EQ(read_rows[r].metrics[m].name, rows[r].metrics[m].name);
      EXPECT_EQ(read_rows[r].metrics[m].value, rows[r].metrics[m].value);
      if (results.findMeasure(results.records[0].measures[0].measure) != nullptr) {
        EXPECT_EQ(read_rows[r].metrics[m].unit, rows[r].metrics[m].unit);
      }
    }
  }
  // Each row is one line: "[[" opens a row's key values.
  size_t row_lines = 0;
  for (size_t at = text.find("\n"); at != std::string::npos; at = text.find("\n", at + 1)) {
    const size_t next = text.find_first_not_of(' ', at + 1);
    if (next != std::string::npos && text.compare(next, 2, "[[") == 0) ++row_lines;
  }
  size_t all_rows = 0;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) all_rows += m.rows.size();
  }
  EXPECT_EQ(row_lines, all_rows);
  // A row with the wrong number of metric values is refused, naming the row.
  auto broken = results::toJson(results);
  broken["records"][0]["measures"][0]["rows"][0][1].push_back(1);
  try {
    results::resultsFromJson(broken);
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("rows[0]"), std::string::npos) << error.what();
  }
}

TEST(ResultsJson, SerialisationIsByteStable) {
  EXPECT_EQ(results::serializeResults(sampleResults()), results::serializeResults(sampleResults()));
  const auto json = results::toJson(sampleResults());
  EXPECT_EQ(json.begin().key(), "schema_version");
  EXPECT_EQ(json["schema_version"], results::kResultsSchemaVersion);
}

TEST(ResultsJson, RejectsAnotherSchemaVersionAndMissingFields) {
  auto json = results::toJson(sampleResults());
  json["schema_version"] = results::kResultsSchemaVersion + 1;
  EXPECT_THROW(results::resultsFromJson(json), std::runtime_error);
  auto broken = results::toJson(sampleResults());
  broken["records"][0].erase("asset");
  try {
    results::resultsFromJson(broken);
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("records[0]: missing field 'asset'"),
              std::string::npos)
        << error.what();
  }
}

TEST(ResultsJson, RoundTripsMeasureDeclarationsAndRejectsUnknownUnits) {
  const results::Results original = sampleResults();
  const results::Results parsed = results::resultsFromJson(results::toJson(original));
  ASSERT_EQ(parsed.measures.size(), 1u);
  const results::MeasureDeclaration& memory = *parsed.findMeasure("memory");
  EXPECT_EQ(memory.metrics, original.measures[0].metrics);
  EXPECT_EQ(memory.headline, std::vector<std::string>{"ratio"});
  EXPECT_EQ(memory.notes, std::vector<std::string>{"a fixed note"});
  auto json = results::toJson(original);
  EXPECT_EQ(json["measures"][0]["metrics"][1]["unit"], "ratio");
  EXPECT_EQ(json["measures"][0]["metrics"][1]["direction"], "higher");
  json["measures"][0]["metrics"][1]["unit"] = "furlongs";
  EXPECT_THROW(results::resultsFromJson(json), std::runtime_error);
}

// Control rows and comparisons: carried when declared, absent (the file's bytes unchanged)
// when not, and read as empty from files written before them.
TEST(ResultsJson, ControlRowsAndComparisonsAreOptional) {
  results::Results declared = sampleResults();
  EXPECT_FALSE(results::toJson(declared)["measures"][0].contains("control_rows"));
  EXPECT_FALSE(results::toJson(declared)["measures"][0].contains("comparisons"));
  declared.measures[0].control_rows = {{{"policy", "*_order_dependent"}},
                                       {{"policy", "error_bound_loose"}, {"spacing", "integer"}}};
  declared.measures[0].comparisons = {{.title = "Triangles at 1 px",
                                       .where = {{"summary", "max_error_1px"}},
                                       .column_key = "policy",
                                       .metric = "ratio",
                                       .valid_flag = "target_reached",
                                       .extra_columns = {{"uniform", "plain_bytes"}},
                                       .facets = {"asset", "camera_path"}}};
  const std::string text = results::serializeResults(declared);
  const results::Results parsed = results::resultsFromJson(nlohmann::ordered_json::parse(text));
  EXPECT_EQ(parsed.measures[0].control_rows, declared.measures[0].control_rows);
  EXPECT_EQ(parsed.measures[0].comparisons, declared.measures[0].comparisons);
  EXPECT_EQ(results::serializeResults(parsed), text);
  auto json = results::toJson(declared);
  json["measures"][0].erase("control_rows");
  json["measures"][0].erase("comparisons");
  const results::Results old = results::resultsFromJson(json);
  EXPECT_TRUE(old.measures[0].control_rows.empty());
  EXPECT_TRUE(old.measures[0].comparisons.empty());
  EXPECT_EQ(results::serializeResults(old), results::serializeResults(sampleResults()));
  json["measures"][0]["comparisons"] = nlohmann::ordered_json::array({{{"title", "no metric"}}});
  EXPECT_THROW(results::resultsFromJson(json), std::runtime_error);
}

TEST(MetricSpec, EveryUnitAndDirectionHasOneSpelling) {
  std::set<std::string_view> spellings;
  for (results::Unit unit : results::allUnits()) {
    EXPECT_TRUE(spellings.insert(toString(unit)).second) << toString(unit);
    EXPECT_EQ(results::parseUnit(toString(unit)), unit);
    EXPECT_FALSE(results::describe(unit).empty());
  }
  EXPECT_EQ(results::parseUnit("ulp of scale"), std::nullopt);
  for (results::Direction direction :
       {results::Direction::kLowerIsBetter, results::Direction::kHigherIsBetter,
        results::Direction::kNone}) {
    EXPECT_EQ(results::parseDirection(toString(direction)), direction);
  }
  EXPECT_EQ(results::parseDirection("sideways"), std::nullopt);
}

}  // namespace
}  // namespace tb
