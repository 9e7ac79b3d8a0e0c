// The decision per asset, the answers block and report.md's summary tables over the committed
// default run (results/baseline/results.json: every bundled asset, no new run). Oracles: the
// run's own declarations (controls, default variants), advise's rendering of the same
// results, and the tables' own cells (no column or row without a figure).
#include "harness/report/decision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "harness/lod/cull_policy.h"
#include "harness/measures/complete_declarations.h"
#include "harness/report/advice.h"
#include "harness/report/answers.h"
#include "harness/report/html.h"
#include "harness/report/markdown.h"
#include "harness/report/summary.h"
#include "harness/results/results_json.h"
#include "tests/test_paths.h"

namespace tb {
namespace {

const results::Results& baseline() {
  static const results::Results r = [] {
    results::Results run =
        results::readResultsFile(std::string(TB_SOURCE_DIR) + "/results/baseline/results.json");
    measures::completeDeclarations(&run);
    return run;
  }();
  return r;
}

const std::string& markdown() {
  static const std::string md = report::renderMarkdown(baseline());
  return md;
}

std::vector<std::string> textLines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

void everyCandidateIsADefaultNonControlVariantAndWatertightOnesWin() {
  const auto decisions = report::decideAssets(baseline());
  ASSERT_GE(decisions.size(), 30u);
  for (const report::AssetDecision& d : decisions) {
    for (const report::DecisionCandidate& c : d.candidates) {
      EXPECT_FALSE(report::isControl(baseline(), c.technique, c.variant)) << c.name();
      for (const auto& t : report::techniquesOf(baseline())) {
        if (t.technique == c.technique) {
          EXPECT_EQ(t.variants.front(), c.variant) << d.asset;
        }
      }
    }
    // A broken rule would let a cracked candidate win over a watertight one.
    const auto& first = d.candidates.front().figures;
    for (const report::DecisionCandidate& c : d.candidates) {
      if (c.figures.cpu == report::Watertightness::kWatertight &&
          c.figures.device == report::Watertightness::kWatertight) {
        EXPECT_EQ(first.cpu, report::Watertightness::kWatertight) << d.asset;
      }
    }
  }
}

// Acceptance 1: the answers block is in the first 40 lines and names, for every surface
// asset, a technique/variant that is not a control.
void answersBlockOpensReportMdAndNamesANonControlChoicePerAsset() {
  const std::vector<std::string> head = textLines(markdown());
  std::string first40;
  for (size_t i = 0; i < std::min<size_t>(40, head.size()); ++i) first40 += head[i] + "\n";
  ASSERT_NE(first40.find("## Answers"), std::string::npos);
  for (const char* question :
       {"Which technique", "Did anything crack", "What does ACC save", "Which culling policy",
        "factor policy beat uniform", "Gauss-Seidel better than Jacobi"}) {
    EXPECT_NE(first40.find(question), std::string::npos) << question;
  }
  for (const report::AssetDecision& d : report::decideAssets(baseline())) {
    const std::string named = "**" + d.recommended() + "** on ";
    const size_t at = first40.find(named);
    ASSERT_NE(at, std::string::npos) << d.asset;
    EXPECT_NE(first40.find(d.asset, at), std::string::npos) << d.asset;
    const auto slash = d.recommended().find('/');
    EXPECT_FALSE(report::isControl(baseline(), d.recommended().substr(0, slash),
                                   d.recommended().substr(slash + 1)));
  }
}

// Acceptance 2: report.md, report.html and advise name the same recommendation per asset.
void reportMdHtmlAndAdviseAgreeForEveryAsset() {
  const std::string html = report::renderHtml(baseline(), {"/* no chart.js */", "", {}, {}});
  for (const report::AssetDecision& d : report::decideAssets(baseline())) {
    const std::string md_heading = "### " + d.asset + "\n";
    const size_t at = markdown().find(md_heading);
    ASSERT_NE(at, std::string::npos) << d.asset;
    EXPECT_NE(markdown().find("| **1 (recommended)** | " + d.recommended() + " |", at),
              std::string::npos)
        << d.asset;
    // The chart's label, or the line of the assets without a chart.
    EXPECT_NE(html.find(d.asset + ", recommended " + d.recommended()), std::string::npos)
        << d.asset;
    const report::Advice advice = report::rankCandidates(baseline(), d.asset, {});
    EXPECT_EQ(advice.recommendation, d.recommended()) << d.asset;
    EXPECT_NE(
        report::renderAdviceMarkdown(advice, {}).find("no constraints): " + d.recommended() + "."),
        std::string::npos);
  }
}

bool emptyCell(const std::string& cell) {
  return cell.empty() || cell == "—" || cell == "-" || cell == "n/a";
}

std::vector<std::string> cellsOf(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += '|';
      ++i;
    } else if (line[i] == '|') {
      const size_t b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
      cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return cells;
}

// Acceptance 4: no summary table of report.md (the sections before the per-measure details)
// has a column or a row without one figure.
void noEmptyColumnOrRowOfDashesInReportMdSummaries() {
  const std::vector<std::string> all = textLines(markdown());
  std::vector<std::vector<std::string>> table;
  std::string heading;
  const auto check = [&] {
    if (table.size() < 3) return;
    const size_t columns = table[0].size();
    for (size_t c = 1; c < columns; ++c) {
      bool any = false;
      for (size_t r = 2; r < table.size(); ++r)
        any |= c < table[r].size() && !emptyCell(table[r][c]);
      EXPECT_TRUE(any) << heading << ": column \"" << table[0][c] << "\" has no figure";
    }
    for (size_t r = 2; r < table.size(); ++r) {
      bool any = false;
      for (size_t c = 1; c < table[r].size(); ++c) any |= !emptyCell(table[r][c]);
      EXPECT_TRUE(any) << heading << ": row \"" << table[r][0] << "\" has no figure";
    }
  };
  for (const std::string& line : all) {
    if (line.rfind("## Measures", 0) == 0) break;  // the per-measure details follow
    if (line.rfind("#", 0) == 0) heading = line;
    if (line.rfind("|", 0) == 0) {
      table.push_back(cellsOf(line));
    } else {
      check();
      table.clear();
    }
  }
}

// The conservative policies the report reads from the culling declaration's note are the
// ones lod::isConservative names; the note without its "conservative" words gives none (the
// check can fail).
void conservativePoliciesAgreeWithTheCullPolicyCode() {
  const std::vector<std::string> parsed = report::conservativeCullPolicies(baseline());
  ASSERT_FALSE(parsed.empty());
  const results::MeasureDeclaration* culling = baseline().findMeasure("culling");
  ASSERT_NE(culling, nullptr);
  std::string note;
  for (const std::string& n : culling->notes) {
    if (n.rfind("policies", 0) == 0) note = n;
  }
  for (const lod::CullPolicy policy : lod::allCullPolicies()) {
    const std::string name(lod::cullPolicyName(policy));
    if (note.find(" " + name + " = ") == std::string::npos) continue;  // not in this run
    const bool listed = std::find(parsed.begin(), parsed.end(), name) != parsed.end();
    EXPECT_EQ(listed, lod::isConservative(policy)) << name;
  }
  results::Results broken;  // the declarations alone
  broken.measures = baseline().measures;
  for (results::MeasureDeclaration& d : broken.measures) {
    for (std::string& n : d.notes) {
      for (size_t at; (at = n.find("; conservative;")) != std::string::npos;) n.erase(at, 15);
    }
  }
  EXPECT_TRUE(report::conservativeCullPolicies(broken).empty());
}

// One test, so the 8 MB baseline is read once (gtest_discover_tests runs each test in its own
// process): about 2.5 s in Release.
TEST(Decision, DefaultRunDecisionsAnswersAgreementAndTables) {
  {
    SCOPED_TRACE("conservativePoliciesAgreeWithTheCullPolicyCode");
    conservativePoliciesAgreeWithTheCullPolicyCode();
  }
  {
    SCOPED_TRACE("everyCandidateIsADefaultNonControlVariantAndWatertightOnesWin");
    everyCandidateIsADefaultNonControlVariantAndWatertightOnesWin();
  }
  {
    SCOPED_TRACE("answersBlockOpensReportMdAndNamesANonControlChoicePerAsset");
    answersBlockOpensReportMdAndNamesANonControlChoicePerAsset();
  }
  {
    SCOPED_TRACE("reportMdHtmlAndAdviseAgreeForEveryAsset");
    reportMdHtmlAndAdviseAgreeForEveryAsset();
  }
  {
    SCOPED_TRACE("noEmptyColumnOrRowOfDashesInReportMdSummaries");
    noEmptyColumnOrRowOfDashesInReportMdSummaries();
  }
}

}  // namespace
}  // namespace tb
