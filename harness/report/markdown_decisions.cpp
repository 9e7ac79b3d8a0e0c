// report.md's opening: the answers block, the decision per surface asset, and the simulations
// keyed by scenario (markdown_sections.h).
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>

#include "harness/report/answers.h"
#include "harness/report/decision.h"
#include "harness/report/decision_inputs.h"
#include "harness/report/markdown_sections.h"
#include "harness/report/row_values.h"
#include "harness/report/summary.h"

namespace tb::report::markdown_detail {
namespace {

// Columns of a decision table; a column no candidate of the asset has a figure for is left out.
struct DecisionColumn {
  std::string header;
  std::function<std::optional<std::string>(const DecisionCandidate&)> cell;
};

// A column's header from the input the run declares for `role`; "" when none.
std::string columnHeader(const results::Results& results, results::DecisionRole role) {
  const auto input = inputFor(results, role);
  return input ? headerOf(*input) : "";
}

std::vector<DecisionColumn> decisionColumns(const results::Results& results,
                                            const AssetDecision& d) {
  using results::DecisionRole;
  const auto optional = [](const std::optional<double>& v) -> std::optional<std::string> {
    return v ? std::optional<std::string>(formatAdviceNumber(*v)) : std::nullopt;
  };
  std::string triangles = columnHeader(results, DecisionRole::kTrianglesAtTarget);
  if (!d.candidates.empty() && !d.candidates[0].figures.camera_path.empty() &&
      triangles.size() > 1 && triangles.back() == ')') {
    triangles.insert(triangles.size() - 1, ", path " + d.candidates[0].figures.camera_path);
  }
  return {
      {columnHeader(results, DecisionRole::kError),
       [=](const DecisionCandidate& c) { return optional(c.figures.error); }},
      {triangles,
       [=](const DecisionCandidate& c) -> std::optional<std::string> {
         if (!c.figures.triangles_1px) return std::nullopt;
         return formatAdviceNumber(*c.figures.triangles_1px) + " (" + c.figures.triangles_policy +
                ")";
       }},
      {columnHeader(results, DecisionRole::kMemoryRatio),
       [=](const DecisionCandidate& c) { return optional(c.figures.memory_ratio); }},
      {columnHeader(results, DecisionRole::kShaderCost),
       [=](const DecisionCandidate& c) { return optional(c.figures.instructions); }},
      {"watertight CPU / device",
       [](const DecisionCandidate& c) -> std::optional<std::string> {
         if (c.figures.cpu == Watertightness::kNotMeasured &&
             c.figures.device == Watertightness::kNotMeasured)
           return std::nullopt;
         return watertightText(c.figures.cpu, c.figures.cpu_points) + " / " +
                watertightText(c.figures.device, c.figures.device_points);
       }},
  };
}

void appendDecision(const results::Results& results, const AssetDecision& d, std::string* out) {
  *out += "### " + d.asset + "\n\n";
  std::vector<DecisionColumn> columns;
  for (DecisionColumn& column : decisionColumns(results, d)) {
    const bool any =
        std::any_of(d.candidates.begin(), d.candidates.end(),
                    [&](const DecisionCandidate& c) { return column.cell(c).has_value(); });
    if (any) columns.push_back(std::move(column));
  }
  std::vector<std::string> header{"rank", "technique/variant", "path"};
  for (const DecisionColumn& column : columns) header.push_back(column.header);
  // The front is over error and triangles at 1 px: no column when no candidate has both.
  const bool front = std::any_of(d.candidates.begin(), d.candidates.end(), [](const auto& c) {
    return c.figures.error && c.figures.triangles_1px;
  });
  if (front) header.push_back("Pareto front");
  appendHeader(out, header);
  for (size_t i = 0; i < d.candidates.size(); ++i) {
    const DecisionCandidate& c = d.candidates[i];
    std::vector<std::string> cells{i == 0 ? "**1 (recommended)**" : std::to_string(i + 1),
                                   c.technique + "/" + c.variant, c.path};
    for (const DecisionColumn& column : columns) cells.push_back(column.cell(c).value_or("n/a"));
    if (front) cells.push_back(c.on_front ? "yes" : "no");
    appendRow(out, cells);
  }
  *out += "\n" + d.why + " " + d.runner_up + "\n\n";
}

}  // namespace

void appendAnswers(const results::Results& results, const std::vector<AssetDecision>& decisions,
                   std::string* out) {
  *out += "## Answers\n\n";
  for (const Answer& a : answerQuestions(results, decisions)) {
    *out += "- **" + a.question + "** " + a.answer + " *(" + a.source + ")*\n";
  }
  *out += "\n";
}

namespace {

// The cracked row with the largest world gap of a record, and how many rows crack.
struct WorstCrack {
  const results::MetricRow* row = nullptr;
  double gap = 0;
  size_t rows = 0;
};

WorstCrack worstCrackOf(const DeclaredInput& points, const std::optional<DeclaredInput>& gap_input,
                        const results::MeasureResult& m) {
  WorstCrack worst;
  for (const results::MetricRow& row : m.rows) {
    if (row.status != results::MeasureStatus::kOk || rowFigure(*points.input, row).value_or(0) <= 0)
      continue;
    ++worst.rows;
    const double gap = gap_input ? rowFigure(*gap_input->input, row).value_or(0) : 0;
    if (worst.row == nullptr || gap > worst.gap) worst = {&row, gap, worst.rows};
  }
  return worst;
}

// "edge between patches 3 and 7 at t = 0.5 of patch 3's edge 1" (kCrackPlace's metrics: patch
// a, local a, patch b, local b, is-corner, t).
std::string crackPlace(const std::optional<DeclaredInput>& place, const results::MetricRow& row) {
  if (!place) return "not located";
  const auto value = [&](size_t i) { return metricAt(*place->input, row, i); };
  const auto n = [&](size_t i) { return formatAdviceNumber(value(i).value_or(-1)); };
  if (value(0).value_or(-1) < 0) return "not located (unpaired points)";
  if (value(4).value_or(0) > 0) {
    return "corner " + n(1) + " of patch " + n(0) + " / corner " + n(3) + " of patch " + n(2);
  }
  return "edge " + n(1) + " of patch " + n(0) + " at t = " + n(5) + " / patch " + n(2);
}

bool measureOk(const results::Record& record, const std::optional<DeclaredInput>& input) {
  const results::MeasureResult* m = input ? resultOf(record, *input) : nullptr;
  return m != nullptr && m->status == results::MeasureStatus::kOk;
}

}  // namespace

std::string crackPictureOf(const results::Results& results, const results::Record& record) {
  const auto error = inputFor(results, results::DecisionRole::kError);
  const auto picture = inputFor(results, results::DecisionRole::kCrackPicture);
  if (record.parameters.count("displacement") > 0 || !measureOk(record, error) || !picture)
    return "";
  bool cracks = false;
  if (const results::MeasureResult* m = resultOf(record, *picture)) {
    for (const results::MetricRow& row : m->rows) {
      cracks =
          cracks ||
          (m->status == results::MeasureStatus::kOk && row.status == results::MeasureStatus::kOk &&
           readsRow(*picture->input, row) && rowFigure(*picture->input, row).value_or(0) > 0);
    }
  }
  if (!cracks) return "";
  std::string path = "pictures/" + record.technique + "--";
  for (char c : record.asset) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '_' || c == '-';
    path += c == '/' ? std::string("--") : std::string(1, plain ? c : '_');
  }
  return path + "--cracks.png";
}

