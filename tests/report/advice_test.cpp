// rankCandidates on hand-built results: the oracle is the ranking rule applied by hand to the
// figures written into the rows (kAdviceRankingRule).
#include "harness/report/advice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/report/results_builders.h"

namespace tb {
namespace {

constexpr const char* kAsset = "test/asset";

results::MeasureDeclaration declaration(const std::string& id,
                                        std::vector<results::MetricSpec> metrics,
                                        results::RowScope scope = {}) {
  results::MeasureDeclaration d;
  d.measure = id;
  d.title = id;
  d.metrics = std::move(metrics);
  for (const results::MetricSpec& m : d.metrics) d.headline.push_back(m.name);
  d.summary_scope = std::move(scope);
  return d;
}

results::Results emptyResults() {
  results::Results r;
  using D = results::Direction;
  r.measures = {
      declaration("cracks", {{"points_not_equal", results::Unit::kCount, D::kLowerIsBetter},
                             {"unpaired_points", results::Unit::kCount, D::kLowerIsBetter}}),
      declaration("error", {{"hausdorff", results::Unit::kDiagonal, D::kLowerIsBetter}}),
      declaration("instructions", {{"total", results::Unit::kCount, D::kLowerIsBetter}},
                  {{"source", "spirv_O"}, {"expansion", "vector"}, {"stage", "*.tese"}}),
      declaration("memory", {{"plain_over_technique", results::Unit::kRatio, D::kHigherIsBetter}}),
  };
  measures::completeDeclarations(&r);
  return r;
}

using testing::measureResult;
using testing::row;

struct Figures {
  double error = 1e-3;        // hausdorff at the two levels: error/2 and error
  double instructions = 100;  // the .tese total (the .tesc row gets 10x)
  double plain_over = 10;     // smallest plain_over_technique (the other level 2x)
  double not_equal = 0;       // cracks points_not_equal on the cpu row
  bool gpu_skipped = false;   // the gpu cracks row skipped (no device)
  bool with_memory = true;
  bool with_error = true;
};

void addRecord(results::Results* r, const std::string& technique, const std::string& variant,
               const Figures& f) {
  results::Record record;
  record.technique = technique;
  record.variant = variant;
  record.asset = kAsset;
  if (f.with_error) {
    results::MeasureResult error = measureResult("error");
    error.rows = {row({{"level", "4"}}, {{"hausdorff", f.error / 2}}),
                  row({{"level", "8"}}, {{"hausdorff", f.error}})};
    record.measures.push_back(error);
  }
  results::MeasureResult cracks = measureResult("cracks");
  cracks.rows = {
      row({{"backend", "cpu_float"}}, {{"points_not_equal", f.not_equal}, {"unpaired_points", 0}})};
  cracks.rows.push_back(
      f.gpu_skipped ? results::unmeasuredRow({{"backend", "gpu"}}, results::MeasureStatus::kSkipped,
                                             "no Vulkan device (test)")
                    : row({{"backend", "gpu"}}, {{"points_not_equal", 0}, {"unpaired_points", 0}}));
  record.measures.push_back(cracks);
  results::MeasureResult instructions = measureResult("instructions");
  const std::map<std::string, std::string> tese{
      {"source", "spirv_O"}, {"expansion", "vector"}, {"stage", technique + "/x.tese"}};
  std::map<std::string, std::string> tesc = tese;
  tesc["stage"] = technique + "/x.tesc";
  instructions.rows = {row(tesc, {{"total", 10 * f.instructions}}),
                       row(tese, {{"total", f.instructions}})};
  record.measures.push_back(instructions);
  if (f.with_memory) {
    results::MeasureResult memory = measureResult("memory");
    memory.rows = {row({{"level", "8"}}, {{"plain_over_technique", f.plain_over}}),
                   row({{"level", "64"}}, {{"plain_over_technique", 2 * f.plain_over}})};
    record.measures.push_back(memory);
  }
  r->records.push_back(record);
}

std::vector<std::string> names(const report::Advice& advice) {
  std::vector<std::string> out;
  for (const report::Candidate& c : advice.ranked) out.push_back(c.technique + "/" + c.variant);
  return out;
}

TEST(Advice, FiguresAreTheWorstOverTheSummaryScope) {
  results::Results r = emptyResults();
  addRecord(&r, "a", "default", {.error = 2e-3, .instructions = 120, .plain_over = 8});
  const report::Advice advice = report::rankCandidates(r, kAsset, {});
  ASSERT_EQ(advice.ranked.size(), 1u);
  const report::CandidateFigures& f = advice.ranked[0].figures;
  EXPECT_DOUBLE_EQ(*f.error, 2e-3);            // the larger of the two levels
  EXPECT_DOUBLE_EQ(*f.instructions, 120);      // the .tese row only, not the .tesc one
  EXPECT_DOUBLE_EQ(*f.memory_ratio, 1.0 / 8);  // 1 / the smallest plain_over_technique
  EXPECT_EQ(f.watertight, report::Watertightness::kWatertight);
  EXPECT_TRUE(advice.ranked[0].passes);
  EXPECT_EQ(advice.ranked[0].verdict.rfind("wins:", 0), 0u) << advice.ranked[0].verdict;
}

TEST(Advice, OrderIsErrorThenInstructionsThenMemoryThenName) {
  results::Results r = emptyResults();
  addRecord(&r, "d", "default", {.error = 3e-3});
  addRecord(&r, "c", "default", {.error = 1e-3, .instructions = 90, .plain_over = 5});
  addRecord(&r, "b", "default", {.error = 1e-3, .instructions = 90, .plain_over = 10});
  addRecord(&r, "a", "z", {.error = 1e-3, .instructions = 100});
  addRecord(&r, "a", "y", {.error = 1e-3, .instructions = 100});
  const report::Advice advice = report::rankCandidates(r, kAsset, {});
  EXPECT_EQ(names(advice),
            (std::vector<std::string>{"b/default", "c/default", "a/y", "a/z", "d/default"}));
  EXPECT_NE(advice.ranked[1].verdict.find("larger memory ratio"), std::string::npos);
  EXPECT_NE(advice.ranked[2].verdict.find("more instructions"), std::string::npos);
  EXPECT_NE(advice.ranked[3].verdict.find("by name"), std::string::npos);
  EXPECT_NE(advice.ranked[4].verdict.find("higher error"), std::string::npos);
}

TEST(Advice, PassingCandidatesComeFirstAndExcludedOnesSayByHowMuch) {
  results::Results r = emptyResults();
  addRecord(&r, "low_error_cracked", "default", {.error = 1e-4, .not_equal = 12});
  addRecord(&r, "over_budget", "default", {.error = 5e-3, .plain_over = 2});
  addRecord(&r, "fits", "default", {.error = 8e-4, .plain_over = 10});
  report::AdviceConstraints constraints;
  constraints.max_error = 1e-3;
  constraints.max_memory_ratio = 0.25;
  constraints.watertight = true;
  const report::Advice advice = report::rankCandidates(r, kAsset, constraints);
  EXPECT_EQ(names(advice), (std::vector<std::string>{"fits/default", "low_error_cracked/default",
                                                     "over_budget/default"}));
  ASSERT_TRUE(advice.anyPasses());
  const report::Candidate& first = advice.ranked[0];
  EXPECT_LE(*first.figures.error, *constraints.max_error);
  EXPECT_LE(*first.figures.memory_ratio, *constraints.max_memory_ratio);
  EXPECT_EQ(first.figures.watertight, report::Watertightness::kWatertight);

  const report::Candidate& cracked = advice.ranked[1];
  EXPECT_FALSE(cracked.passes);
  ASSERT_EQ(cracked.failures.size(), 1u);
  EXPECT_NE(cracked.failures[0].find("12 points not equal"), std::string::npos);

  const report::Candidate& over = advice.ranked[2];
  ASSERT_EQ(over.failures.size(), 2u);  // error and memory, both with the amount
  EXPECT_NE(over.failures[0].find("error 0.005 rel_diag > max 0.001 (over by 0.004, 5x)"),
            std::string::npos)
      << over.failures[0];
  EXPECT_NE(over.failures[1].find("memory ratio 0.5 > max 0.25"), std::string::npos)
      << over.failures[1];
  EXPECT_EQ(over.verdict.rfind("excluded: ", 0), 0u);
}

TEST(Advice, SkippedDeviceRowsLeaveWatertightnessUnverifiedWhichFailsWatertight) {
  results::Results r = emptyResults();
  addRecord(&r, "a", "default", {.gpu_skipped = true});
  EXPECT_TRUE(
      report::rankCandidates(r, kAsset, {}).anyPasses());  // no --watertight: not a constraint
  report::AdviceConstraints constraints;
  constraints.watertight = true;
  const report::Advice advice = report::rankCandidates(r, kAsset, constraints);
  ASSERT_EQ(advice.ranked.size(), 1u);
  EXPECT_EQ(advice.ranked[0].figures.watertight, report::Watertightness::kUnverified);
  EXPECT_FALSE(advice.anyPasses());
  ASSERT_EQ(advice.ranked[0].failures.size(), 1u);
  EXPECT_NE(advice.ranked[0].failures[0].find("watertightness unverified on the device"),
            std::string::npos);
  EXPECT_NE(advice.ranked[0].failures[0].find("no Vulkan device (test)"), std::string::npos);
}

// Oracle: the declaration. A control (made to show a failure) with the best figures of all is
// still never a choice: it ranks after every passing candidate, with the reason; the same
// variant undeclared (the broken control of this check) would rank first.
TEST(Advice, AControlIsNeverAChoiceEvenWithTheBestFigures) {
  results::Results r = emptyResults();
  addRecord(&r, "a", "default", {.error = 1e-3});
  addRecord(&r, "a", "asymmetric", {.error = 1e-6});
  EXPECT_EQ(names(report::rankCandidates(r, kAsset, {})).front(), "a/asymmetric");
  r.context.selection.techniques = {{"a", {"default", "asymmetric"}, {"asymmetric"}}};
  const report::Advice advice = report::rankCandidates(r, kAsset, {});
  ASSERT_EQ(advice.ranked.size(), 2u);
  EXPECT_EQ(names(advice).front(), "a/default");
  EXPECT_TRUE(advice.anyPasses());
  EXPECT_FALSE(advice.ranked[1].passes);
  EXPECT_EQ(advice.ranked[1].failures.front(), "a control: made to show a failure, never a choice");
}

TEST(Advice, AMissingFigureFailsTheConstraintThatNeedsIt) {
  results::Results r = emptyResults();
  addRecord(&r, "a", "default", {.with_error = false});
  report::AdviceConstraints constraints;
  constraints.max_error = 1;
  const report::Advice advice = report::rankCandidates(r, kAsset, constraints);
  ASSERT_EQ(advice.ranked.size(), 1u);
  EXPECT_FALSE(advice.ranked[0].passes);
  ASSERT_EQ(advice.ranked[0].failures.size(), 1u);
  EXPECT_EQ(advice.ranked[0].failures[0], "no error figure: error measure not run");
  // Without the constraint the missing figure only sorts last.
  EXPECT_TRUE(report::rankCandidates(r, kAsset, {}).anyPasses());
}

TEST(Advice, AVariantWithoutMemoryRowsHasItsDefaultVariantsFigure) {
  results::Results r = emptyResults();
  addRecord(&r, "a", "default", {.plain_over = 4});
  addRecord(&r, "a", "same_patch_data", {.with_memory = false});
  report::AdviceConstraints constraints;
  constraints.max_memory_ratio = 1;
  const report::Advice advice = report::rankCandidates(r, kAsset, constraints);
  ASSERT_EQ(advice.ranked.size(), 2u);
  for (const report::Candidate& c : advice.ranked) {
    ASSERT_TRUE(c.figures.memory_ratio.has_value()) << c.variant;
    EXPECT_DOUBLE_EQ(*c.figures.memory_ratio, 0.25);
    EXPECT_EQ(c.figures.memory_from_default, c.variant != "default");
  }
}

TEST(Advice, UnsupportedTechniquesAreExcludedWithTheirReason) {
  results::Results r = emptyResults();
  addRecord(&r, "phong", "default", {});
  r.skipped.push_back({"acc", kAsset, "acc: face 0 has 3 vertices; ACC needs quads"});
  r.skipped.push_back({"acc", "other/asset", "not this asset"});
  const report::Advice advice = report::rankCandidates(r, kAsset, {});
  ASSERT_EQ(advice.unsupported.size(), 1u);
  EXPECT_EQ(advice.unsupported[0].technique, "acc");
  EXPECT_NE(advice.unsupported[0].reason.find("ACC needs quads"), std::string::npos);
  const std::string markdown = report::renderAdviceMarkdown(advice, {});
  EXPECT_NE(markdown.find("excluded: unsupported input: acc: face 0"), std::string::npos);
  EXPECT_NE(markdown.find(report::kAdviceRankingRule), std::string::npos);
}

TEST(Advice, TechniqueFilterAndAssetSelectTheCandidates) {
  results::Results r = emptyResults();
  addRecord(&r, "a", "default", {});
  addRecord(&r, "b", "default", {});
  report::AdviceConstraints constraints;
  constraints.techniques = {"b"};
  EXPECT_EQ(names(report::rankCandidates(r, kAsset, constraints)),
            (std::vector<std::string>{"b/default"}));
  EXPECT_TRUE(report::rankCandidates(r, "no/such_asset", {}).ranked.empty());
  EXPECT_FALSE(report::rankCandidates(r, "no/such_asset", {}).anyPasses());
}

}  // namespace
}  // namespace tb
