#include "harness/report/answers.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "harness/report/decision_inputs.h"
#include "harness/report/row_values.h"
#include "harness/report/summary.h"

namespace tb::report {
namespace {

using RowFn = std::function<void(const results::Record&, const results::MetricRow&)>;

// Every ok row the input reads in records of default, non-control variants.
// Rows of every pipeline path: the answers are over the whole run.
void forDefaultRows(const results::Results& results, const DeclaredInput& input, const RowFn& fn) {
  results::DecisionInput every_path = *input.input;
  every_path.rows_on_path = false;
  std::map<std::string, std::string> default_variant;
  for (const auto& t : techniquesOf(results)) {
    if (!t.variants.empty()) default_variant[t.technique] = t.variants.front();
  }
  for (const results::Record& record : results.records) {
    if (default_variant[record.technique] != record.variant ||
        isControl(results, record.technique, record.variant))
      continue;
    const results::MeasureResult* m = resultOf(record, input);
    if (m == nullptr || m->status != results::MeasureStatus::kOk) continue;
    for (const results::MetricRow& row : m->rows) {
      if (row.status == results::MeasureStatus::kOk && readsRow(every_path, row)) fn(record, row);
    }
  }
}

// "measure: metric, rows key = value" of the input, or "not declared" when the run has none.
std::string sourceText(const std::optional<DeclaredInput>& input) {
  return input ? sourceOf(*input) : "no measure of this run declares it";
}

std::string num(double value) { return formatAdviceNumber(value); }

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

Answer whichTechnique(const std::vector<AssetDecision>& decisions) {
  Answer a{"Which technique for this asset, and why?", "", ""};
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  for (const AssetDecision& d : decisions) {
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const auto& g) { return g.first == d.recommended(); });
    if (it == groups.end()) it = groups.insert(groups.end(), {d.recommended(), {}});
    it->second.push_back(d.asset);
  }
  std::sort(groups.begin(), groups.end(),
            [](const auto& x, const auto& y) { return x.second.size() > y.second.size(); });
  if (groups.empty()) a.answer = "no surface asset in this run.";
  for (const auto& [who, assets] : groups) {
    a.answer += fmt::format("{}**{}** on {} of {} ({})", a.answer.empty() ? "" : "; ", who,
                            assets.size(), decisions.size(), joined(assets));
  }
  a.source = "per asset: the decision below, its rule and figures";
  return a;
}

Answer didAnythingCrack(const results::Results& results) {
  Answer a{"Did anything crack?", "", ""};
  std::map<std::string, std::set<std::string>> cracked;  // who -> assets
  std::map<std::string, double> worst;
  size_t rows = 0;
  const auto input = inputFor(results, results::DecisionRole::kCrackPoints);
  if (input)
    forDefaultRows(results, *input, [&](const results::Record& r, const results::MetricRow& row) {
      ++rows;
      const double points = rowFigure(*input->input, row).value_or(0);
      if (points <= 0) return;
      const std::string who = r.technique + "/" + r.variant;
      cracked[who].insert(r.asset);
      worst[who] = std::max(worst[who], points);
    });
  std::vector<std::string> parts;
  for (const auto& [who, assets] : cracked) {
    parts.push_back(
        fmt::format("{} on {} assets (up to {} points)", who, assets.size(), num(worst[who])));
  }
  a.answer = rows == 0 ? "not measured in this run."
             : parts.empty()
                 ? fmt::format("no: every default variant is watertight on its {} {} rows.", rows,
                               input->measure())
                 : "yes: " + joined(parts) +
                       " (where: \"Where the default "
                       "variants crack\" below).";
  a.source = sourceText(input) +
             " > 0 in some row (CPU float and device capture, every level), default variants; "
             "controls crack by design and are left out";
  return a;
}

