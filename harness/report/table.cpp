#include "harness/report/table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <span>
#include <tuple>

#include "harness/report/answers.h"
#include "harness/report/comparison.h"
#include "harness/report/decision_inputs.h"
#include "harness/report/published_figures.h"
#include "harness/report/row_values.h"
#include "harness/report/summary.h"

namespace tb::report {
namespace {

// 4 significant digits; integers without a fraction.
std::string figure(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15) {
    return fmt::format("{}", static_cast<long long>(value));
  }
  return fmt::format("{:.4g}", value);
}

std::string orNone(const std::string& text, const char* none) {
  return text.empty() ? std::string(none) : text;
}

}  // namespace

std::optional<TableFormat> parseTableFormat(std::string_view text) {
  if (text == "markdown") return TableFormat::kMarkdown;
  if (text == "csv") return TableFormat::kCsv;
  if (text == "latex") return TableFormat::kLatex;
  return std::nullopt;
}

std::vector<std::string> runContextFootnote(const results::Results& results) {
  const results::RunContext& c = results.context;
  std::vector<std::string> lines;
  lines.push_back(fmt::format("Run {} ({}), git {}, Vulkan device: {}, suite: {}.",
                              orNone(c.run_id, "unnamed"), orNone(c.date, "undated"),
                              orNone(c.git_sha, "unknown"), orNone(c.vulkan_device, "none"),
                              orNone(c.selection.suite, "default")));
  std::string libraries;
  for (const auto& [name, version] : c.libraries) {
    libraries += fmt::format("{}{} {}", libraries.empty() ? "" : ", ", name, version);
  }
  lines.push_back("Libraries: " + orNone(libraries, "not recorded") + ".");
  return lines;
}

std::vector<TextTable> comparisonTables(const results::Results& results,
                                        const results::MeasureDeclaration& declaration) {
  std::vector<TextTable> tables;
  for (const results::ComparisonSpec& spec : declaration.comparisons) {
    const ComparisonTable comparison = comparisonTable(results, declaration, spec);
    for (const ComparisonGroup& group : comparison.groups) {
      TextTable table;
      table.title = spec.title + (group.facets.empty() ? "" : " (" + group.name() + ")");
      table.header = {"technique"};
      table.numeric = {false};
      for (const std::string& column : group.columns) {
        table.header.push_back(column + (comparison.unit.empty() || column != group.columns.front()
                                             ? ""
                                             : " (" + comparison.unit + ")"));
        table.numeric.push_back(true);
      }
      for (const ComparisonLine& line : group.lines) {
        std::vector<std::string> row{line.technique};
        for (const ComparisonCell& cell : line.cells) {
          std::string text = cell.value ? fmt::format("{:.6g}", *cell.value) : "";
          for (const std::optional<double>& more : cell.more) {
            text += " / " + (more ? fmt::format("{:.6g}", *more) : std::string("—"));
          }
          row.push_back(text);
        }
        table.rows.push_back(std::move(row));
      }
      table.footnote = {spec.title + " (measure " + declaration.measure + ")"};
      for (std::string& line : runContextFootnote(results)) table.footnote.push_back(line);
      tables.push_back(std::move(table));
    }
  }
  return tables;
}