namespace {

std::string pictureLink(const results::Results& results, const results::Record& record) {
  const std::string path = crackPictureOf(results, record);
  if (path.empty() && record.parameters.count("displacement") > 0)
    return "none (displaced: no pictures)";
  return path.empty() ? "none (no CPU float crack or no error picture)"
                      : "[" + path.substr(path.find('/') + 1) + "](" + path + ")";
}

}  // namespace

// Where each default variant cracks: its worst cracks row and the place of the largest gap.
void appendCrackLocations(const results::Results& results, std::string* out) {
  const auto points = inputFor(results, results::DecisionRole::kCrackPoints);
  if (!points) return;
  const auto gap = inputFor(results, results::DecisionRole::kCrackGap);
  const auto place = inputFor(results, results::DecisionRole::kCrackPlace);
  std::string body;
  for (const auto& t : techniquesOf(results)) {
    if (t.variants.empty() || isControl(results, t.technique, t.variants.front())) continue;
    for (const results::Record& record : results.records) {
      if (record.technique != t.technique || record.variant != t.variants.front()) continue;
      const results::MeasureResult* m = resultOf(record, *points);
      if (m == nullptr || m->status != results::MeasureStatus::kOk) continue;
      const WorstCrack worst = worstCrackOf(*points, gap, *m);
      if (worst.row == nullptr) continue;
      const results::MetricRow& row = *worst.row;
      appendRow(
          &body,
          {record.asset, t.technique + "/" + t.variants.front(), std::to_string(worst.rows),
           rowKey(row, "backend") + ", " + rowKey(row, "spacing") + ", level " +
               rowKey(row, "level") +
               (rowKey(row, "levels").empty() ? "" : " (" + rowKey(row, "levels") + ")"),
           formatAdviceNumber(metricAt(*points->input, row, 0).value_or(0)),
           formatAdviceNumber(worst.gap), crackPlace(place, row), pictureLink(results, record)});
    }
  }
  if (body.empty()) return;
  *out += "## Where the default variants crack\n\n";
  *out +=
      "Per asset, the cracks rows (backend, spacing, level) where shared points differ and the "
      "row with the largest gap: where it is, by patch and local edge or corner (the patch "
      "order of the technique's patch data; t from the edge's first corner). The picture "
      "(in the run folder when the run rendered pictures, and in report.html): the surface "
      "with every unequal point of the CPU float row with the largest gap marked.\n\n";
  appendHeader(out, {"asset", "technique/variant", "rows cracked", "worst row",
                     "points not equal (count)", "largest gap (world units)", "where", "picture"});
  *out += body + "\n";
}

