#include "harness/report/markdown.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "harness/report/summary.h"

namespace tb {
namespace {

std::string escapeCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

void appendRow(std::string* out, const std::vector<std::string>& cells) {
  *out += "|";
  for (const auto& cell : cells) {
    // Appended piece by piece: `" " + escapeCell(cell) + " |"` trips GCC 12's -Wrestrict.
    *out += ' ';
    *out += escapeCell(cell);
    *out += " |";
  }
  *out += "\n";
}

void appendHeader(std::string* out, const std::vector<std::string>& cells) {
  appendRow(out, cells);
  *out += "|";
  for (size_t i = 0; i < cells.size(); ++i) *out += "---|";
  *out += "\n";
}

void appendContext(const Results& results, std::string* out) {
  const RunContext& c = results.context;
  *out += "## Run context\n\n";
  appendHeader(out, {"field", "value"});
  appendRow(out, {"run id", c.run_id});
  appendRow(out, {"date (UTC)", c.date});
  appendRow(out, {"git sha", c.git_sha});
  appendRow(out, {"host", c.host});
  appendRow(out, {"CPU", c.cpu});
  appendRow(out, {"compiler", c.compiler + " (" + c.build_type + ")"});
  appendRow(out, {"Vulkan device", c.vulkan_device.empty() ? "none opened" : c.vulkan_device});
  for (const auto& [name, version] : c.libraries) appendRow(out, {name, version});
  appendRow(out, {"command", "`" + c.command_line + "`"});
  if (c.shard.count > 0) {
    appendRow(out, {"shard", std::to_string(c.shard.index) + " of " +
                                 std::to_string(c.shard.count) + " (numbered from 0)"});
  }
  for (const ShardSource& source : c.merged_from) {
    appendRow(out, {"merged from shard " + std::to_string(source.shard.index) + "/" +
                        std::to_string(source.shard.count),
                    source.folder + " (run " + source.run_id + ", " + source.date + ", " +
                        source.host + ")"});
  }
  *out += "\n";
}

void appendAssets(const Results& results, std::string* out) {
  *out += "## Assets\n\n";
  appendHeader(out, {"asset", "faces", "vertices", "faces are", "normals"});
  for (const AssetSummary& a : results.assets) {
    appendRow(out, {a.name, std::to_string(a.faces), std::to_string(a.vertices), a.face_kinds,
                    a.normals_computed ? "computed (angle-weighted)" : "from file"});
  }
  *out += "\n";
}

// The measure's metric columns: the declared metrics some row emits, in declared order,
// then any undeclared one (results written without declarations) in order of appearance.
struct Column {
  std::string name;
  std::string header;  // "max_gap_world (world, lower better)"
};

std::string directionLabel(Direction direction) {
  switch (direction) {
    case Direction::kLowerIsBetter:
      return ", lower better";
    case Direction::kHigherIsBetter:
      return ", higher better";
    case Direction::kNone:
      return "";
  }
  return "";
}

using RowFilter = bool (*)(const MetricRow&);

// The metric columns of the measure's rows that pass `filter`: declared metrics in
// declaration order, then undeclared ones in order of appearance.
std::vector<Column> metricColumns(const Results& results, const std::string& measure_id,
                                  const MeasureDeclaration* declaration, RowFilter filter) {
  std::vector<std::string> seen;  // emitted names, in order of appearance
  std::map<std::string, std::string> row_unit;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        for (const Metric& metric : row.metrics) {
          if (row_unit.emplace(metric.name, metric.unit).second) seen.push_back(metric.name);
        }
      }
    }
  }
  std::vector<Column> columns;
  if (declaration != nullptr) {
    for (const MetricSpec& spec : declaration->metrics) {
      if (!row_unit.contains(spec.name)) continue;
      columns.push_back({spec.name, spec.name + " (" + std::string(toString(spec.unit)) +
                                        directionLabel(spec.direction) + ")"});
    }
  }
  for (const std::string& name : seen) {
    if (declaration != nullptr && declaration->find(name) != nullptr) continue;
    columns.push_back({name, name + " (" + row_unit[name] + ")"});
  }
  return columns;
}

