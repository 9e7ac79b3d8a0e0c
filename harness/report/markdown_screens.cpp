// The three job screens of report.md (regression tracking, choosing a technique per asset,
// publishing tables) and the technique × asset matrices (markdown_sections.h).
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "harness/report/answers.h"
#include "harness/report/decision_inputs.h"
#include "harness/report/markdown_sections.h"
#include "harness/report/summary.h"

namespace tb::report::markdown_detail {
namespace {

// summaryRowsNote of the measure declaring the cull efficiency; "" when none does.
std::string cullSummaryNote(const results::Results& results) {
  const auto input = inputFor(results, results::DecisionRole::kCullEfficiency);
  return input ? summaryRowsNote(results, input->measure()) : "";
}

// Rows of every status for one measure, for the regression screen.
struct StatusCounts {
  size_t records = 0;
  size_t ok = 0;
  size_t skipped = 0;
  size_t failed = 0;
};

StatusCounts countStatuses(const results::Results& results, const std::string& measure) {
  StatusCounts counts;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure != measure) continue;
      ++counts.records;
      if (m.status != results::MeasureStatus::kOk) {
        (m.status == results::MeasureStatus::kSkipped ? counts.skipped : counts.failed)++;
        continue;
      }
      for (const results::MetricRow& row : m.rows) {
        switch (row.status) {
          case results::MeasureStatus::kOk:
            ++counts.ok;
            break;
          case results::MeasureStatus::kSkipped:
            ++counts.skipped;
            break;
          case results::MeasureStatus::kFailed:
            ++counts.failed;
            break;
        }
      }
    }
  }
  return counts;
}

std::string headlineList(const results::Results& results, const std::string& measure) {
  const results::MeasureDeclaration* declaration = results.findMeasure(measure);
  std::string text;
  if (declaration == nullptr) return text;
  for (const std::string& metric : declaration->headline) {
    text += (text.empty() ? "" : ", ") + metric + " (" + unitOf(results, measure, metric) + ", " +
            directionWord(directionOf(results, measure, metric)) + ")";
  }
  return text;
}

}  // namespace

// Job 1: is this run clean, and what to compare it with.
void appendRegressionScreen(const results::Results& results,
                            const std::vector<std::string>& measures, std::string* out) {
  *out += "## Regression tracking\n\n";
  *out +=
      "Every row of every measure, by status. `tessbench compare BASE NEW` lists what changed "
      "against another run (the committed baseline is `results/baseline`), worst first, by "
      "each metric's declared direction, and exits 1 on a worsened or missing figure.\n\n";
  appendHeader(out, {"measure", "records", "rows ok", "rows skipped", "rows failed", "headline"});
  std::vector<std::string> problems;
  for (const std::string& measure : measures) {
    const StatusCounts counts = countStatuses(results, measure);
    appendRow(out, {measure, std::to_string(counts.records), std::to_string(counts.ok),
                    std::to_string(counts.skipped), std::to_string(counts.failed),
                    headlineList(results, measure)});
  }
  *out += "\n";
  size_t failed_shown = 0;
  constexpr size_t kFailuresShown = 10;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      std::string reason = m.status == results::MeasureStatus::kFailed ? m.reason : "";
      for (const results::MetricRow& row : m.rows) {
        if (reason.empty() && row.status == results::MeasureStatus::kFailed) reason = row.reason;
      }
      if (reason.empty()) continue;
      if (failed_shown++ < kFailuresShown) {
        *out += "- failed: " + record.technique + "/" + record.variant + " " + record.asset + " " +
                m.measure + ": " + reason + "\n";
      }
    }
  }
  if (failed_shown > kFailuresShown) {
    *out += fmt::format("- … and {} more failures (status column of tables/*.csv)\n",
                        failed_shown - kFailuresShown);
  }
  if (failed_shown > 0) *out += "\n";
}

namespace {

// How many of the run's assets each technique measured, and why it refused the others
// (the first refusal as the example; every refusal is under "Not measured").
void appendCoverage(const results::Results& results, std::string* out) {
  appendHeader(out, {"technique", "assets measured", "assets refused", "first refusal"});
  for (const auto& technique : techniquesOf(results)) {
    std::set<std::string> measured;
    for (const results::Record& record : results.records) {
      if (record.technique == technique.technique) measured.insert(record.asset);
    }
    size_t refused = 0;
    std::string example;
    for (const results::Skip& skip : results.skipped) {
      if (skip.technique != technique.technique) continue;
      if (refused++ == 0) example = skip.asset + ": " + skip.reason;
    }
    appendRow(out,
              {technique.technique, fmt::format("{} of {}", measured.size(), results.assets.size()),
               std::to_string(refused), example});
  }
  *out += "\n";
}

}  // namespace