Answer accMemory(const results::Results& results) {
  const auto input = inputFor(results, results::DecisionRole::kMemorySaving);
  const std::string level = input ? input->input->where.count("level") > 0
                                        ? input->input->where.at("level")
                                        : std::string("every level")
                                  : std::string("?");
  Answer a{fmt::format("What does ACC save against triangles at level {}?", level), "", ""};
  std::vector<double> ratios;
  if (input)
    forDefaultRows(results, *input, [&](const results::Record& r, const results::MetricRow& row) {
      if (r.technique != "acc" || r.parameters.count("displacement") > 0) return;
      if (const auto ratio = rowFigure(*input->input, row)) ratios.push_back(*ratio);
    });
  if (ratios.empty()) {
    a.answer = "not measured in this run (no acc " + (input ? input->measure() : "") + " rows).";
  } else {
    const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
    a.answer = fmt::format(
        "the plain triangle mesh takes {}x acc's bytes with a 16-bit displacement map (median "
        "over {} assets, {} to {}x).",
        num(medianValue(ratios)), ratios.size(), num(*lo), num(*hi));
  }
  a.source = sourceText(input) + ", acc's default variant";
  return a;
}

Answer whichCulling(const results::Results& results) {
  Answer a{"Which culling policy?", "", ""};
  const std::vector<std::string> conservative = conservativeCullPolicies(results);
  std::map<std::string, std::vector<double>> efficiency;
  std::map<std::string, double> false_culls;
  const auto input = inputFor(results, results::DecisionRole::kCullEfficiency);
  const auto false_input = inputFor(results, results::DecisionRole::kFalseCulls);
  if (input)
    forDefaultRows(results, *input, [&](const results::Record&, const results::MetricRow& row) {
      const std::string policy = rowKey(row, "policy");
      if (std::find(conservative.begin(), conservative.end(), policy) == conservative.end()) return;
      if (const auto e = rowFigure(*input->input, row)) efficiency[policy].push_back(*e);
      if (false_input) false_culls[policy] += rowFigure(*false_input->input, row).value_or(0);
    });
  std::string best;
  for (const auto& [policy, values] : efficiency) {
    if (best.empty() || medianValue(values) > medianValue(efficiency[best])) best = policy;
  }
  if (best.empty()) {
    a.answer = "not measured in this run.";
  } else {
    std::vector<std::string> others;
    for (const auto& [policy, values] : efficiency) {
      if (policy != best) others.push_back(fmt::format("{} {}", policy, num(medianValue(values))));
    }
    a.answer = fmt::format(
        "**{}**: it culls a median {} of the patches an ideal culler removes over {} technique "
        "x asset x path summaries, with {} false culls in all (other conservative policies: {}).",
        best, num(medianValue(efficiency[best])), efficiency[best].size(), num(false_culls[best]),
        joined(others));
  }
  a.source = sourceText(input) + " and " + sourceText(false_input) +
             ", default variants, conservative policies only (" + joined(conservative) + ")";
  return a;
}

Answer factorPolicy(const results::Results& results) {
  Answer a{"Does any factor policy beat uniform?", "", ""};
  std::map<std::string, std::vector<double>> ratios;
  const auto input = inputFor(results, results::DecisionRole::kTriangleRatio);
  if (input)
    forDefaultRows(results, *input, [&](const results::Record&, const results::MetricRow& row) {
      if (results::isControlRow(*input->declaration, row.keys)) return;  // made to fail
      if (const auto r = rowFigure(*input->input, row))
        ratios[rowKey(row, input->input->chosen_key)].push_back(*r);
    });
  std::vector<std::string> parts;
  for (const auto& [policy, values] : ratios) {
    const size_t below =
        std::count_if(values.begin(), values.end(), [](double v) { return v < 1; });
    parts.push_back(fmt::format(
        "{} needs a median {}x uniform's triangles for a 1 px error ({}: below 1 on {} of {} "
        "technique x asset)",
        policy, num(medianValue(values)),
        medianValue(values) < 1 ? "beats uniform" : "does not beat it", below, values.size()));
  }
  a.answer = parts.empty() ? "not measured in this run." : joined(parts) + ".";
  a.source = sourceText(input) + ", default variants; control policies (made to fail) left out";
  return a;
}