// What the declaration says once for the whole measure: its title, fixed notes, headline
// metrics and the meaning of the units its columns use.
void appendDeclaration(const MeasureDeclaration& declaration, std::string* out) {
  if (!declaration.title.empty()) *out += "**" + declaration.title + "**";
  if (!declaration.description.empty()) *out += ": " + declaration.description;
  if (!declaration.title.empty() || !declaration.description.empty()) *out += "\n\n";
  for (const std::string& note : declaration.notes) *out += "- " + note + "\n";
  if (!declaration.headline.empty()) {
    *out += "- headline: ";
    for (size_t i = 0; i < declaration.headline.size(); ++i) {
      *out += (i > 0 ? ", " : "") + declaration.headline[i];
    }
    *out += "\n";
  }
  // Units whose spelling does not already say it all ("count", "bytes", "ratio" do).
  std::vector<Unit> units;
  for (const MetricSpec& spec : declaration.metrics) {
    if (toString(spec.unit) != describe(spec.unit) &&
        std::find(units.begin(), units.end(), spec.unit) == units.end()) {
      units.push_back(spec.unit);
    }
  }
  if (!units.empty()) {
    *out += "- units: ";
    for (size_t i = 0; i < units.size(); ++i) {
      *out += std::string(i > 0 ? "; " : "") + std::string(toString(units[i])) + " = " +
              std::string(describe(units[i]));
    }
    *out += "\n";
  }
  *out += "\n";
}

// The notes that belong to one record (e.g. how this asset's patches were sampled),
// each naming its record.
void appendRecordNotes(const Results& results, const std::string& measure_id, std::string* out) {
  bool any = false;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const std::string& note : m.notes) {
        if (!any) *out += "Notes per record:\n\n";
        any = true;
        *out += "- " + record.technique + "/" + record.variant + " on " + record.asset + ": " +
                note + "\n";
      }
    }
  }
  if (any) *out += "\n";
}

// One table of the measure's rows that pass `filter`: a line per row, a column per key and
// metric. Records whose measure did not run are listed when `with_status_rows`.
void appendTable(const Results& results, const std::string& measure_id,
                 const MeasureDeclaration* declaration, RowFilter filter, bool with_status_rows,
                 std::string* out) {
  std::vector<std::string> key_names;
  std::set<std::string> seen_keys;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        for (const auto& [key, value] : row.keys) {
          if (seen_keys.insert(key).second) key_names.push_back(key);
        }
      }
    }
  }
  const std::vector<Column> columns = metricColumns(results, measure_id, declaration, filter);
  std::vector<std::string> header{"technique", "variant", "asset"};
  header.insert(header.end(), key_names.begin(), key_names.end());
  header.push_back("status");
  for (const Column& column : columns) header.push_back(column.header);
  appendHeader(out, header);
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      if (m.status != MeasureStatus::kOk) {
        if (!with_status_rows) continue;
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        cells.resize(cells.size() + key_names.size());
        cells.push_back(std::string(toString(m.status)) + ": " + m.reason);
        cells.resize(header.size());
        appendRow(out, cells);
        continue;
      }
      for (const MetricRow& row : m.rows) {
        if (!filter(row)) continue;
        std::vector<std::string> cells{record.technique, record.variant, record.asset};
        for (const std::string& key : key_names) {
          auto it = row.keys.find(key);
          cells.push_back(it == row.keys.end() ? "" : it->second);
        }
        if (row.status != MeasureStatus::kOk) {
          cells.push_back(std::string(toString(row.status)) + ": " + row.reason);
          cells.resize(header.size());
          appendRow(out, cells);
          continue;
        }
        cells.push_back("ok");
        for (const Column& column : columns) {
          std::string value;
          for (const Metric& metric : row.metrics) {
            if (metric.name == column.name) value = formatMetricValue(metric);
          }
          cells.push_back(value);
        }
        appendRow(out, cells);
      }
    }
  }
  *out += "\n";
}

size_t countRows(const Results& results, const std::string& measure_id, RowFilter filter) {
  size_t count = 0;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure_id) continue;
      for (const MetricRow& row : m.rows) count += filter(row) ? 1 : 0;
    }
  }
  return count;
}

// A measure with at most this many rows also gets its detail table in report.md (a small
// run reads whole); a larger one leaves its rows to tables/<measure>.csv and results.json.
constexpr size_t kDetailRowsInReport = 40;

std::string shortSha(const std::string& sha) { return sha.substr(0, 12); }

