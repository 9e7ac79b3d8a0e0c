#include "harness/report/advice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

#include "harness/report/decision.h"
#include "harness/report/decision_inputs.h"
#include "harness/report/summary.h"

namespace tb::report {

const char* const kAdviceRankingRule =
    "candidates that meet every constraint given come first, ordered by error ascending, then "
    "instructions ascending, then memory ratio ascending, then technique/variant name (a "
    "missing figure sorts after every present one); excluded candidates follow in the same "
    "order, each with every constraint it fails and by how much. A candidate lacking the figure "
    "a constraint needs fails that constraint. Watertightness is a constraint unless "
    "--allow-cracks: every row of the watertightness figure (CPU and device backends, every "
    "spacing and level) must have no point that differs and none unpaired; skipped device rows "
    "leave it unverified, which fails it. Controls (variants made to show a failure) are never "
    "a choice. Techniques that refuse the asset are listed last with their reason.";

std::string adviceFigureUnits(const results::Results& results) {
  using results::DecisionRole;
  std::string text = "each figure is the worst over its measure's summary scope:";
  for (const DecisionRole role : {DecisionRole::kAdviceError, DecisionRole::kAdviceCost,
                                  DecisionRole::kAdviceMemory, DecisionRole::kAdviceCracks}) {
    const auto input = inputFor(results, role);
    if (!input) continue;
    text +=
        fmt::format(" {} = {} ({}){};", input->input->label, sourceOf(*input), input->input->column,
                    role == DecisionRole::kAdviceMemory ? ", its reciprocal" : "");
  }
  text.back() = '.';
  return text;
}

namespace {

// The measure and metrics of an advice input; an empty measure when the run declares none.
struct AdviceInput {
  std::string name;  // the figure's name: the input's label, else the role's spelling
  std::string measure;
  std::vector<std::string> metrics;
  std::string metric(size_t i) const { return i < metrics.size() ? metrics[i] : std::string(); }
};

AdviceInput adviceInput(const results::Results& results, results::DecisionRole role) {
  const auto input = inputFor(results, role);
  if (!input) return {std::string(results::toString(role)), "", {}};
  return {input->input->label, input->measure(), input->input->metrics};
}

using LineKey = std::pair<std::string, std::string>;  // technique, variant

// One measure's per-asset summary lines of `asset`, by technique and variant.
std::map<LineKey, SummaryLine> linesOf(const results::Results& results, const std::string& measure,
                                       const std::string& asset,
                                       const std::vector<std::string>& metrics) {
  std::map<LineKey, SummaryLine> lines;
  MeasureSummary summary = summarizeMeasure(results, measure, SummaryGrouping::kPerAsset, metrics);
  for (SummaryLine& line : summary.lines) {
    if (line.asset != asset) continue;
    LineKey key{line.technique, line.variant};
    lines.emplace(std::move(key), std::move(line));
  }
  return lines;
}

const SummaryLine* findLine(const std::map<LineKey, SummaryLine>& lines, const LineKey& key) {
  const auto it = lines.find(key);
  return it == lines.end() ? nullptr : &it->second;
}

// Why a candidate has no figure from `measure`.
std::string missingReason(const SummaryLine* line, const std::string& figure,
                          const std::string& measure, const std::string& metric) {
  if (line == nullptr) return fmt::format("no {} figure: {} measure not run", figure, measure);
  if (line->ok_rows == 0 && !line->first_reason.empty()) {
    const char* what = line->failed_rows > 0 && line->skipped_rows == 0 ? "failed" : "skipped";
    return fmt::format("no {} figure: {} measure {} ({})", figure, measure, what,
                       line->first_reason);
  }
  return fmt::format("no {} figure: no {} in the {} rows", figure, metric, measure);
}

// The worst value of one metric of a line, or the reason there is none.
std::optional<double> worstFigure(const results::Results& results, const SummaryLine* line,
                                  const std::string& figure, const std::string& measure,
                                  const std::string& metric, std::string* missing) {
  const MetricStats* stats = line != nullptr ? line->find(metric) : nullptr;
  if (stats == nullptr || stats->rows == 0) {
    *missing = missingReason(line, figure, measure, metric);
    return std::nullopt;
  }
  return worstOf(*stats, directionOf(results, measure, metric));
}

void readWatertightness(const AdviceInput& cracks, const SummaryLine* line,
                        CandidateFigures* figures) {
  if (line == nullptr) {
    figures->watertight = Watertightness::kNotMeasured;
    figures->watertight_detail =
        "no watertightness figure: " + (cracks.measure.empty() ? "no" : cracks.measure) +
        " measure not run";
    return;
  }
  const MetricStats* not_equal = line->find(cracks.metric(0));
  const MetricStats* unpaired = line->find(cracks.metric(1));
  figures->points_not_equal = not_equal != nullptr ? not_equal->max : 0;
  figures->unpaired_points = unpaired != nullptr ? unpaired->max : 0;
  if (figures->points_not_equal > 0 || figures->unpaired_points > 0) {
    figures->watertight = Watertightness::kCracked;
    figures->watertight_detail =
        fmt::format("{}: up to {} points not equal and {} unpaired in one {} row", cracks.measure,
                    formatAdviceNumber(figures->points_not_equal),
                    formatAdviceNumber(figures->unpaired_points), cracks.measure);
    return;
  }
  if (line->skipped_rows > 0 || line->failed_rows > 0) {
    figures->watertight = Watertightness::kUnverified;
    figures->watertight_detail =
        fmt::format("{} {} rows {} ({}): watertightness unverified on the device",
                    line->skipped_rows + line->failed_rows, cracks.measure,
                    line->failed_rows > 0 ? "skipped or failed" : "skipped", line->first_reason);
    return;
  }
  if (line->ok_rows == 0 || not_equal == nullptr || unpaired == nullptr) {
    figures->watertight = Watertightness::kNotMeasured;
    figures->watertight_detail = "no watertightness figure: no " + cracks.measure + " rows";
    return;
  }
  figures->watertight = Watertightness::kWatertight;
}

std::string overBy(const std::string& what, double value, double bound, const std::string& unit) {
  return fmt::format("{} {}{} > max {} (over by {}, {}x)", what, formatAdviceNumber(value),
                     unit.empty() ? "" : " " + unit, formatAdviceNumber(bound),
                     formatAdviceNumber(value - bound),
                     bound > 0 ? formatAdviceNumber(value / bound) : std::string("inf"));
}

// The figures' names in the constraints' failures.
struct AdviceNames {
  std::string error, memory, cost;
};

std::vector<std::string> failuresOf(const CandidateFigures& f, const AdviceConstraints& c,
                                    const AdviceNames& names) {
  std::vector<std::string> failures;
  if (c.max_error) {
    if (!f.error) {
      failures.push_back(f.missing_error);
    } else if (*f.error > *c.max_error) {
      failures.push_back(overBy(names.error, *f.error, *c.max_error, "rel_diag"));
    }
  }
  if (c.max_memory_ratio) {
    if (!f.memory_ratio) {
      failures.push_back(f.missing_memory);
    } else if (*f.memory_ratio > *c.max_memory_ratio) {
      failures.push_back(overBy(names.memory + " ratio", *f.memory_ratio, *c.max_memory_ratio, ""));
    }
  }
  if (c.watertight && f.watertight != Watertightness::kWatertight) {
    failures.push_back(f.watertight_detail);
  }
  if (c.max_instructions) {
    if (!f.instructions) {
      failures.push_back(f.missing_instructions);
    } else if (*f.instructions > *c.max_instructions) {
      failures.push_back(overBy(names.cost, *f.instructions, *c.max_instructions, ""));
    }
  }
  return failures;
}

double orInfinity(const std::optional<double>& value) {
  return value.value_or(std::numeric_limits<double>::infinity());
}

auto rankKey(const Candidate& c) {
  return std::make_tuple(!c.passes, orInfinity(c.figures.error), orInfinity(c.figures.instructions),
                         orInfinity(c.figures.memory_ratio), c.technique, c.variant);
}

// Why `c` comes after `before` (both pass): the first key of the rule that differs.
std::string behind(const Candidate& c, const Candidate& before, size_t before_rank) {
  const auto differ = [](const std::optional<double>& a, const std::optional<double>& b) {
    return orInfinity(a) != orInfinity(b);
  };
  // Enough digits to tell the two apart.
  const auto pair = [](const std::optional<double>& a, const std::optional<double>& b) {
    const auto shown = [](const std::optional<double>& v, int digits) {
      return v ? fmt::format("{:.{}g}", *v, digits) : std::string("none");
    };
    int digits = 4;
    while (digits < 17 && shown(a, digits) == shown(b, digits)) ++digits;
    return std::pair{shown(a, digits), shown(b, digits)};
  };
  if (differ(c.figures.error, before.figures.error)) {
    const auto [mine, theirs] = pair(c.figures.error, before.figures.error);
    return fmt::format("higher error than #{} ({} > {} rel_diag)", before_rank, mine, theirs);
  }
  if (differ(c.figures.instructions, before.figures.instructions)) {
    const auto [mine, theirs] = pair(c.figures.instructions, before.figures.instructions);
    return fmt::format("same error as #{}, more instructions ({} > {})", before_rank, mine, theirs);
  }
  if (differ(c.figures.memory_ratio, before.figures.memory_ratio)) {
    const auto [mine, theirs] = pair(c.figures.memory_ratio, before.figures.memory_ratio);
    return fmt::format("same error and instructions as #{}, larger memory ratio ({} > {})",
                       before_rank, mine, theirs);
  }
  return fmt::format("same figures as #{}, after it by name", before_rank);
}

void writeVerdicts(std::vector<Candidate>* ranked) {
  size_t passing = 0;
  for (const Candidate& c : *ranked) passing += c.passes ? 1 : 0;
  for (size_t i = 0; i < ranked->size(); ++i) {
    Candidate& c = (*ranked)[i];
    if (!c.passes) {
      std::string text;
      for (const std::string& failure : c.failures) text += (text.empty() ? "" : "; ") + failure;
      c.verdict = "excluded: " + text;
    } else if (i == 0) {
      c.verdict = fmt::format(
          "wins: meets every constraint given ({} of {} candidates do) and ranks first by the rule",
          passing, ranked->size());
    } else {
      c.verdict = "passes every constraint; " + behind(c, (*ranked)[i - 1], i);
    }
  }
}

bool selected(const AdviceConstraints& constraints, const std::string& technique) {
  return constraints.techniques.empty() ||
         std::find(constraints.techniques.begin(), constraints.techniques.end(), technique) !=
             constraints.techniques.end();
}

}  // namespace

const char* toString(Watertightness watertightness) {
  switch (watertightness) {
    case Watertightness::kNotMeasured:
      return "not measured";
    case Watertightness::kWatertight:
      return "yes";
    case Watertightness::kCracked:
      return "no";
    case Watertightness::kUnverified:
      return "unverified";
  }
  return "not measured";
}

std::string formatAdviceNumber(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15) {
    return fmt::format("{}", static_cast<long long>(value));
  }
  return fmt::format("{:.4g}", value);
}

