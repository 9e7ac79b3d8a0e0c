// `tessbench table`: a measure's summary (summary.h) or a published table beside ours
// (published_figures.h) as Markdown, CSV or LaTeX. Pure functions over the results model.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::report {

enum class TableFormat { kMarkdown, kCsv, kLatex };
// "markdown" | "csv" | "latex"; nullopt for anything else.
std::optional<TableFormat> parseTableFormat(std::string_view text);

// A table before rendering: header cells, rows of as many cells, and the footnote lines.
struct TextTable {
  std::string title;                           // what the table shows (the declaration's title)
  std::vector<std::string> header;             // cells, units in parentheses
  std::vector<bool> numeric;                   // per column: right-aligned figures
  std::vector<std::vector<std::string>> rows;  // "" = no figure
  std::vector<std::string> footnote;           // lines: sources, the run's context
};

struct SummaryTableOptions {
  std::string measure;
  std::vector<std::string> metrics;  // empty: the declaration's headline metrics
  bool per_asset = false;            // a line per technique x variant x asset
};

// technique, variant (asset), then per metric its median and worst ("hausdorff median
// (rel_diag)"), over the rows of the measure's summary scope; footnote: the declaration's
// title and the run's context.
TextTable summaryTable(const results::Results& results, const SummaryTableOptions& options);

// The measure's declared side-by-side comparisons (comparison.h), a table per group: the
// technique, then a column per column-key value and the extra columns; the title is the
// comparison's lead line with the group's name; footnote: the run's context.
std::vector<TextTable> comparisonTables(const results::Results& results,
                                        const results::MeasureDeclaration& declaration);

// The measures with a published table: "memory" (NVIDIA's displacement subdivision surfaces
// talk's memory table) and "published_figures" (its Bezier instruction counts and the DirectX SDK
// SubD10 sample's ACC shader costs).
bool hasPublishedTable(const results::Results& results, const std::string& measure);
// The published figures beside ours from the same run; rows empty when the run has none.
TextTable publishedTable(const results::Results& results, const std::string& measure);

// The run's context, one line each: run id and date, git sha, Vulkan device, suite; the
// library versions.
std::vector<std::string> runContextFootnote(const results::Results& results);

// Markdown: a pipe table, then the footnote lines. CSV (RFC 4180): the footnote as leading
// lines starting with "# " (comment lines: pandas comment='#'), then the header and rows,
// fields quoted when they hold a comma, quote, line break or a leading '#'. LaTeX: a booktabs
// tabular fragment (\toprule, \midrule, \bottomrule) and the footnote in \footnotesize after
// it; every cell escaped. Every text is cited by source title (citeSources).
std::string renderTable(const TextTable& table, TableFormat format);

// Helpers, exposed for tests.
std::string latexEscape(std::string_view text);
std::string csvField(std::string_view text);

}  // namespace tb::report
