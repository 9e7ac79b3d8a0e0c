// Decision inputs: the figures a measure lets the decision, `advise`, the answers block and the
// report's tables read, declared beside its metrics (MeasureDeclaration::decision_inputs).
// harness/report finds a figure by its role and reads it through the declaration, never by
// a measure or metric name; a measure added later reaches the decision by declaring one.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::results {

// As metric_spec.h: a key -> value (or glob) filter on rows.
using RowScope = std::map<std::string, std::string>;

// The row key of a pipeline path, and its two values: the hardware tessellator (rows with it
// or without the key) and the compute path (core/gpu/compute_path.h).
inline constexpr const char* kPathKey = "path";
inline constexpr const char* kTessellatorPath = "tessellator";
inline constexpr const char* kComputePath = "compute";

// What a figure is to a reader. The decision's terms first, then the answers' and tables'.
enum class DecisionRole {
  kError,                // distance to the exact surface (rel_diag; lower better): the rule's error
  kTrianglesAtTarget,    // triangles per frame at the pixel target (count; lower better)
  kMemoryRatio,          // the technique's bytes over the plain mesh's (ratio; lower better)
  kShaderCost,           // the rule's cost term (lower better); the highest precedence is read
  kCrackPoints,          // points that break watertightness (count; 0 = watertight)
  kCrackGap,             // a cracked row's largest gap (world): which row the report shows
  kCrackPlace,           // metrics: patch a, local a, patch b, local b, is-corner flag, t
  kCrackPicture,         // rows whose cracks are drawn (CPU float, undisplaced)
  kMemorySaving,         // the plain mesh's bytes over the technique's (ratio; answers)
  kCullEfficiency,       // share of what an ideal culler removes (answers; higher better)
  kFalseCulls,           // patches culled that cover a pixel (answers; a sum over rows)
  kTriangleRatio,        // triangles against uniform levels at the target (answers)
  kSolverResidual,       // residual at one frame's dispatch budget (answers)
  kSimulationFigure,     // a column of report.md's per-scenario simulation tables
  kResidualPerDispatch,  // report.html's per-dispatch chart: the residual (y)
  kDispatchesPerIteration,  // and the dispatches one iteration takes (x = iteration x this)
  kPublishedMemory,         // `table memory`: metrics patches, plain bytes, technique bytes, ratio
  kPublishedCost,           // `table published_figures`: published ALU, loads; ours vector, scalar,
                            // loads
  // `advise`'s constraints: the worst of the metric over the measure's summary scope.
  kAdviceError,   // bounded by --max-error
  kAdviceMemory,  // the plain mesh's bytes over the technique's: --max-memory bounds 1 / it
  kAdviceCost,    // bounded by --max-instructions
  kAdviceCracks,  // metrics: points not equal, unpaired points; both 0 = watertight
};

// How the rows an input reads become one figure.
enum class DecisionReduce {
  kMax,   // the largest row value
  kMin,   // the smallest (with DecisionInput::chosen_key: the row's key is kept)
  kSum,   // the sum over the rows
  kLast,  // the last row read (one row per record, as the memory level's)
};

struct DecisionInput {
  DecisionRole role = DecisionRole::kError;
  // How reports name the figure: a column header, a clause ("TCS + TES instructions").
  std::string label;
  // The decision table's column header; empty: "label (metric, unit)".
  std::string column = {};
  // The row's figure: the sum of these metrics (an absent one counts 0; a row without the
  // first is not read). kCrackPlace and kPublished* read them one by one, in order.
  std::vector<std::string> metrics;
  std::string per = {};  // a metric dividing the sum (a ratio); empty: none
  RowScope where = {};   // the rows read (rowInScope)
  // And in at least one of these (the TCS or the TES stage); empty: no further condition.
  std::vector<RowScope> any_of = {};
  DecisionReduce reduce = DecisionReduce::kMax;
  std::string valid_flag = {};  // a flag metric: rows with it 0 are not read
  // The pipeline path whose candidates read the input: kTessellatorPath or kComputePath (a
  // compute candidate reads the tessellator's input for a role it has none for).
  std::string path = kTessellatorPath;
  // Whether rows are on the path by their kPathKey key (memory, the device's cracks rows);
  // false: every row (instructions select theirs by stage).
  bool rows_on_path = false;
  // kCrackPoints: the rows of the device side (the rest are the CPU's, every path's).
  RowScope device_rows = {};
  std::string first_of = {};    // a key: only rows of its first value (the default path)
  std::string chosen_key = {};  // a key whose value on the chosen row is reported (policy)
  int precedence = 0;           // of one role's inputs for a path, the highest is read
  bool operator==(const DecisionInput&) const = default;
};

std::string_view toString(DecisionRole role);  // "error", "triangles_at_target", ...
std::optional<DecisionRole> parseDecisionRole(std::string_view text);
std::string_view toString(DecisionReduce reduce);  // "max", "min", "sum", "last"
std::optional<DecisionReduce> parseDecisionReduce(std::string_view text);

}  // namespace tb::results