TextTable summaryTable(const results::Results& results, const SummaryTableOptions& options) {
  const MeasureSummary summary = summarizeMeasure(
      results, options.measure,
      options.per_asset ? SummaryGrouping::kPerAsset : SummaryGrouping::kAcrossAssets,
      options.metrics, summaryRowsOf(results, options.measure), /*split_paths=*/true);
  TextTable table;
  table.title = summary.declaration != nullptr ? summary.declaration->title : options.measure;
  table.header = {"technique", "variant"};
  if (options.per_asset) table.header.push_back("asset");
  // The pipeline's path (tessellator | compute) where the measure keys its rows by it.
  const bool paths = std::any_of(summary.lines.begin(), summary.lines.end(),
                                 [](const SummaryLine& line) { return !line.path.empty(); });
  if (paths) table.header.push_back("path");
  table.numeric.assign(table.header.size(), false);
  for (const std::string& metric : summary.metrics) {
    const std::string unit = unitOf(results, options.measure, metric);
    const std::string suffix = unit.empty() ? "" : " (" + unit + ")";
    table.header.push_back(metric + " median" + suffix);
    table.header.push_back(metric + " worst" + suffix);
    table.numeric.insert(table.numeric.end(), {true, true});
  }
  for (const SummaryLine& line : summary.lines) {
    std::vector<std::string> row{line.technique, line.variant};
    if (options.per_asset) row.push_back(line.asset);
    if (paths) row.push_back(line.path);
    for (const std::string& metric : summary.metrics) {
      const MetricStats* stats = line.find(metric);
      if (stats == nullptr || stats->rows == 0) {
        const std::string status = line.ok_rows == 0 && line.skipped_rows + line.failed_rows > 0
                                       ? (line.failed_rows > 0 ? "failed" : "skipped")
                                       : "";
        row.insert(row.end(), {status, status});
        continue;
      }
      row.push_back(figure(stats->median));
      row.push_back(figure(worstOf(*stats, directionOf(results, options.measure, metric))));
    }
    table.rows.push_back(std::move(row));
  }
  table.footnote.push_back(fmt::format(
      "{} (measure {}): median and worst over the rows of its summary scope{}; worst is the "
      "largest where lower is better, the smallest where higher is better.",
      table.title, options.measure, options.per_asset ? "" : " and every asset"));
  if (const std::string note = summaryRowsNote(results, options.measure); !note.empty()) {
    table.footnote.push_back("Rows: " + note + ".");
  }
  for (std::string& line : runContextFootnote(results)) table.footnote.push_back(std::move(line));
  return table;
}

