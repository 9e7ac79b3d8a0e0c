// Every metric is declared once, with a known unit and a direction, and every metric a
// measure emits is one it declared (issue 12, acceptance 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>
#include <string>

#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// snake_case; a '-' only as a tolerance's negative exponent ("iterations_to_1e-3", the
// name the amendments to issue 19 give).
bool isSnakeCase(const std::string& name) {
  if (name.empty() || name.front() == '_' || name.back() == '_') return false;
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool exponent_sign = c == '-' && i >= 2 && name[i - 1] == 'e' &&
                               std::isdigit(static_cast<unsigned char>(name[i - 2])) &&
                               i + 1 < name.size() &&
                               std::isdigit(static_cast<unsigned char>(name[i + 1]));
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || exponent_sign)) {
      return false;
    }
  }
  return true;
}

TEST(Declarations, EveryRegisteredMeasureDeclaresEachMetricOnce) {
  const std::vector<const measures::Measure*> measures =
      measures::MeasureRegistry::instance().all();
  ASSERT_GE(measures.size(), 5u);  // cracks, error, instructions, memory, published_figures
  for (const measures::Measure* measure : measures) {
    const measures::MeasureInfo& info = measure->info();
    SCOPED_TRACE(info.id);
    EXPECT_FALSE(info.title.empty());
    EXPECT_FALSE(info.description.empty());
    ASSERT_FALSE(info.metrics.empty());
    std::set<std::string> names;
    for (const results::MetricSpec& spec : info.metrics) {
      SCOPED_TRACE(spec.name);
      EXPECT_TRUE(isSnakeCase(spec.name));
      EXPECT_TRUE(names.insert(spec.name).second) << "declared twice";
      // A unit of the closed set, spelled and read back the same.
      EXPECT_EQ(results::parseUnit(toString(spec.unit)), spec.unit);
      EXPECT_NE(results::describe(spec.unit), "");
      EXPECT_EQ(results::parseDirection(toString(spec.direction)), spec.direction);
    }
    ASSERT_FALSE(info.headline.empty()) << "a measure names what a summary shows first";
    std::set<std::string> headline;
    const results::MeasureDeclaration declaration = measures::declarationOf(info);
    for (const std::string& name : info.headline) {
      EXPECT_TRUE(names.contains(name)) << name << " is a headline but not declared";
      EXPECT_TRUE(headline.insert(name).second) << name << " is a headline twice";
      // A summary's first figure has a direction: it ranks techniques.
      const results::MetricSpec* spec = declaration.find(name);
      ASSERT_NE(spec, nullptr);
      EXPECT_NE(spec->direction, results::Direction::kNone) << name;
    }
  }
}

TEST(Declarations, TheRunCarriesTheSelectedMeasuresDeclarations) {
  suite::SuiteSelection selection;
  selection.techniques = {techniques::TechniqueRegistry::instance().find("phong")};
  selection.assets = {suite::resolveAsset("catmark_cube")};
  selection.measures = {measures::MeasureRegistry::instance().find("memory"),
                        measures::MeasureRegistry::instance().find("error")};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  ASSERT_EQ(results.measures.size(), 2u);
  EXPECT_EQ(results.measures[0].measure, "error");  // sorted by id
  EXPECT_EQ(results.measures[1].measure, "memory");
  ASSERT_NE(results.findMeasure("memory"), nullptr);
  EXPECT_EQ(results.findMeasure("memory")->metrics,
            measures::MeasureRegistry::instance().find("memory")->info().metrics);
}

// Runs every measure on every technique that takes three small bundled assets (quads;
// quads and triangles mixed; triangles) and checks each emitted metric against its declaration.
TEST(Declarations, EveryEmittedMetricIsDeclaredWithItsUnit) {
  // A schema check over a whole suite run; under a sanitizer ThreadInvariance runs that code.
  if (::tb::testing::kUnderSanitizer)
    GTEST_SKIP() << "ThreadInvariance runs the suite under a sanitizer";
  suite::SuiteSelection selection;
  selection.assets = {suite::resolveAsset("catmark_cube"), suite::resolveAsset("catmark_pyramid"),
                      suite::resolveAsset("loop_cube")};
  results::Results results;
  suite::runSuite(selection, nullptr, &results);
  ASSERT_FALSE(results.records.empty());
  std::set<std::pair<std::string, std::string>> emitted;  // (measure, metric)
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      SCOPED_TRACE(record.technique + "/" + record.variant + " " + record.asset + " " + m.measure);
      const results::MeasureDeclaration* declaration = results.findMeasure(m.measure);
      ASSERT_NE(declaration, nullptr) << "no declaration in the results";
      for (const results::MetricRow& row : m.rows) {
        for (const results::Metric& metric : row.metrics) {
          const results::MetricSpec* spec = declaration->find(metric.name);
          ASSERT_NE(spec, nullptr) << metric.name << " is emitted but not declared";
          EXPECT_EQ(metric.unit, toString(spec->unit)) << metric.name;
          emitted.insert({m.measure, metric.name});
        }
      }
    }
  }
  // Each measure that ran emits its headline somewhere.
  for (const results::MeasureDeclaration& declaration : results.measures) {
    for (const std::string& name : declaration.headline) {
      bool ran = false;
      for (const auto& [measure, metric] : emitted) ran |= measure == declaration.measure;
      if (ran) {
        EXPECT_TRUE(emitted.contains({declaration.measure, name})) << name;
      }
    }
  }
  for (const char* id : {"cracks", "error", "instructions", "memory", "published_figures"}) {
    EXPECT_TRUE(std::any_of(emitted.begin(), emitted.end(),
                            [&](const auto& entry) { return entry.first == id; }))
        << id << " emitted nothing on the small assets";
  }
}

struct Sample {
  double length = 0;
  uint64_t count = 0;
  bool has_extra = false;
};

TEST(MetricTable, GivesSpecsAndValuesInOneOrderAndLeavesAbsentValuesOut) {
  const measures::MetricTable<Sample> table{
      {"length", results::Unit::kWorld, results::Direction::kLowerIsBetter, &Sample::length},
      {"count", results::Unit::kCount, results::Direction::kNone, &Sample::count},
      {"extra", results::Unit::kRatio, results::Direction::kHigherIsBetter,
       [](const Sample& s) -> std::optional<double> {
         if (!s.has_extra) return std::nullopt;
         return 2 * s.length;
       }},
  };
  const std::vector<results::MetricSpec> specs = table.specs();
  ASSERT_EQ(specs.size(), 3u);
  EXPECT_EQ(specs[0], (results::MetricSpec{"length", results::Unit::kWorld,
                                           results::Direction::kLowerIsBetter}));
  EXPECT_EQ(specs[2].direction, results::Direction::kHigherIsBetter);

  std::vector<results::Metric> row = table.metrics({1.5, 7, false});
  ASSERT_EQ(row.size(), 2u);
  EXPECT_EQ(row[0].name, "length");
  EXPECT_EQ(row[0].value, 1.5);
  EXPECT_EQ(row[0].unit, "world");
  EXPECT_EQ(row[1].value, 7);
  EXPECT_EQ(row[1].unit, "count");
  row = table.metrics({1.5, 7, true});
  ASSERT_EQ(row.size(), 3u);
  EXPECT_EQ(row[2].name, "extra");
  EXPECT_EQ(row[2].value, 3);
}

}  // namespace
}  // namespace tb
