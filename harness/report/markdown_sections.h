// The pieces report.md is built of (renderMarkdown, markdown.cpp): table lines, metric
// headers and figures (markdown_cells.cpp), the three job screens and the technique × asset
// matrices (markdown_screens.cpp), the measures' sections (markdown_measures.cpp). Each
// section appends to `out`. Internal to harness/report.
#pragma once

#include <string>
#include <vector>

#include "harness/report/decision.h"
#include "harness/results/results_model.h"

namespace tb::report::markdown_detail {

// "| a | b |": a table line, '|' escaped and newlines as spaces.
void appendRow(std::string* out, const std::vector<std::string>& cells);
// The header line and its "|---|" rule.
void appendHeader(std::string* out, const std::vector<std::string>& cells);

// "lower better", "higher better", "context".
std::string directionWord(results::Direction direction);
// "hausdorff (rel_diag, lower better)"
std::string metricHeader(const results::Results& results, const std::string& measure,
                         const std::string& metric);
std::string formatFigure(double value, const std::string& unit);
// The first headline metric of a measure: what its matrices and job screens show.
std::string firstHeadline(const results::Results& results, const std::string& measure);

// The answers block (answers.h): one line per question, its figure and source.
void appendAnswers(const results::Results& results, const std::vector<AssetDecision>& decisions,
                   std::string* out);
// Per surface asset its decision table (decision.h), the why and the runner-up's trade.
void appendDecisions(const results::Results& results, const std::vector<AssetDecision>& decisions,
                     std::string* out);
// Per asset, where each default variant cracks (its worst cracks row and the place), and a
// link to its crack picture.
void appendCrackLocations(const results::Results& results, std::string* out);
// The crack picture a run renders of `record`, relative to the run folder (the path of
// harness/pictures/run_pictures.h's crackPicturePath: pictures/<technique>--<asset, '/' as
// "--", other characters than [A-Za-z0-9._-] as '_'>--cracks.png), when the record is
// undisplaced, its error measure ok and a cpu_float cracks row (undisplaced) has unequal
// points; empty otherwise.
std::string crackPictureOf(const results::Results& results, const results::Record& record);
// The simulation measures per scenario × technique/variant (markdown_decisions.cpp).
void appendSimulations(const results::Results& results, std::string* out);

// Job 1: is this run clean, and what to compare it with.
void appendRegressionScreen(const results::Results& results,
                            const std::vector<std::string>& measures, std::string* out);
// Job 2: per asset, which technique × variant wins each measure's first headline figure.
void appendChoiceScreen(const results::Results& results, const std::vector<std::string>& measures,
                        std::string* out);
// Job 3: one line per technique × variant, each measure's first headline figure over every
// asset: median (worst).
void appendPublishingScreen(const results::Results& results,
                            const std::vector<std::string>& measures, std::string* out);
// A measure's technique × asset matrix of its first headline metric.
void appendMatrix(const results::Results& results, const std::string& measure, std::string* out);
// A measure's section: its declaration, its summary, its rows when few.
void appendMeasureSection(const results::Results& results, const std::string& measure,
                          std::string* out);

}  // namespace tb::report::markdown_detail
