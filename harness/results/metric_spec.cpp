#include "harness/results/metric_spec.h"

#include <algorithm>
#include <array>

namespace tb::results {
namespace {

struct UnitText {
  Unit unit;
  std::string_view spelling;
  std::string_view description;
};
constexpr std::array<UnitText, 14> kUnits{{
    {Unit::kCount, "count", "count"},
    {Unit::kBytes, "bytes", "bytes"},
    {Unit::kRatio, "ratio", "ratio"},
    {Unit::kDiagonal, "rel_diag", "fraction of the bounding-box diagonal"},
    {Unit::kDegrees, "deg", "degrees"},
    {Unit::kUlp, "ulp", "float ulps"},
    {Unit::kScaleUlp, "scale_ulp", "float ulps at the model's largest coordinate"},
    {Unit::kWorld, "world", "world (asset) units"},
    {Unit::kPixels, "px", "pixels"},
    {Unit::kSeconds, "s", "seconds"},
    {Unit::kId, "id", "index (-1: none)"},
    {Unit::kFlag, "flag", "0 or 1"},
    {Unit::kEdgeParameter, "edge_parameter", "edge parameter (0 to 1)"},
    {Unit::kCycles, "cycles", "clock cycles (the compiler's estimate)"},
}};

struct DirectionText {
  Direction direction;
  std::string_view spelling;
  std::string_view description;
};
constexpr std::array<DirectionText, 3> kDirections{{
    {Direction::kLowerIsBetter, "lower", "lower is better"},
    {Direction::kHigherIsBetter, "higher", "higher is better"},
    {Direction::kNone, "none", "context (neither better)"},
}};

const UnitText& unitText(Unit unit) {
  for (const UnitText& text : kUnits) {
    if (text.unit == unit) return text;
  }
  return kUnits[0];  // unreachable for a valid enumerator
}

const DirectionText& directionText(Direction direction) {
  for (const DirectionText& text : kDirections) {
    if (text.direction == direction) return text;
  }
  return kDirections[2];
}

}  // namespace

std::string_view toString(Unit unit) { return unitText(unit).spelling; }
std::string_view describe(Unit unit) { return unitText(unit).description; }
std::string_view toString(Direction direction) { return directionText(direction).spelling; }
std::string_view describe(Direction direction) { return directionText(direction).description; }

std::optional<Unit> parseUnit(std::string_view text) {
  for (const UnitText& unit : kUnits) {
    if (unit.spelling == text) return unit.unit;
  }
  return std::nullopt;
}

std::optional<Direction> parseDirection(std::string_view text) {
  for (const DirectionText& direction : kDirections) {
    if (direction.spelling == text) return direction.direction;
  }
  return std::nullopt;
}

const std::vector<Unit>& allUnits() {
  static const std::vector<Unit> kAll = [] {
    std::vector<Unit> units;
    for (const UnitText& text : kUnits) units.push_back(text.unit);
    return units;
  }();
  return kAll;
}

std::string_view toString(PlotKind kind) {
  switch (kind) {
    case PlotKind::kLine:
      return "line";
    case PlotKind::kScatter:
      return "scatter";
    case PlotKind::kBar:
      return "bar";
  }
  return "scatter";
}

std::optional<PlotKind> parsePlotKind(std::string_view text) {
  for (PlotKind kind : {PlotKind::kLine, PlotKind::kScatter, PlotKind::kBar}) {
    if (toString(kind) == text) return kind;
  }
  return std::nullopt;
}

std::string_view toString(PlotReduce reduce) {
  return reduce == PlotReduce::kMax ? "max" : "median";
}

std::optional<PlotReduce> parsePlotReduce(std::string_view text) {
  if (text == "median") return PlotReduce::kMedian;
  if (text == "max") return PlotReduce::kMax;
  return std::nullopt;
}

namespace {

// '*' matches any run of characters (also none); every other character itself.
bool globMatches(std::string_view pattern, std::string_view text) {
  const size_t star = pattern.find('*');
  if (star == std::string_view::npos) return pattern == text;
  const std::string_view head = pattern.substr(0, star);
  if (text.substr(0, head.size()) != head) return false;
  const std::string_view rest = pattern.substr(star + 1);
  for (size_t from = head.size(); from <= text.size(); ++from) {
    if (globMatches(rest, text.substr(from))) return true;
  }
  return false;
}

}  // namespace

bool rowInScope(const RowScope& scope, const std::map<std::string, std::string>& keys) {
  for (const auto& [key, pattern] : scope) {
    const auto it = keys.find(key);
    if (pattern.empty()) {
      if (it != keys.end()) return false;  // "": the row must not have the key
      continue;
    }
    if (it == keys.end() || !globMatches(pattern, it->second)) return false;
  }
  return true;
}

bool isControlRow(const MeasureDeclaration& declaration,
                  const std::map<std::string, std::string>& keys) {
  // An empty entry would make every row a control: it marks none.
  return std::any_of(
      declaration.control_rows.begin(), declaration.control_rows.end(),
      [&](const RowScope& scope) { return !scope.empty() && rowInScope(scope, keys); });
}

const MetricSpec* MeasureDeclaration::find(std::string_view name) const {
  for (const MetricSpec& spec : metrics) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

}  // namespace tb::results