std::string directionWord(Direction direction) {
  switch (direction) {
    case Direction::kLowerIsBetter:
      return "lower better";
    case Direction::kHigherIsBetter:
      return "higher better";
    case Direction::kNone:
      return "context";
  }
  return "";
}

// "hausdorff (rel_diag, lower better)"
std::string metricHeader(const Results& results, const std::string& measure,
                         const std::string& metric) {
  const std::string unit = unitOf(results, measure, metric);
  const Direction direction = directionOf(results, measure, metric);
  std::string header = metric + " (";
  if (!unit.empty()) header += unit + ", ";
  return header + directionWord(direction) + ")";
}

std::string formatFigure(double value, const std::string& unit) {
  return formatMetricValue(Metric{"", value, unit});
}

// The first headline metric of a measure: what its matrices and job screens show.
std::string firstHeadline(const Results& results, const std::string& measure) {
  const MeasureDeclaration* declaration = results.findMeasure(measure);
  if (declaration != nullptr && !declaration->headline.empty()) return declaration->headline[0];
  return "";
}

// Rows of every status for one measure, for the regression screen.
struct StatusCounts {
  size_t records = 0;
  size_t ok = 0;
  size_t skipped = 0;
  size_t failed = 0;
};

StatusCounts countStatuses(const Results& results, const std::string& measure) {
  StatusCounts counts;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure != measure) continue;
      ++counts.records;
      if (m.status != MeasureStatus::kOk) {
        (m.status == MeasureStatus::kSkipped ? counts.skipped : counts.failed)++;
        continue;
      }
      for (const MetricRow& row : m.rows) {
        switch (row.status) {
          case MeasureStatus::kOk:
            ++counts.ok;
            break;
          case MeasureStatus::kSkipped:
            ++counts.skipped;
            break;
          case MeasureStatus::kFailed:
            ++counts.failed;
            break;
        }
      }
    }
  }
  return counts;
}

std::string headlineList(const Results& results, const std::string& measure) {
  const MeasureDeclaration* declaration = results.findMeasure(measure);
  std::string text;
  if (declaration == nullptr) return text;
  for (const std::string& metric : declaration->headline) {
    text += (text.empty() ? "" : ", ") + metric + " (" + unitOf(results, measure, metric) + ", " +
            directionWord(directionOf(results, measure, metric)) + ")";
  }
  return text;
}