Answer solver(const results::Results& results) {
  Answer a{"Is Gauss-Seidel better than Jacobi at 8 dispatches per frame?", "", ""};
  std::map<std::string, std::vector<std::pair<double, std::string>>> by_scenario;
  const auto input = inputFor(results, results::DecisionRole::kSolverResidual);
  for (const results::Record& record : results.records) {
    const results::MeasureResult* m = input ? resultOf(record, *input) : nullptr;
    if (m == nullptr || m->status != results::MeasureStatus::kOk) continue;
    for (const results::MetricRow& row : m->rows) {
      if (const auto r = rowFigure(*input->input, row))
        by_scenario[record.asset].push_back({*r, record.variant});
    }
  }
  std::vector<std::string> parts;
  size_t jacobi_wins = 0;
  for (auto& [scenario, values] : by_scenario) {
    std::sort(values.begin(), values.end());
    std::string order;
    for (const auto& [residual, variant] : values)
      order += (order.empty() ? "" : " < ") + variant + " " + num(residual);
    jacobi_wins += values.front().second.rfind("jacobi", 0) == 0 ? 1 : 0;
    parts.push_back(scenario + ": " + order);
  }
  a.answer = parts.empty() ? "not measured in this run."
                           : fmt::format(
                                 "{}: a Jacobi variant has the lowest residual on {} of {} "
                                 "scenarios ({}).",
                                 jacobi_wins == by_scenario.size() ? "no"
                                 : jacobi_wins == 0                ? "yes"
                                                                   : "not always",
                                 jacobi_wins, by_scenario.size(), joined(parts));
  a.source = sourceText(input) + " (" + (input ? input->input->label : "") + ", lower better)";
  return a;
}

}  // namespace

std::vector<std::string> conservativeCullPolicies(const results::Results& results) {
  const auto input = inputFor(results, results::DecisionRole::kCullEfficiency);
  std::vector<std::string> conservative;
  if (!input) return conservative;
  const results::MeasureDeclaration* culling = input->declaration;
  for (const std::string& note : culling->notes) {
    if (note.rfind("policies", 0) != 0) continue;
    // "NAME = description; [not ]conservative; NEXT = ...": each policy's segment runs to the
    // next " = " whose name ends a "; " (or the note's ": ").
    std::vector<std::pair<std::string, size_t>> names;  // name, where its description starts
    for (size_t at = note.find(" = "); at != std::string::npos; at = note.find(" = ", at + 3)) {
      const size_t start = note.find_last_of(";:", at);
      if (start == std::string::npos) continue;
      std::string name = note.substr(start + 1, at - start - 1);
      name.erase(0, name.find_first_not_of(' '));
      if (!name.empty() && name.find(' ') == std::string::npos) names.push_back({name, at});
    }
    for (size_t i = 0; i < names.size(); ++i) {
      const size_t end = i + 1 < names.size() ? names[i + 1].second : note.size();
      const std::string segment = note.substr(names[i].second, end - names[i].second);
      if (segment.find("; conservative;") != std::string::npos)
        conservative.push_back(names[i].first);
    }
  }
  return conservative;
}

std::function<bool(const results::MetricRow&)> summaryRowsOf(const results::Results& results,
                                                             const std::string& measure) {
  const auto input = inputFor(results, results::DecisionRole::kCullEfficiency);
  if (!input || input->measure() != measure) return {};
  return [keep = conservativeCullPolicies(results),
          scope = input->input->where](const results::MetricRow& row) {
    return results::rowInScope(scope, row.keys) &&
           std::find(keep.begin(), keep.end(), rowKey(row, "policy")) != keep.end();
  };
}

std::string summaryRowsNote(const results::Results& results, const std::string& measure) {
  const auto input = inputFor(results, results::DecisionRole::kCullEfficiency);
  if (!input || input->measure() != measure) return "";
  std::string scope;
  for (const auto& [key, value] : input->input->where) {
    scope += (scope.empty() ? "" : ", ") + key + " = " + value;
  }
  return measure + ": the summary rows (" + scope + ") of its conservative policies only (" +
         joined(conservativeCullPolicies(results)) + ")";
}

std::vector<Answer> answerQuestions(const results::Results& results,
                                    const std::vector<AssetDecision>& decisions) {
  return {whichTechnique(decisions), didAnythingCrack(results), accMemory(results),
          whichCulling(results),     factorPolicy(results),     solver(results)};
}

}  // namespace tb::report
