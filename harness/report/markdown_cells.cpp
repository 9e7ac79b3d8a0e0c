// Table lines, metric headers and figures of report.md (markdown_sections.h).
#include <fmt/format.h>

#include "harness/report/markdown.h"
#include "harness/report/markdown_sections.h"
#include "harness/report/summary.h"

namespace tb::report::markdown_detail {
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

}  // namespace

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

std::string directionWord(results::Direction direction) {
  switch (direction) {
    case results::Direction::kLowerIsBetter:
      return "lower better";
    case results::Direction::kHigherIsBetter:
      return "higher better";
    case results::Direction::kNone:
      return "context";
  }
  return "";
}

// "hausdorff (rel_diag, lower better)"
std::string metricHeader(const results::Results& results, const std::string& measure,
                         const std::string& metric) {
  const std::string unit = unitOf(results, measure, metric);
  const results::Direction direction = directionOf(results, measure, metric);
  std::string header = metric + " (";
  if (!unit.empty()) header += unit + ", ";
  return header + directionWord(direction) + ")";
}

std::string formatFigure(double value, const std::string& unit) {
  return formatMetricValue(results::Metric{"", value, unit});
}

// The first headline metric of a measure: what its matrices and job screens show.
std::string firstHeadline(const results::Results& results, const std::string& measure) {
  const results::MeasureDeclaration* declaration = results.findMeasure(measure);
  if (declaration != nullptr && !declaration->headline.empty()) return declaration->headline[0];
  return "";
}
}  // namespace tb::report::markdown_detail
