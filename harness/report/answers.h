// The answers block that opens report.md and report.html: one line per question a user brings
// to a run (which technique for this asset; did anything crack; what ACC saves against
// triangles; which culling policy; does a factor policy beat uniform; Gauss-Seidel or Jacobi
// at 8 dispatches), each with the figure and the measure, metric and rows it comes from.
// Pure over the results model; a question the run has no rows for says so.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "harness/report/decision.h"
#include "harness/results/results_model.h"

namespace tb::report {

struct Answer {
  std::string question;  // "Which technique for this asset?"
  std::string answer;    // the answer with its figure
  std::string source;    // "error: hausdorff; adaptivity: ...": where the figure comes from
};

// The culling policies that never cull a patch covering a pixel, as the culling measure's
// declaration states them: its note on the policies says "NAME = ...; conservative;" (the
// measure's words for lod::isConservative; tests/report checks they agree). Empty when the
// run has no culling declaration or the note says none.
std::vector<std::string> conservativeCullPolicies(const results::Results& results);
// The rows a summary of `measure` reduces over: culling's summary rows of its conservative
// policies (a worst value over every policy would be "none"'s 0, or a false cull a
// conservative policy never makes); empty (every row) for any other measure.
std::function<bool(const results::MetricRow&)> summaryRowsOf(const results::Results& results,
                                                             const std::string& measure);
// What summaryRowsOf keeps, for a table's note: "" when every row.
std::string summaryRowsNote(const results::Results& results, const std::string& measure);

// The answers, in the order above; `decisions` from decideAssets(results).
std::vector<Answer> answerQuestions(const results::Results& results,
                                    const std::vector<AssetDecision>& decisions);

}  // namespace tb::report
