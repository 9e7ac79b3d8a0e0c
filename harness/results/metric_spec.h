// Metric declarations: what each figure a measure emits is, in which unit, and which way
// is better. A measure declares its metrics once (harness/measures/metric_table.h); the
// declarations travel in results.json at the measure level, and the renderers and a
// compare read them instead of knowing a measure by name.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb {

// The closed set of units. A new metric picks one of these; a unit that does not fit is
// added here (with its spelling in metric_spec.cpp), never written as free text.
enum class Unit {
  kCount,          // "count": how many (points, edges, instructions, samples)
  kBytes,          // "bytes"
  kRatio,          // "ratio": one quantity over another of the same unit
  kDiagonal,       // "rel_diag": a length as a fraction of the bounding-box diagonal
  kDegrees,        // "deg": an angle
  kUlp,            // "ulp": float units in the last place, per component
  kScaleUlp,       // "scale_ulp": a gap over the float spacing at the model's largest |coordinate|
  kWorld,          // "world": a length in the asset's own units
  kPixels,         // "px"
  kSeconds,        // "s"
  kId,             // "id": an index (patch, local edge or corner); -1 for none
  kFlag,           // "flag": 0 or 1
  kEdgeParameter,  // "edge_parameter": position along an edge, 0 at its first corner, 1 at the next
};

// Which way a change is an improvement. kNone is declared explicitly for context figures
// (ids, flags, sizes of the input, counts of compared points): a compare never flags them.
enum class Direction { kLowerIsBetter, kHigherIsBetter, kNone };

struct MetricSpec {
  std::string name;  // snake_case, unique within its measure
  Unit unit = Unit::kCount;
  Direction direction = Direction::kNone;
  bool operator==(const MetricSpec&) const = default;
};

// Spellings in results.json. parseUnit / parseDirection return nullopt for anything else.
std::string_view toString(Unit unit);
std::string_view toString(Direction direction);
std::optional<Unit> parseUnit(std::string_view text);
std::optional<Direction> parseDirection(std::string_view text);
// For readers: "fraction of the bounding-box diagonal", "lower is better".
std::string_view describe(Unit unit);
std::string_view describe(Direction direction);
// Every unit, in declaration order (for tests and legends).
const std::vector<Unit>& allUnits();

// A measure's declaration, as results.json and the renderers see it.
struct MeasureDeclaration {
  std::string measure;  // measure id, e.g. "memory"
  std::string title;
  std::string description;
  std::vector<MetricSpec> metrics;    // in the order rows emit them
  std::vector<std::string> headline;  // names from `metrics`, what a summary shows first
  // Notes that hold for every record of the measure (definitions, method); rendered once
  // under the measure's heading. Notes about one record live in MeasureResult::notes.
  std::vector<std::string> notes;
  const MetricSpec* find(std::string_view name) const;
};

}  // namespace tb