namespace {

// Ours beside the talk's memory table: per technique x variant and level, the median over the
// run's assets of bytes per patch scaled to the talk's patch count, and the ratio.
TextTable publishedMemory(const results::Results& results) {
  TextTable table;
  table.title = "Memory against plain triangle meshes, published and ours";
  table.header = {"source",
                  "technique/variant",
                  "level",
                  "plain mesh (MB)",
                  "technique with displacement (MB)",
                  "plain / technique (ratio)"};
  table.numeric = {false, false, true, true, true, true};
  // (technique/variant, level) -> per-asset values.
  struct Values {
    std::vector<double> plain_mb, technique_mb, ratio;
  };
  std::map<std::pair<std::string, int>, Values> ours;
  std::vector<std::string> order;
  // kPublishedMemory's metrics: patches, plain bytes, technique bytes, plain / technique.
  const auto input = inputFor(results, results::DecisionRole::kPublishedMemory);
  for (const results::Record& record : results.records) {
    const results::MeasureResult* m = input ? resultOf(record, *input) : nullptr;
    if (m == nullptr || m->status != results::MeasureStatus::kOk) continue;
    const std::string who = record.technique + "/" + record.variant;
    if (std::find(order.begin(), order.end(), who) == order.end()) order.push_back(who);
    for (const results::MetricRow& row : m->rows) {
      const auto level = row.keys.find("level");
      if (row.status != results::MeasureStatus::kOk || level == row.keys.end()) continue;
      const auto at = [&](size_t i) { return metricAt(*input->input, row, i).value_or(0); };
      if (!metricAt(*input->input, row, 0) || at(0) <= 0) continue;
      Values& values = ours[{who, std::atoi(level->second.c_str())}];
      const double scale = kPublishedMemoryPatches / at(0) / 1e6;
      values.plain_mb.push_back(at(1) * scale);
      values.technique_mb.push_back(at(2) * scale);
      values.ratio.push_back(at(3));
    }
  }
  for (const PublishedMemoryRow& published : publishedMemoryTable()) {
    table.rows.push_back({sourceName(kPublishedMemorySeed), "-", std::to_string(published.level),
                          figure(published.plain_mb), figure(published.technique_mb),
                          figure(published.plain_mb / published.technique_mb)});
    for (const std::string& who : order) {
      const auto it = ours.find({who, published.level});
      if (it == ours.end()) continue;
      const Values& v = it->second;
      table.rows.push_back({"ours", who, std::to_string(published.level),
                            figure(medianValue(v.plain_mb)), figure(medianValue(v.technique_mb)),
                            figure(medianValue(v.ratio))});
    }
  }
  table.footnote.push_back("Published: " + sourceCitation(kPublishedMemorySeed) +
                           "; its table fits about 14,400 quad patches, a plain vertex of about "
                           "16 B and one 16-bit displacement texel per vertex.");
  table.footnote.push_back(
      "Ours: " + (input ? sourceOf(*input) : std::string("not declared")) +
      "; the bytes per patch x 14,400 patches (MB = 10^6 B) and the ratio, each the median over "
      "the run's assets. Our plain vertex is 32 B plus 32-bit indices, so our ratios run "
      "higher.");
  for (std::string& line : runContextFootnote(results)) table.footnote.push_back(std::move(line));
  return table;
}

// The published_figures rows: the published shader costs and ours for the same stage.
TextTable publishedInstructions(const results::Results& results) {
  TextTable table;
  table.title = "Shader costs, published and ours";
  table.header = {"source",
                  "technique/variant",
                  "what",
                  "published ALU (count)",
                  "published loads (count)",
                  "ours ALU, vector (count)",
                  "ours ALU, scalar (count)",
                  "ours loads (count)",
                  "ours on RDNA2, machine instructions (count)",
                  "assets (count)"};
  table.numeric = {false, false, false, true, true, true, true, true, true, true};
  // The figures are the shaders', the same on every asset: one row per distinct figure line,
  // with the number of assets it was measured on (two lines for one stage would show the
  // figures differ between assets).
  std::map<std::vector<std::string>, size_t> seen;
  std::vector<std::string> sources;
  // kPublishedCost's metrics: published ALU, published loads, ours vector, scalar, loads,
  // ours on RDNA2 (absent in runs before the isa measure, or without the radeon ICD).
  const auto input = inputFor(results, results::DecisionRole::kPublishedCost);
  for (const results::Record& record : results.records) {
    const results::MeasureResult* found = input ? resultOf(record, *input) : nullptr;
    for (const results::MeasureResult& m : std::span(found, found == nullptr ? 0 : 1)) {
      if (m.status != results::MeasureStatus::kOk) continue;
      for (const results::MetricRow& row : m.rows) {
        if (row.status != results::MeasureStatus::kOk) continue;
        const auto source = row.keys.find("source");
        const auto what = row.keys.find("what");
        const std::string source_name = source != row.keys.end() ? source->second : "";
        if (std::find(sources.begin(), sources.end(), source_name) == sources.end()) {
          sources.push_back(source_name);
        }
        const auto v = [&](size_t i) {
          const auto value = metricAt(*input->input, row, i);
          return value ? figure(*value) : std::string();
        };
        // Published loads 0: not published (the measure's notes).
        const std::string loads = v(1) == "0" ? "" : v(1);
        std::vector<std::string> line{source_name,
                                      record.technique + "/" + record.variant,
                                      what != row.keys.end() ? what->second : "",
                                      v(0),
                                      loads,
                                      v(2),
                                      v(3),
                                      v(4),
                                      v(5)};
        const auto [it, added] = seen.emplace(line, table.rows.size());
        if (added) {
          line.push_back("1");
          table.rows.push_back(std::move(line));
        } else {
          std::string& count = table.rows[it->second].back();
          count = std::to_string(std::stoul(count) + 1);
        }
      }
    }
  }
  for (const std::string& name : sources) {
    table.footnote.push_back("Published: " + sourceCitationByName(name) + ".");
  }
  table.footnote.push_back(
      "Ours: float arithmetic + FMA instructions of the stage after spirv-opt -O (vector: per "
      "SPIR-V instruction, as a D3D listing counts a float3 mad once; scalar: per component) "
      "and its loads and stores (the " +
      (input ? input->measure() : std::string("undeclared")) + " measure).");
  for (std::string& line : runContextFootnote(results)) table.footnote.push_back(std::move(line));
  return table;
}

}  // namespace

namespace {

bool declares(const results::Results& results, results::DecisionRole role,
              const std::string& measure) {
  const auto input = inputFor(results, role);
  return input && input->measure() == measure;
}

}  // namespace

bool hasPublishedTable(const results::Results& results, const std::string& measure) {
  return declares(results, results::DecisionRole::kPublishedMemory, measure) ||
         declares(results, results::DecisionRole::kPublishedCost, measure);
}