Advice rankCandidates(const results::Results& results, const std::string& asset,
                      const AdviceConstraints& constraints) {
  Advice advice;
  advice.asset = asset;
  using results::DecisionRole;
  const AdviceInput error_input = adviceInput(results, DecisionRole::kAdviceError);
  const AdviceInput memory_input = adviceInput(results, DecisionRole::kAdviceMemory);
  const AdviceInput cost_input = adviceInput(results, DecisionRole::kAdviceCost);
  const AdviceInput cracks_input = adviceInput(results, DecisionRole::kAdviceCracks);
  const auto lines = [&](const AdviceInput& input) {
    return input.measure.empty() ? std::map<LineKey, SummaryLine>{}
                                 : linesOf(results, input.measure, asset, input.metrics);
  };
  const auto error = lines(error_input);
  const auto memory = lines(memory_input);
  const auto instructions = lines(cost_input);
  const auto cracks = lines(cracks_input);

  // The default variant of each technique is its first (summary.h: techniquesOf).
  std::map<std::string, std::string> default_variant;
  for (const auto& t : techniquesOf(results)) {
    if (!t.variants.empty()) default_variant[t.technique] = t.variants.front();
  }

  for (const results::Record& record : results.records) {
    if (record.asset != asset || !selected(constraints, record.technique)) continue;
    const bool seen =
        std::any_of(advice.ranked.begin(), advice.ranked.end(), [&](const Candidate& c) {
          return c.technique == record.technique && c.variant == record.variant;
        });
    if (seen) continue;
    Candidate c;
    c.technique = record.technique;
    c.variant = record.variant;
    const LineKey key{c.technique, c.variant};
    CandidateFigures& f = c.figures;
    const auto default_it = default_variant.find(c.technique);
    const bool is_default = default_it == default_variant.end() || default_it->second == c.variant;
    // error runs once in the default suite for a variant that only reorders the float
    // evaluation (VariantPolicy::kEveryDistinctSurface): the default's double surface.
    const SummaryLine* error_line = findLine(error, key);
    if (error_line == nullptr && !is_default) {
      error_line = findLine(error, {c.technique, default_it->second});
      f.error_from_default = error_line != nullptr;
    }
    f.error = worstFigure(results, error_line, error_input.name, error_input.measure,
                          error_input.metric(0), &f.missing_error);
    f.instructions = worstFigure(results, findLine(instructions, key), cost_input.name,
                                 cost_input.measure, cost_input.metric(0), &f.missing_instructions);
    // memory runs only on variants whose patch data differ from the default's
    // (VariantPolicy::kWhenPatchDataDiffers): another variant has the default's bytes.
    const SummaryLine* memory_line = findLine(memory, key);
    if (memory_line == nullptr && !is_default) {
      memory_line = findLine(memory, {c.technique, default_it->second});
      f.memory_from_default = memory_line != nullptr;
    }
    const std::optional<double> plain_over =
        worstFigure(results, memory_line, memory_input.name, memory_input.measure,
                    memory_input.metric(0), &f.missing_memory);
    if (plain_over && *plain_over > 0) f.memory_ratio = 1.0 / *plain_over;
    readWatertightness(cracks_input, findLine(cracks, key), &f);
    c.failures = failuresOf(f, constraints, {error_input.name, memory_input.name, cost_input.name});
    if (isControl(results, c.technique, c.variant)) {
      c.failures.insert(c.failures.begin(), "a control: made to show a failure, never a choice");
    }
    c.passes = c.failures.empty();
    advice.ranked.push_back(std::move(c));
  }
  std::stable_sort(advice.ranked.begin(), advice.ranked.end(),
                   [](const Candidate& a, const Candidate& b) { return rankKey(a) < rankKey(b); });
  writeVerdicts(&advice.ranked);

  const AssetDecision decision = decideAsset(results, asset);
  advice.recommendation = decision.recommended();
  advice.figure_units = adviceFigureUnits(results);
  advice.recommendation_why = decision.why + " " + decision.runner_up;
  for (const results::Skip& skip : results.skipped) {
    if (skip.asset == asset && selected(constraints, skip.technique)) {
      advice.unsupported.push_back({skip.technique, skip.reason});
    }
  }
  return advice;
}

