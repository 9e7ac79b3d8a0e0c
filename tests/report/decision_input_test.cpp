// docs/CONTRIBUTING.md's measure checklist, shown complete: a small measure declared here, in
// tests/ only, declares one decision input (a shader cost above the instruction count's
// precedence) and reaches report.md's decision table and the decision's ranking with no edit
// outside this file. Oracle: on opensubdiv/catmark_edgecorner of the default run, acc and
// gregory_acc are both within 1e-3 and tie on triangles at 1 px (710), so the cost term decides;
// the instruction count ranks gregory_acc first (529 < 989), this measure's cost, made lower for
// acc, ranks acc first. Control: the same measure declaring its input at a lower precedence than
// the instruction count changes nothing.
#include <gtest/gtest.h>

#include <string>

#include "harness/measures/complete_declarations.h"
#include "harness/measures/measure.h"
#include "harness/report/decision.h"
#include "harness/report/markdown.h"
#include "harness/results/results_json.h"
#include "tests/test_paths.h"

namespace tb {
namespace {

constexpr const char* kTieAsset = "opensubdiv/catmark_edgecorner";

// The measure: one row per record with its cost (a fixed figure per technique, so the test
// knows the ranking it must produce).
class TestCostMeasure final : public measures::Measure {
 public:
  explicit TestCostMeasure(int precedence) : precedence_(precedence) {}
  const measures::MeasureInfo& info() const override {
    info_ = {.id = "test_cost",
             .title = "A test's shader cost",
             .description = "a cost per record, to show a measure reaching the decision",
             .metrics = {{"cost", results::Unit::kCount, results::Direction::kLowerIsBetter}},
             .headline = {"cost"},
             .decision_inputs = {{.role = results::DecisionRole::kShaderCost,
                                  .label = "test cost",
                                  .metrics = {"cost"},
                                  .precedence = precedence_}}};
    return info_;
  }
  measures::MeasureRequirements requirements() const override { return {}; }
  results::MeasureResult run(const measures::MeasureInput&) const override { return {}; }
  // Its row for a technique: acc the cheapest.
  results::MeasureResult resultFor(const std::string& technique) const {
    results::MeasureResult m;
    m.measure = info().id;
    m.rows.push_back({{}, {{"cost", technique == "acc" ? 10.0 : 100.0, "count"}}});
    return m;
  }

 private:
  int precedence_;
  mutable measures::MeasureInfo info_;
};

// The default run with the measure's declaration and a row on every record of kTieAsset, as the
// suite would write them (measures::declarationOf).
results::Results runWith(const TestCostMeasure& measure) {
  results::Results run =
      results::readResultsFile(std::string(TB_SOURCE_DIR) + "/results/baseline/results.json");
  measures::completeDeclarations(&run);
  run.measures.push_back(measures::declarationOf(measure.info()));
  for (results::Record& record : run.records) {
    if (record.asset == kTieAsset) record.measures.push_back(measure.resultFor(record.technique));
  }
  return run;
}

TEST(DecisionInput, AMeasureDeclaredInTestsReachesTheDecisionAndReportMd) {
  const results::Results baseline = [] {
    results::Results run =
        results::readResultsFile(std::string(TB_SOURCE_DIR) + "/results/baseline/results.json");
    measures::completeDeclarations(&run);
    return run;
  }();
  const report::AssetDecision before = report::decideAsset(baseline, kTieAsset);
  ASSERT_GE(before.candidates.size(), 2u);
  EXPECT_EQ(before.candidates[0].technique, "gregory_acc") << "the instruction count decides";

  const TestCostMeasure measure(/*precedence=*/1);
  const results::Results run = runWith(measure);
  const report::AssetDecision after = report::decideAsset(run, kTieAsset);
  EXPECT_EQ(after.candidates[0].technique, "acc") << "the declared cost decides";
  EXPECT_EQ(after.candidates[0].figures.cost_label, "test cost");
  EXPECT_EQ(*after.candidates[0].figures.instructions, 10);
  EXPECT_NE(after.why.find("10 test cost"), std::string::npos) << after.why;

  const std::string md = report::renderMarkdown(run);
  const size_t table = md.find("### " + std::string(kTieAsset) + "\n");
  ASSERT_NE(table, std::string::npos);
  const std::string section = md.substr(table, md.find("\n### ", table + 1) - table);
  EXPECT_NE(section.find("| test cost (cost, count) |"), std::string::npos) << section;
  EXPECT_NE(section.find("| **1 (recommended)** | acc/default |"), std::string::npos) << section;
}

TEST(DecisionInput, ControlALowerPrecedenceLeavesTheInstructionCountDeciding) {
  const TestCostMeasure measure(/*precedence=*/-1);
  const report::AssetDecision decision = report::decideAsset(runWith(measure), kTieAsset);
  ASSERT_GE(decision.candidates.size(), 2u);
  EXPECT_EQ(decision.candidates[0].technique, "gregory_acc");
  EXPECT_EQ(decision.candidates[0].figures.cost_label, "TCS + TES instructions");
}

}  // namespace
}  // namespace tb