void appendDecisions(const results::Results& results, const std::vector<AssetDecision>& decisions,
                     std::string* out) {
  if (decisions.empty()) return;
  *out += "## Decision per surface asset\n\n";
  *out += std::string("Candidates: each technique's default variant (controls never). Rule: ") +
          kDecisionRule +
          ". Pareto front: no other candidate has lower-or-equal error and triangles at 1 px, one "
          "strictly lower. `tessbench advise ASSET` prints the same recommendation and ranks "
          "every variant under your constraints.\n\n";
  for (const AssetDecision& d : decisions) appendDecision(results, d, out);
}

namespace {

// The metrics of one simulation measure shown per scenario × technique/variant.
struct SimulationMeasure {
  std::string measure;
  std::vector<std::string> metrics;
};

// The kSimulationFigure inputs, a table per declaring measure in the run's order.
std::vector<SimulationMeasure> simulationMeasures(const results::Results& results) {
  std::vector<SimulationMeasure> measures;
  for (const DeclaredInput& input : inputsOf(results, results::DecisionRole::kSimulationFigure)) {
    if (measures.empty() || measures.back().measure != input.measure())
      measures.push_back({input.measure(), {}});
    for (const std::string& metric : input.input->metrics)
      measures.back().metrics.push_back(metric);
  }
  return measures;
}

}  // namespace

void appendSimulations(const results::Results& results, std::string* out) {
  const std::vector<SimulationMeasure> measures = simulationMeasures(results);
  std::string body;
  for (const SimulationMeasure& sm : measures) {
    MeasureSummary summary =
        summarizeMeasure(results, sm.measure, SummaryGrouping::kPerAsset, sm.metrics);
    std::stable_sort(summary.lines.begin(), summary.lines.end(),
                     [](const SummaryLine& a, const SummaryLine& b) { return a.asset < b.asset; });
    std::vector<std::string> metrics;
    for (const std::string& metric : sm.metrics) {
      const bool any = std::any_of(summary.lines.begin(), summary.lines.end(),
                                   [&](const SummaryLine& l) { return l.find(metric) != nullptr; });
      if (any) metrics.push_back(metric);
    }
    if (metrics.empty()) continue;
    body += fmt::format("### {}\n\n", sm.measure);
    std::vector<std::string> header{"scenario", "technique/variant"};
    for (const std::string& metric : metrics)
      header.push_back(metricHeader(results, sm.measure, metric));
    appendHeader(&body, header);
    for (const SummaryLine& line : summary.lines) {
      if (std::none_of(metrics.begin(), metrics.end(),
                       [&](const std::string& m) { return line.find(m); }))
        continue;
      std::vector<std::string> cells{line.asset, line.technique + "/" + line.variant};
      for (const std::string& metric : metrics) {
        const MetricStats* stats = line.find(metric);
        cells.push_back(
            stats == nullptr
                ? "n/a"
                : formatFigure(worstOf(*stats, directionOf(results, sm.measure, metric)),
                               unitOf(results, sm.measure, metric)));
      }
      appendRow(&body, cells);
    }
    body += "\n";
  }
  if (body.empty()) return;
  *out += "## Simulations by scenario\n\n";
  *out +=
      "Per scenario and solver or variant, the worst value over the measure's summary rows "
      "(n/a: the variant has no such row, e.g. an iteration count to a residual it did not "
      "reach).\n\n";
  *out += body;
}

}  // namespace tb::report::markdown_detail