// Job 2: per asset, which technique × variant wins each measure's first headline figure.
void appendChoiceScreen(const results::Results& results, const std::vector<std::string>&,
                        std::string* out) {
  *out += "## Choosing a technique per asset\n\n";
  *out +=
      "Which techniques take which assets (every refusal with its reason: \"Not measured\" "
      "below):\n\n";
  appendCoverage(results, out);
  *out +=
      "The decision per asset is above (\"Decision per surface asset\"); `tessbench "
      "advise ASSET` ranks every candidate under constraints (error, memory, "
      "watertightness, instructions).\n\n";
}

namespace {

// The techniques of one family: surfaces (a record with an error result) or simulations.
std::vector<results::RunSelection::TechniqueVariants> familyOf(const results::Results& results,
                                                               bool surface) {
  // A surface technique is one with a result of the measure declaring the error.
  std::set<std::string> surfaces;
  const auto error = inputFor(results, results::DecisionRole::kError);
  for (const results::Record& record : results.records) {
    if (error && resultOf(record, *error) != nullptr) surfaces.insert(record.technique);
  }
  std::vector<results::RunSelection::TechniqueVariants> family;
  for (const auto& technique : techniquesOf(results)) {
    if ((surfaces.count(technique.technique) > 0) == surface) family.push_back(technique);
  }
  return family;
}

std::string figureCell(const results::Results& results, const MeasureSummary& summary,
                       const std::string& metric, const std::string& technique,
                       const std::string& variant, std::set<std::string>* assets) {
  for (const SummaryLine& line : summary.lines) {
    if (line.technique != technique || line.variant != variant) continue;
    const MetricStats* stats = line.find(metric);
    if (stats == nullptr) return "";
    for (const results::Record& record : results.records) {
      if (record.technique == technique && record.variant == variant) assets->insert(record.asset);
    }
    const std::string unit = unitOf(results, summary.measure, metric);
    return formatFigure(stats->median, unit) + " (" +
           formatFigure(worstOf(*stats, directionOf(results, summary.measure, metric)), unit) + ")";
  }
  return "";
}

// One family's publishing table: only the measures with a figure for it, only the variants
// with a figure; "n/a" where a variant has no rows of a measure.
void appendFamilyTable(const results::Results& results, const std::vector<std::string>& measures,
                       bool surface, std::string* out) {
  const auto family = familyOf(results, surface);
  std::vector<MeasureSummary> summaries;
  std::vector<std::string> metrics;
  std::vector<std::vector<std::string>> rows;  // technique, variant, cells..., assets
  for (const std::string& measure : measures) {
    const std::string metric = firstHeadline(results, measure);
    if (metric.empty()) continue;
    summaries.push_back(summarizeMeasure(results, measure, SummaryGrouping::kAcrossAssets, {metric},
                                         summaryRowsOf(results, measure)));
    metrics.push_back(metric);
  }
  std::vector<bool> used(summaries.size(), false);
  for (const auto& technique : family) {
    for (const std::string& variant : technique.variants) {
      std::vector<std::string> row{technique.technique, variant};
      std::set<std::string> assets;
      for (size_t i = 0; i < summaries.size(); ++i) {
        row.push_back(
            figureCell(results, summaries[i], metrics[i], technique.technique, variant, &assets));
        used[i] = used[i] || !row.back().empty();
      }
      if (assets.empty()) continue;
      row.push_back(std::to_string(assets.size()));
      rows.push_back(std::move(row));
    }
  }
  if (rows.empty()) return;
  *out += surface ? "### Surface techniques\n\n" : "### Simulations\n\n";
  std::vector<std::string> header{"technique", "variant"};
  for (size_t i = 0; i < summaries.size(); ++i) {
    if (used[i])
      header.push_back(summaries[i].measure + ": " +
                       metricHeader(results, summaries[i].measure, metrics[i]));
  }
  header.push_back(surface ? "assets covered" : "scenarios covered");
  appendHeader(out, header);
  for (const auto& row : rows) {
    std::vector<std::string> cells{row[0], row[1]};
    for (size_t i = 0; i < summaries.size(); ++i) {
      if (used[i]) cells.push_back(row[2 + i].empty() ? "n/a" : row[2 + i]);
    }
    cells.push_back(row.back());
    appendRow(out, cells);
  }
  *out += "\n";
}

}  // namespace

// Job 3: per family, one line per technique × variant, each measure's first headline figure
// over every asset: median (worst).
void appendPublishingScreen(const results::Results& results,
                            const std::vector<std::string>& measures, std::string* out) {
  *out += "## Publishing tables\n\n";
  *out +=
      "Per family, technique and variant, each measure's first headline figure over the "
      "assets (or scenarios) the variant was measured on: median (worst); the last column "
      "says how many, so two medians over different counts are not over the same assets. " +
      cullSummaryNote(results) +
      ". n/a: no rows of that measure for the variant. `tessbench table RUN --measure M "
      "--format markdown|csv|latex` renders one measure's summary with units and this run's "
      "context, ready to publish.\n\n";
  appendFamilyTable(results, measures, true, out);
  appendFamilyTable(results, measures, false, out);
}