TextTable publishedTable(const results::Results& results, const std::string& measure) {
  if (declares(results, results::DecisionRole::kPublishedMemory, measure))
    return publishedMemory(results);
  if (declares(results, results::DecisionRole::kPublishedCost, measure))
    return publishedInstructions(results);
  return {};
}

std::string latexEscape(std::string_view text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "\\&";
        break;
      case '%':
        out += "\\%";
        break;
      case '$':
        out += "\\$";
        break;
      case '#':
        out += "\\#";
        break;
      case '_':
        out += "\\_";
        break;
      case '{':
        out += "\\{";
        break;
      case '}':
        out += "\\}";
        break;
      case '~':
        out += "\\textasciitilde{}";
        break;
      case '^':
        out += "\\textasciicircum{}";
        break;
      case '\\':
        out += "\\textbackslash{}";
        break;
      case '<':
        out += "\\textless{}";
        break;
      case '>':
        out += "\\textgreater{}";
        break;
      case '\n':
        out += ' ';
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string csvField(std::string_view text) {
  const bool quote =
      text.find_first_of(",\"\r\n") != std::string_view::npos ||
      (!text.empty() && (text.front() == '#' || text.front() == ' ' || text.back() == ' '));
  if (!quote) return std::string(text);
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  return out + "\"";
}

namespace {

std::string markdownCell(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '|')
      out += "\\|";
    else if (ch == '\n')
      out += ' ';
    else
      out += ch;
  }
  return out.empty() ? "n/a" : out;
}

std::string renderMarkdown(const TextTable& t) {
  std::string out = "| ";
  for (size_t i = 0; i < t.header.size(); ++i) out += (i ? " | " : "") + markdownCell(t.header[i]);
  out += " |\n|";
  for (size_t i = 0; i < t.header.size(); ++i) out += t.numeric[i] ? "---:|" : "---|";
  out += "\n";
  for (const auto& row : t.rows) {
    out += "| ";
    for (size_t i = 0; i < row.size(); ++i) out += (i ? " | " : "") + markdownCell(row[i]);
    out += " |\n";
  }
  out += "\n";
  for (const std::string& line : t.footnote) out += line + "  \n";
  return out;
}

std::string csvLine(const std::vector<std::string>& cells) {
  std::string out;
  for (size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + csvField(cells[i]);
  return out + "\r\n";
}

std::string renderCsv(const TextTable& t) {
  std::string out;
  for (const std::string& line : t.footnote) out += "# " + line + "\r\n";
  out += csvLine(t.header);
  for (const auto& row : t.rows) out += csvLine(row);
  return out;
}

std::string latexLine(const std::vector<std::string>& cells) {
  std::string out;
  for (size_t i = 0; i < cells.size(); ++i) {
    out += (i ? " & " : "") + (cells[i].empty() ? std::string("n/a") : latexEscape(cells[i]));
  }
  return out + " \\\\\n";
}

std::string renderLatex(const TextTable& t) {
  std::string spec;
  for (bool numeric : t.numeric) spec += numeric ? 'r' : 'l';
  std::string out =
      "% " + latexEscape(t.title) + " (tessbench table; needs \\usepackage{booktabs})\n";
  out += "\\begin{tabular}{" + spec + "}\n\\toprule\n" + latexLine(t.header) + "\\midrule\n";
  for (const auto& row : t.rows) out += latexLine(row);
  out += "\\bottomrule\n\\end{tabular}\n\\par\\smallskip\n{\\footnotesize\n";
  for (const std::string& line : t.footnote) out += latexEscape(line) + "\\par\n";
  out += "}\n";
  return out;
}

}  // namespace

std::string renderTable(const TextTable& table, TableFormat format) {
  TextTable cited = table;
  cited.title = citeSources(cited.title);
  for (std::string& cell : cited.header) cell = citeSources(cell);
  for (auto& row : cited.rows) {
    for (std::string& cell : row) cell = citeSources(cell);
  }
  for (std::string& line : cited.footnote) line = citeSources(line);
  switch (format) {
    case TableFormat::kMarkdown:
      return renderMarkdown(cited);
    case TableFormat::kCsv:
      return renderCsv(cited);
    case TableFormat::kLatex:
      return renderLatex(cited);
  }
  return {};
}

}  // namespace tb::report