// Job 1: is this run clean, and what to compare it with.
void appendRegressionScreen(const Results& results, const std::vector<std::string>& measures,
                            std::string* out) {
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
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      std::string reason = m.status == MeasureStatus::kFailed ? m.reason : "";
      for (const MetricRow& row : m.rows) {
        if (reason.empty() && row.status == MeasureStatus::kFailed) reason = row.reason;
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

// The best technique × variant of one asset by one metric: its worst value over the rows.
struct Best {
  std::string who;
  double value = 0;
  bool found = false;
};

// How many of the run's assets each technique measured, and why it refused the others
// (the first refusal as the example; every refusal is under "Not measured").
void appendCoverage(const Results& results, std::string* out) {
  appendHeader(out, {"technique", "assets measured", "assets refused", "first refusal"});
  for (const auto& technique : techniquesOf(results)) {
    std::set<std::string> measured;
    for (const Record& record : results.records) {
      if (record.technique == technique.technique) measured.insert(record.asset);
    }
    size_t refused = 0;
    std::string example;
    for (const Skip& skip : results.skipped) {
      if (skip.technique != technique.technique) continue;
      if (refused++ == 0) example = skip.asset + ": " + skip.reason;
    }
    appendRow(out, {technique.technique,
                    fmt::format("{} of {}", measured.size(), results.assets.size()),
                    std::to_string(refused), example});
  }
  *out += "\n";
}

// Job 2: per asset, which technique × variant wins each measure's first headline figure.
void appendChoiceScreen(const Results& results, const std::vector<std::string>& measures,
                        std::string* out) {
  *out += "## Choosing a technique per asset\n\n";
  *out += "Which techniques take which assets (every refusal with its reason: \"Not measured\" "
          "below):\n\n";
  appendCoverage(results, out);
  *out += "Per asset, the technique/variant with the best value of each measure's first headline "
          "figure, taking each candidate's worst value over its levels, spacings, backends and "
          "frames (ties: the first in run order). `tessbench advise ASSET` ranks every candidate "
          "under constraints (error, memory, watertightness, instructions).\n\n";
  std::vector<std::string> shown;
  std::vector<std::string> header{"asset"};
  std::vector<std::map<std::string, Best>> best_per_measure;
  for (const std::string& measure : measures) {
    const std::string metric = firstHeadline(results, measure);
    if (metric.empty()) continue;
    const Direction direction = directionOf(results, measure, metric);
    const MeasureSummary summary =
        summarizeMeasure(results, measure, SummaryGrouping::kPerAsset, {metric});
    std::map<std::string, Best> best;
    for (const SummaryLine& line : summary.lines) {
      const MetricStats* stats = line.find(metric);
      if (stats == nullptr) continue;
      const double value = worstOf(*stats, direction);
      Best& current = best[line.asset];
      const bool better = !current.found ||
                          (direction == Direction::kHigherIsBetter ? value > current.value
                                                                   : value < current.value);
      if (better) current = {line.technique + "/" + line.variant, value, true};
    }
    shown.push_back(measure);
    header.push_back(measure + ": " + metricHeader(results, measure, metric));
    best_per_measure.push_back(std::move(best));
  }
  appendHeader(out, header);
  for (const AssetSummary& asset : results.assets) {
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
void appendPublishingScreen(const Results& results, const std::vector<std::string>& measures,
                            std::string* out) {
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
          const Direction direction = directionOf(results, summaries[i].measure, metrics[i]);
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
void appendMatrix(const Results& results, const std::string& measure, std::string* out) {
  const std::string metric = firstHeadline(results, measure);
  if (metric.empty()) return;
  const Direction direction = directionOf(results, measure, metric);
  const std::string unit = unitOf(results, measure, metric);
  const MeasureSummary summary =
      summarizeMeasure(results, measure, SummaryGrouping::kPerAsset, {metric});
  std::set<std::string> measured_by;
  std::vector<std::string> inputs;
  for (const AssetSummary& asset : results.assets) inputs.push_back(asset.name);
  for (const Record& record : results.records) {
    const bool has = std::any_of(record.measures.begin(), record.measures.end(),
                                 [&](const MeasureResult& m) { return m.measure == measure; });
    if (!has) continue;
    measured_by.insert(record.technique);
    if (std::find(inputs.begin(), inputs.end(), record.asset) == inputs.end()) {
      inputs.push_back(record.asset);
    }
  }
  // A technique that refused an input the measure ran on stays a column (n/a there).
  std::set<std::string> measured_inputs;
  for (const Record& record : results.records) {
    for (const MeasureResult& m : record.measures) {
      if (m.measure == measure) measured_inputs.insert(record.asset);
    }
  }
  for (const Skip& skip : results.skipped) {
    if (measured_inputs.count(skip.asset) > 0) measured_by.insert(skip.technique);
  }
  std::vector<RunSelection::TechniqueVariants> techniques;
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
          results.skipped.begin(), results.skipped.end(), [&](const Skip& skip) {
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

// A measure's section: its declaration, then one line per technique × variant over every
// asset, each headline metric as median / worst; the rows themselves only when few.
void appendMeasureSection(const Results& results, const std::string& measure, std::string* out) {
  const MeasureDeclaration* declaration = results.findMeasure(measure);
  *out += "### " + measure + "\n\n";
  if (declaration != nullptr) appendDeclaration(*declaration, out);
  if (declaration != nullptr && !declaration->summary_scope.empty()) {
    std::string scope;
    for (const auto& [key, value] : declaration->summary_scope) {
      scope += (scope.empty() ? "" : ", ") + key + " = " + value;
    }
    *out += "Summaries read the rows with " + scope + ".\n\n";
  }
  const MeasureSummary summary = summarizeMeasure(results, measure, SummaryGrouping::kAcrossAssets);
  std::vector<std::string> header{"technique", "variant", "rows"};
  for (const std::string& metric : summary.metrics) {
    header.push_back(metricHeader(results, measure, metric) + " median / worst");
  }
  header.push_back("not measured");
  appendHeader(out, header);
  for (const SummaryLine& line : summary.lines) {
    std::vector<std::string> cells{line.technique, line.variant, std::to_string(line.ok_rows)};
    for (const std::string& metric : summary.metrics) {
      const MetricStats* stats = line.find(metric);
      if (stats == nullptr) {
        cells.push_back("—");
        continue;
      }
      const std::string unit = unitOf(results, measure, metric);
      cells.push_back(formatFigure(stats->median, unit) + " / " +
                      formatFigure(worstOf(*stats, directionOf(results, measure, metric)), unit));
    }
    std::string status;
    if (line.skipped_rows > 0) status += fmt::format("{} skipped", line.skipped_rows);
    if (line.failed_rows > 0) status += fmt::format("{}{} failed", status.empty() ? "" : ", ", line.failed_rows);
    if (!status.empty()) status += ": " + line.first_reason;
    cells.push_back(status);
    appendRow(out, cells);
  }
  *out += "\n";
  const size_t rows = countRows(results, measure, [](const MetricRow&) { return true; });
  if (rows <= kDetailRowsInReport) {
    appendTable(results, measure, declaration, [](const MetricRow&) { return true; }, true, out);
    appendRecordNotes(results, measure, out);
  } else {
    *out += fmt::format("Every row ({}): `tables/{}.csv` and results.json.\n\n", rows, measure);
  }
}

}  // namespace

std::string formatBytes(double bytes) {
  static const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int unit = 0;
  while (std::fabs(bytes) >= 1024 && unit < 4) {
    bytes /= 1024;
    ++unit;
  }
  return unit == 0 ? fmt::format("{:.0f} B", bytes) : fmt::format("{:.2f} {}", bytes, kUnits[unit]);
}

std::string formatMetricValue(const Metric& metric) {
  if (metric.unit == "bytes") return formatBytes(metric.value);
  if (std::isfinite(metric.value) && metric.value == std::floor(metric.value) &&
      std::fabs(metric.value) < 1e15) {
    return fmt::format("{:.0f}", metric.value);
  }
  return fmt::format("{:.4g}", metric.value);
}

std::string renderMarkdown(const Results& results) {
  const RunContext& c = results.context;
  const std::vector<std::string> measures = measureIds(results);
  size_t variants = 0;
  for (const auto& technique : techniquesOf(results)) variants += technique.variants.size();
  std::string out = "# tessbench report\n\n";
  out += fmt::format(
      "Run `{}` of {} · git {} · {} · suite {} · {} records ({} technique variants × {} "
      "assets), {} technique × asset pairs not measured. Every figure is measured by this run; "
      "every row is in `results.json` (schema {}) and `tables/<measure>.csv`, the charts and "
      "pictures in `report.html`.\n\n",
      c.run_id, c.date, shortSha(c.git_sha),
      c.vulkan_device.empty() ? "no Vulkan device" : c.vulkan_device,
      c.selection.suite.empty() ? "default" : c.selection.suite, results.records.size(), variants,
      results.assets.size(), results.skipped.size(), results.schema_version);
  appendRegressionScreen(results, measures, &out);
  appendChoiceScreen(results, measures, &out);
  appendPublishingScreen(results, measures, &out);
  out += "## Technique × asset matrices\n\n";
  out += "Each technique's default variant (its first); the worst value over the rows of the "
         "measure's summary scope. n/a: the technique does not take the asset; —: not run.\n\n";
  for (const std::string& measure : measures) appendMatrix(results, measure, &out);
  out += "## Measures\n\n";
  for (const std::string& measure : measures) appendMeasureSection(results, measure, &out);
  appendContext(results, &out);
  appendAssets(results, &out);
  if (!results.skipped.empty()) {
    out += "## Not measured\n\n";
    appendHeader(&out, {"technique", "asset", "reason"});
    for (const Skip& skip : results.skipped)
      appendRow(&out, {skip.technique, skip.asset, skip.reason});
    out += "\n";
  }
  size_t warnings = 0;
  size_t records_warned = 0;
  for (const Record& record : results.records) {
    warnings += record.warnings.size();
    records_warned += record.warnings.empty() ? 0 : 1;
  }
  if (warnings > 0) {
    out += "## Warnings\n\n";
    constexpr size_t kWarningsShown = 10;
    if (warnings <= kWarningsShown) {
      for (const Record& record : results.records) {
        for (const std::string& warning : record.warnings) {
          out += "- " + record.technique + "/" + record.variant + " on " + record.asset + ": " +
                 warning + "\n";
        }
      }
    } else {
      out += fmt::format("{} warnings on {} records (patch statistics and notes of the input): "
                         "`tables/warnings.csv`.\n",
                         warnings, records_warned);
    }
  }
  return out;
}

}  // namespace tb