// A measure's technique × asset matrix: each technique's default variant (its first), the
// worst value of the first headline metric over the rows; "n/a" where the technique does
// not take the asset, "—" where the measure did not run. Only the techniques with a record
// of the measure, or a refusal of an input it ran on, are columns, and only the inputs (assets,
// then scenarios) where some cell says more than "—" are rows, so a simulation's matrix lists its
// scenarios and a surface measure's leaves out displaced assets (whose rows its summary scope
// excludes).
void appendMatrix(const results::Results& results, const std::string& measure, std::string* out) {
  const std::string metric = firstHeadline(results, measure);
  if (metric.empty()) return;
  const results::Direction direction = directionOf(results, measure, metric);
  const std::string unit = unitOf(results, measure, metric);
  const MeasureSummary summary = summarizeMeasure(results, measure, SummaryGrouping::kPerAsset,
                                                  {metric}, summaryRowsOf(results, measure));
  std::set<std::string> measured_by;
  std::vector<std::string> inputs;
  for (const results::AssetSummary& asset : results.assets) inputs.push_back(asset.name);
  for (const results::Record& record : results.records) {
    const bool has =
        std::any_of(record.measures.begin(), record.measures.end(),
                    [&](const results::MeasureResult& m) { return m.measure == measure; });
    if (!has) continue;
    measured_by.insert(record.technique);
    if (std::find(inputs.begin(), inputs.end(), record.asset) == inputs.end()) {
      inputs.push_back(record.asset);
    }
  }
  // A technique that refused an input the measure ran on stays a column (n/a there).
  std::set<std::string> measured_inputs;
  for (const results::Record& record : results.records) {
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure == measure) measured_inputs.insert(record.asset);
    }
  }
  for (const results::Skip& skip : results.skipped) {
    if (measured_inputs.count(skip.asset) > 0) measured_by.insert(skip.technique);
  }
  std::vector<results::RunSelection::TechniqueVariants> techniques;
  for (const auto& technique : techniquesOf(results)) {
    if (measured_by.count(technique.technique) > 0) techniques.push_back(technique);
  }
  if (techniques.empty()) return;  // no technique ran it (a run of simulations alone, say)
  // The grid first, then only the columns and rows with a figure (or a skipped/failed
  // status): a simulation's column on surface assets, or an asset every technique refused,
  // says nothing.
  // A measure of policies (culling) shows the median over its conservative policies' rows: their
  // worst is 0 wherever a path leaves nothing to one half of a policy.
  const std::string rows_note = summaryRowsNote(results, measure);
  const bool median = !rows_note.empty();
  std::vector<std::vector<std::string>> grid;  // per input: the input, then a cell per technique
  for (const std::string& input : inputs) {
    std::vector<std::string> cells{input};
    for (const auto& technique : techniques) {
      std::string cell = "—";
      const bool unsupported = std::any_of(
          results.skipped.begin(), results.skipped.end(), [&](const results::Skip& skip) {
            return skip.technique == technique.technique && skip.asset == input;
          });
      if (unsupported) cell = "n/a";
      for (const SummaryLine& line : summary.lines) {
        if (line.technique != technique.technique || line.asset != input ||
            technique.variants.empty() || line.variant != technique.variants.front()) {
          continue;
        }
        if (const MetricStats* stats = line.find(metric)) {
          cell = formatFigure(median ? stats->median : worstOf(*stats, direction), unit);
        } else if (line.skipped_rows + line.failed_rows > 0) {
          cell = line.failed_rows > 0 ? "failed" : "skipped";
        }
      }
      cells.push_back(cell);
    }
    grid.push_back(std::move(cells));
  }
  const auto says = [](const std::string& cell) { return cell != "—" && cell != "n/a"; };
  std::vector<size_t> columns;
  for (size_t c = 1; c <= techniques.size(); ++c) {
    if (std::any_of(grid.begin(), grid.end(), [&](const auto& row) { return says(row[c]); }))
      columns.push_back(c);
  }
  if (columns.empty()) return;
  *out += "### " + measure + ": " + metricHeader(results, measure, metric) + "\n\n";
  if (median) *out += "The median (not the worst) over " + rows_note + ".\n\n";
  std::vector<std::string> header{"asset"};
  for (size_t c : columns) {
    const auto& technique = techniques[c - 1];
    header.push_back(technique.technique +
                     (technique.variants.empty() ? "" : "/" + technique.variants.front()));
  }
  appendHeader(out, header);
  for (const auto& row : grid) {
    std::vector<std::string> cells{row[0]};
    bool informative = false;
    for (size_t c : columns) {
      cells.push_back(row[c]);
      informative |= says(row[c]);
    }
    if (informative) appendRow(out, cells);
  }
  *out += "\n";
}

}  // namespace tb::report::markdown_detail