namespace {

std::string cell(std::string text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n')
      out += ' ';
    else
      out += ch;
  }
  return out;
}

std::string figureCell(const std::optional<double>& value) {
  return value ? formatAdviceNumber(*value) : std::string("n/a");
}

std::string constraintsText(const AdviceConstraints& c) {
  std::string text;
  const auto add = [&](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  if (c.max_error) add("error <= " + formatAdviceNumber(*c.max_error) + " rel_diag");
  if (c.max_memory_ratio) add("memory ratio <= " + formatAdviceNumber(*c.max_memory_ratio));
  if (c.watertight) add("watertight");
  if (c.max_instructions) add("instructions <= " + formatAdviceNumber(*c.max_instructions));
  return text.empty() ? "none" : text;
}

}  // namespace

std::string renderAdviceMarkdown(const Advice& advice, const AdviceConstraints& constraints) {
  std::string out = fmt::format("# Advice for {}\n\n", advice.asset);
  out += fmt::format("- Constraints: {}\n", constraintsText(constraints));
  out += fmt::format("- Ranking rule: {}\n", kAdviceRankingRule);
  out += fmt::format("- Figures: {}\n\n", advice.figure_units);
  out +=
      "| rank | technique/variant | error (rel_diag) | instructions (count) | memory ratio "
      "(ratio) | watertight | verdict |\n|---:|---|---:|---:|---:|---|---|\n";
  for (size_t i = 0; i < advice.ranked.size(); ++i) {
    const Candidate& c = advice.ranked[i];
    std::string memory = figureCell(c.figures.memory_ratio);
    if (c.figures.memory_from_default) memory += " (default variant's)";
    std::string error = figureCell(c.figures.error);
    if (c.figures.error_from_default) error += " (default variant's)";
    out += fmt::format("| {} | {}/{} | {} | {} | {} | {} | {} |\n", i + 1, c.technique, c.variant,
                       error, figureCell(c.figures.instructions), memory,
                       toString(c.figures.watertight), cell(c.verdict));
  }
  for (const UnsupportedTechnique& u : advice.unsupported) {
    out += fmt::format("| - | {} | n/a | n/a | n/a | n/a | excluded: unsupported input: {} |\n",
                       u.technique, cell(u.reason));
  }
  out += advice.anyPasses() ? "\nFirst choice: " + advice.ranked.front().technique + "/" +
                                  advice.ranked.front().variant + "\n"
                            : "\nNo candidate meets every constraint.\n";
  if (!advice.recommendation.empty()) {
    out += fmt::format(
        "\nRecommendation (report.md's rule, default variants, no constraints): {}. "
        "{}\nRule: {}.\n",
        advice.recommendation, advice.recommendation_why, kDecisionRule);
  }
  return out;
}

}  // namespace tb::report
