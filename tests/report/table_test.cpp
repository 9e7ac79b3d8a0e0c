// The table renderers on hand-built results. Oracles: the LaTeX structure checked token by
// token (and pdflatex when installed), an RFC 4180 reader for the CSV, the published figures
// of NVIDIA's displacement subdivision surfaces talk as typed into published_figures.cpp.
#include "harness/report/table.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "harness/report/published_figures.h"
#include "tests/cli/cli_support.h"
#include "tests/report/results_builders.h"

namespace tb {
namespace {

using testing::measureResult;
using testing::row;

results::Results sampleResults() {
  results::Results r;
  r.context.run_id = "run_42";
  r.context.date = "2024-01-02T03:04:05Z";
  r.context.git_sha = "abc1234def";
  r.context.vulkan_device = "llvmpipe (LLVM 15.0.7, 256 bits)";
  r.context.libraries = {{"opensubdiv", "3.5.0"}, {"embree", "3.13"}};
  results::MeasureDeclaration error;
  error.measure = "error";
  error.title = "Error against the limit surface";
  error.metrics = {{"hausdorff", results::Unit::kDiagonal, results::Direction::kLowerIsBetter},
                   {"normal_max", results::Unit::kDegrees, results::Direction::kLowerIsBetter}};
  error.headline = {"hausdorff", "normal_max"};
  results::MeasureDeclaration memory;
  memory.measure = "memory";
  memory.title = "Memory footprint against plain triangle meshes";
  memory.metrics = {
      {"plain_bytes", results::Unit::kBytes, results::Direction::kNone},
      {"technique_with_displacement_bytes", results::Unit::kBytes,
       results::Direction::kLowerIsBetter},
      {"plain_over_technique", results::Unit::kRatio, results::Direction::kHigherIsBetter},
      {"patches", results::Unit::kCount, results::Direction::kNone}};
  memory.headline = {"plain_over_technique"};
  results::MeasureDeclaration seed;
  seed.measure = "published_figures";
  seed.title = "Shader costs beside published figures";
  seed.metrics = {{"published_alu", results::Unit::kCount, results::Direction::kNone},
                  {"published_loads", results::Unit::kCount, results::Direction::kNone},
                  {"ours_alu_vector", results::Unit::kCount, results::Direction::kLowerIsBetter},
                  {"ours_alu_scalar", results::Unit::kCount, results::Direction::kLowerIsBetter},
                  {"ours_loads", results::Unit::kCount, results::Direction::kLowerIsBetter}};
  seed.headline = {"ours_alu_vector"};
  r.measures = {error, memory, seed};

  // Names that need escaping in every format.
  for (const auto& [technique, variant] :
       {std::pair{"acc", "sym_fma"}, std::pair{"pn", "50% & {alpha}"}}) {
    for (const char* asset : {"a/one", "a/two"}) {
      results::Record record;
      record.technique = technique;
      record.variant = variant;
      record.asset = asset;
      results::MeasureResult e = measureResult("error");
      e.rows = {row({{"level", "4"}}, {{"hausdorff", 1e-3}, {"normal_max", 2}}),
                row({{"level", "8"}}, {{"hausdorff", 3e-3}, {"normal_max", 1}})};
      results::MeasureResult m = measureResult("memory");
      for (int level : {8, 16, 32, 64}) {
        const double plain = 56.0 * level * level * 6;
        m.rows.push_back(row({{"level", std::to_string(level)}},
                             {{"plain_bytes", plain},
                              {"technique_with_displacement_bytes", plain / 25},
                              {"plain_over_technique", 25},
                              {"patches", 6}}));
      }
      record.measures = {e, m};
      if (std::string(technique) == "acc" && std::string(asset) == "a/one") {
        results::MeasureResult s = measureResult("published_figures");
        s.rows = {row({{"source", "NVIDIA's displacement subdivision surfaces talk"},
                       {"what", "bezier position, asymmetric"}},
                      {{"published_alu", 60},
                       {"published_loads", 0},
                       {"ours_alu_vector", 70},
                       {"ours_alu_scalar", 180},
                       {"ours_loads", 20}}),
                  row({{"source", "the DirectX SDK SubD10 sample"},
                       {"what", "regular patch, acc/acc.tese"}},
                      {{"published_alu", 73},
                       {"published_loads", 16},
                       {"ours_alu_vector", 90},
                       {"ours_alu_scalar", 250},
                       {"ours_loads", 44}})};
        record.measures.push_back(s);
      }
      r.records.push_back(record);
    }
  }
  testing::withRegisteredDeclarations(&r);
  return r;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out.push_back(line);
  }
  return out;
}

// '&' not preceded by a backslash.
size_t unescapedAmpersands(const std::string& line) {
  size_t n = 0;
  for (size_t i = 0; i < line.size(); ++i) n += line[i] == '&' && (i == 0 || line[i - 1] != '\\');
  return n;
}

using testing::occurrences;

void expectLatexStructure(const std::string& latex, size_t columns) {
  EXPECT_EQ(occurrences(latex, "\\begin{tabular}"), 1u) << latex;
  EXPECT_EQ(occurrences(latex, "\\end{tabular}"), 1u);
  EXPECT_EQ(occurrences(latex, "\\toprule"), 1u);
  EXPECT_EQ(occurrences(latex, "\\midrule"), 1u);
  EXPECT_EQ(occurrences(latex, "\\bottomrule"), 1u);
  // Braces balance once escaped braces are taken out.
  int depth = 0;
  for (size_t i = 0; i < latex.size(); ++i) {
    if (latex[i] == '\\') {
      ++i;
      continue;
    }
    if (latex[i] == '{') ++depth;
    if (latex[i] == '}') --depth;
    ASSERT_GE(depth, 0) << latex;
  }
  EXPECT_EQ(depth, 0);
  const std::vector<std::string> all = lines(latex);
  bool in_table = false;
  size_t rows = 0;
  for (const std::string& line : all) {
    if (line.rfind("\\begin{tabular}{", 0) == 0) {
      const std::string spec = line.substr(16, line.find('}', 16) - 16);
      EXPECT_EQ(spec.size(), columns) << line;
      EXPECT_EQ(spec.find_first_not_of("lr"), std::string::npos) << spec;
      in_table = true;
      continue;
    }
    if (line == "\\end{tabular}") in_table = false;
    if (!in_table || line.rfind("\\", 0) == 0) continue;  // rules
    ++rows;
    EXPECT_EQ(unescapedAmpersands(line), columns - 1) << line;
    EXPECT_TRUE(line.size() >= 2 && line.substr(line.size() - 2) == "\\\\") << line;
  }
  EXPECT_GE(rows, 2u);
}

// RFC 4180 records (quoted fields may hold commas, quotes and line breaks), skipping the
// leading "# " comment lines.
std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> records;
  size_t i = 0;
  while (i < text.size() && text[i] == '#') i = text.find("\r\n", i) + 2;
  std::vector<std::string> record(1);
  bool quoted = false;
  for (; i < text.size(); ++i) {
    const char ch = text[i];
    if (quoted) {
      if (ch == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        record.back() += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        record.back() += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      record.emplace_back();
    } else if (ch == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      records.push_back(record);
      record.assign(1, "");
      ++i;
    } else {
      record.back() += ch;
    }
  }
  EXPECT_FALSE(quoted);
  return records;
}

TEST(Table, LatexIsABooktabsFragmentWithEveryCellEscaped) {
  const results::Results r = sampleResults();
  for (bool per_asset : {false, true}) {
    const report::TextTable table = report::summaryTable(r, {"error", {}, per_asset});
    const std::string latex = report::renderTable(table, report::TableFormat::kLatex);
    expectLatexStructure(latex, table.header.size());
    EXPECT_NE(latex.find("sym\\_fma"), std::string::npos) << latex;
    EXPECT_NE(latex.find("50\\% \\& \\{alpha\\}"), std::string::npos) << latex;
    EXPECT_NE(latex.find("hausdorff median (rel\\_diag)"), std::string::npos) << latex;
  }
  for (const char* measure : {"memory", "published_figures"}) {
    const report::TextTable table = report::publishedTable(r, measure);
    expectLatexStructure(report::renderTable(table, report::TableFormat::kLatex),
                         table.header.size());
  }
}

TEST(Table, LatexEscapesEverySpecialCharacter) {
  EXPECT_EQ(report::latexEscape("&%$#_{}~^\\"),
            "\\&\\%\\$\\#\\_\\{\\}\\textasciitilde{}\\textasciicircum{}\\textbackslash{}");
}

TEST(Table, LatexCompilesWhenPdflatexIsInstalled) {
  if (std::system("command -v pdflatex >/dev/null 2>&1") != 0) GTEST_SKIP() << "no pdflatex";
  const auto dir = std::filesystem::temp_directory_path() / "tessbench_table_latex";
  std::filesystem::create_directories(dir);
  const results::Results r = sampleResults();
  std::ofstream(dir / "t.tex") << "\\documentclass{article}\\usepackage{booktabs}"
                                  "\\begin{document}\n"
                               << report::renderTable(report::summaryTable(r, {"error", {}, true}),
                                                      report::TableFormat::kLatex)
                               << report::renderTable(report::publishedTable(r, "memory"),
                                                      report::TableFormat::kLatex)
                               << "\\end{document}\n";
  const std::string command = "cd " + dir.string() +
                              " && pdflatex -interaction=nonstopmode -halt-on-error t.tex "
                              ">/dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << "see " << (dir / "t.log");
}

TEST(Table, CsvParsesBackWithTheSameCellCountOnEveryLine) {
  const results::Results r = sampleResults();
  for (const report::TextTable& table :
       {report::summaryTable(r, {"error", {}, true}), report::publishedTable(r, "memory"),
        report::publishedTable(r, "published_figures")}) {
    const std::string csv = report::renderTable(table, report::TableFormat::kCsv);
    EXPECT_EQ(csv.rfind("# ", 0), 0u) << "the footnote leads as comment lines";
    const auto records = parseCsv(csv);
    ASSERT_EQ(records.size(), table.rows.size() + 1) << csv;
    for (const auto& record : records) EXPECT_EQ(record.size(), table.header.size()) << csv;
    EXPECT_EQ(records[0], table.header);
  }
  EXPECT_EQ(report::csvField("50% & {alpha}"), "50% & {alpha}");
  EXPECT_EQ(report::csvField("a,\"b\""), "\"a,\"\"b\"\"\"");
}

TEST(Table, MarkdownHeaderCarriesUnitsAndFootnoteTheRunContext) {
  const results::Results r = sampleResults();
  const report::TextTable table = report::summaryTable(r, {"error", {}, false});
  ASSERT_EQ(table.rows.size(), 2u);  // one line per technique x variant, over both assets
  const std::string md = report::renderTable(table, report::TableFormat::kMarkdown);
  EXPECT_NE(md.find("| technique | variant | hausdorff median (rel_diag) | hausdorff worst "
                    "(rel_diag) | normal_max median (deg) | normal_max worst (deg) |"),
            std::string::npos)
      << md;
  // Median over four rows (1e-3, 3e-3 on each asset) and the worst (largest).
  EXPECT_NE(md.find("| acc | sym_fma | 0.002 | 0.003 | 1.5 | 2 |"), std::string::npos) << md;
  for (const std::string& text : {md, report::renderTable(table, report::TableFormat::kCsv),
                                  report::renderTable(table, report::TableFormat::kLatex)}) {
    EXPECT_NE(text.find("abc1234def"), std::string::npos) << text;
    EXPECT_NE(text.find("llvmpipe (LLVM 15.0.7, 256 bits)"), std::string::npos) << text;
    EXPECT_NE(text.find("run"), std::string::npos);
    EXPECT_NE(text.find("opensubdiv 3.5.0"), std::string::npos);
    EXPECT_NE(text.find("Error against the limit surface"), std::string::npos);
  }
  const std::string chosen = report::renderTable(
      report::summaryTable(r, {"error", {"normal_max"}, false}), report::TableFormat::kMarkdown);
  EXPECT_EQ(chosen.find("hausdorff"), std::string::npos);
}

TEST(Table, PublishedTablesSetTheTalksFiguresBesideOursCitedByTitle) {
  const results::Results r = sampleResults();
  const report::TextTable memory = report::publishedTable(r, "memory");
  // Per level: the talk's row, then ours for each technique x variant.
  ASSERT_EQ(memory.rows.size(), report::publishedMemoryTable().size() * 3);
  EXPECT_EQ(memory.rows[9][0], "NVIDIA's displacement subdivision surfaces talk");
  EXPECT_EQ(memory.rows[9][2], "64");
  EXPECT_EQ(memory.rows[9][3], "943");
  EXPECT_EQ(memory.rows[9][4], "118");
  EXPECT_EQ(memory.rows[10][0], "ours");
  EXPECT_EQ(memory.rows[10][5], "25");
  // 56 B x 64^2 per patch x 14,400 patches.
  EXPECT_EQ(memory.rows[10][3], "3303");

  const report::TextTable seed = report::publishedTable(r, "published_figures");
  ASSERT_EQ(seed.rows.size(), 2u);
  EXPECT_EQ(seed.rows[0][0], "NVIDIA's displacement subdivision surfaces talk");
  EXPECT_EQ(seed.rows[0][3], "60");
  EXPECT_EQ(seed.rows[0][4], "") << "published_loads 0 means not published";
  EXPECT_EQ(seed.rows[1][0], "the DirectX SDK SubD10 sample");
  EXPECT_EQ(seed.rows[1][2], "regular patch, acc/acc.tese");

  for (const report::TextTable& table :
       {memory, seed, report::summaryTable(r, {"published_figures", {}, true})}) {
    for (report::TableFormat format :
         {report::TableFormat::kMarkdown, report::TableFormat::kCsv, report::TableFormat::kLatex}) {
      const std::string text = report::renderTable(table, format);
      EXPECT_EQ(text.find("seed 0"), std::string::npos) << text;
    }
  }
  EXPECT_EQ(report::citeSources("seed 000's table, seed 003"),
            "NVIDIA's displacement subdivision surfaces talk's table, CAPCOM's \"Lost Planet 2: "
            "DirectX 11 Features\" talk");
}

TEST(Table, FormatsParse) {
  EXPECT_EQ(report::parseTableFormat("latex"), report::TableFormat::kLatex);
  EXPECT_EQ(report::parseTableFormat("csv"), report::TableFormat::kCsv);
  EXPECT_EQ(report::parseTableFormat("markdown"), report::TableFormat::kMarkdown);
  EXPECT_FALSE(report::parseTableFormat("html").has_value());
}

}  // namespace
}  // namespace tb
