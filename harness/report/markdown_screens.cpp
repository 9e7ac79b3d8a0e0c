// The three job screens of report.md (regression tracking, choosing a technique per asset,
// publishing tables) and the technique × asset matrices (markdown_sections.h).
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "harness/report/markdown_sections.h"
#include "harness/report/summary.h"

namespace tb::report::markdown_detail {
namespace {

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
  *out += "Every row of every measure, by status. `tessbench compare BASE NEW` lists what changed "
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

// The best technique × variant of one asset by one metric: its worst value over the rows.
struct Best {
  std::string who;
  double value = 0;
  bool found = false;
};

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
    appendRow(out, {technique.technique,
                    fmt::format("{} of {}", measured.size(), results.assets.size()),
                    std::to_string(refused), example});
  }
  *out += "\n";
}

}  // namespace

// Job 2: per asset, which technique × variant wins each measure's first headline figure.
void appendChoiceScreen(const results::Results& results, const std::vector<std::string>& measures,
                        std::string* out) {
  *out += "## Choosing a technique per asset\n\n";
  *out += "Which techniques take which assets (every refusal with its reason: \"Not measured\" "
          "below):\n\n";
  appendCoverage(results, out);
  *out += "Per asset, the technique/variant with the best value of each measure's first headline "
          "figure, taking each candidate's worst value over its levels, spacings, backends and "
          "frames (ties: the first in run order); controls, the variants made to fail, are never "
          "named. `tessbench advise ASSET` ranks every candidate under constraints (error, "
          "memory, watertightness, instructions).\n\n";
  std::vector<std::string> shown;
  std::vector<std::string> header{"asset"};
  std::vector<std::map<std::string, Best>> best_per_measure;
  for (const std::string& measure : measures) {
    const std::string metric = firstHeadline(results, measure);
    if (metric.empty()) continue;
    const results::Direction direction = directionOf(results, measure, metric);
    const MeasureSummary summary =
        summarizeMeasure(results, measure, SummaryGrouping::kPerAsset, {metric});
    std::map<std::string, Best> best;
    for (const SummaryLine& line : summary.lines) {
      const MetricStats* stats = line.find(metric);
      if (stats == nullptr || isControl(results, line.technique, line.variant)) continue;
      const double value = worstOf(*stats, direction);
      Best& current = best[line.asset];
      const bool better = !current.found || (direction == results::Direction::kHigherIsBetter
                                                 ? value > current.value
                                                 : value < current.value);
      if (better) current = {line.technique + "/" + line.variant, value, true};
    }
    shown.push_back(measure);
    header.push_back(measure + ": " + metricHeader(results, measure, metric));
    best_per_measure.push_back(std::move(best));
  }
  appendHeader(out, header);
  for (const results::AssetSummary& asset : results.assets) {
    std::vector<std::string> cells{asset.name};
    for (size_t i = 0; i < shown.size(); ++i) {
      const auto it = best_per_measure[i].find(asset.name);
      if (it == best_per_measure[i].end()) {
        cells.push_back("—");
        continue;
      }
      const std::string unit = unitOf(results, shown[i], firstHeadline(results, shown[i]));
      cells.push_back(it->second.who + " " + formatFigure(it->second.value, unit));
    }
    appendRow(out, cells);
  }
  *out += "\n";
}

// Job 3: one line per technique × variant, each measure's first headline figure over every
// asset: median (worst).
void appendPublishingScreen(const results::Results& results,
                            const std::vector<std::string>& measures, std::string* out) {
  *out += "## Publishing tables\n\n";
  *out += "Per technique and variant, each measure's first headline figure over every asset and "
          "row: median (worst). `tessbench table RUN --measure M --format markdown|csv|latex` "
          "renders one measure's summary with units and this run's context, ready to publish.\n\n";
  std::vector<std::string> header{"technique", "variant"};
  std::vector<MeasureSummary> summaries;
  std::vector<std::string> metrics;
  for (const std::string& measure : measures) {
    const std::string metric = firstHeadline(results, measure);
    if (metric.empty()) continue;
    summaries.push_back(
        summarizeMeasure(results, measure, SummaryGrouping::kAcrossAssets, {metric}));
    metrics.push_back(metric);
    header.push_back(measure + ": " + metricHeader(results, measure, metric));
  }
  appendHeader(out, header);
  for (const auto& technique : techniquesOf(results)) {
    for (const std::string& variant : technique.variants) {
      std::vector<std::string> cells{technique.technique, variant};
      bool any = false;
      for (size_t i = 0; i < summaries.size(); ++i) {
        std::string cell = "—";
        for (const SummaryLine& line : summaries[i].lines) {
          if (line.technique != technique.technique || line.variant != variant) continue;
          const MetricStats* stats = line.find(metrics[i]);
          if (stats == nullptr) break;
          const std::string unit = unitOf(results, summaries[i].measure, metrics[i]);
          const results::Direction direction =
              directionOf(results, summaries[i].measure, metrics[i]);
          cell = formatFigure(stats->median, unit) + " (" +
                 formatFigure(worstOf(*stats, direction), unit) + ")";
          any = true;
        }
        cells.push_back(cell);
      }
      if (any) appendRow(out, cells);
    }
  }
  *out += "\n";
}

// A measure's technique × asset matrix: each technique's default variant (its first), the
// worst value of the first headline metric over the rows; "n/a" where the technique does
// not take the asset, "—" where the measure did not run. Only the techniques with a record
// of the measure, or a refusal of an input it ran on, are columns, and only the inputs (assets, then scenarios) where some cell
// says more than "—" are rows, so a simulation's matrix lists its scenarios and a surface
// measure's leaves out displaced assets (whose rows its summary scope excludes).
void appendMatrix(const results::Results& results, const std::string& measure, std::string* out) {
  const std::string metric = firstHeadline(results, measure);
  if (metric.empty()) return;
  const results::Direction direction = directionOf(results, measure, metric);
  const std::string unit = unitOf(results, measure, metric);
  const MeasureSummary summary =
      summarizeMeasure(results, measure, SummaryGrouping::kPerAsset, {metric});
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
  *out += "### " + measure + ": " + metricHeader(results, measure, metric) + "\n\n";
  std::vector<std::string> header{"asset"};
  for (const auto& technique : techniques) {
    header.push_back(technique.technique +
                     (technique.variants.empty() ? "" : "/" + technique.variants.front()));
  }
  appendHeader(out, header);
  for (const std::string& input : inputs) {
    std::vector<std::string> cells{input};
    bool informative = false;
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
          cell = formatFigure(worstOf(*stats, direction), unit);
        } else if (line.skipped_rows + line.failed_rows > 0) {
          cell = line.failed_rows > 0 ? "failed" : "skipped";
        }
      }
      informative |= cell != "—";
      cells.push_back(cell);
    }
    if (informative) appendRow(out, cells);
  }
  *out += "\n";
}

}  // namespace tb::report::markdown_detail
