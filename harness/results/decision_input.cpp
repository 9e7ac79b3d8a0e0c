#include "harness/results/decision_input.h"

#include <array>
#include <utility>

namespace tb::results {
namespace {

constexpr std::array<std::pair<DecisionRole, std::string_view>, 22> kRoles{{
    {DecisionRole::kError, "error"},
    {DecisionRole::kTrianglesAtTarget, "triangles_at_target"},
    {DecisionRole::kMemoryRatio, "memory_ratio"},
    {DecisionRole::kShaderCost, "shader_cost"},
    {DecisionRole::kCrackPoints, "crack_points"},
    {DecisionRole::kCrackGap, "crack_gap"},
    {DecisionRole::kCrackPlace, "crack_place"},
    {DecisionRole::kCrackPicture, "crack_picture"},
    {DecisionRole::kMemorySaving, "memory_saving"},
    {DecisionRole::kCullEfficiency, "cull_efficiency"},
    {DecisionRole::kFalseCulls, "false_culls"},
    {DecisionRole::kTriangleRatio, "triangle_ratio"},
    {DecisionRole::kSolverResidual, "solver_residual"},
    {DecisionRole::kSimulationFigure, "simulation_figure"},
    {DecisionRole::kResidualPerDispatch, "residual_per_dispatch"},
    {DecisionRole::kDispatchesPerIteration, "dispatches_per_iteration"},
    {DecisionRole::kPublishedMemory, "published_memory"},
    {DecisionRole::kPublishedCost, "published_cost"},
    {DecisionRole::kAdviceError, "advice_error"},
    {DecisionRole::kAdviceMemory, "advice_memory"},
    {DecisionRole::kAdviceCost, "advice_cost"},
    {DecisionRole::kAdviceCracks, "advice_cracks"},
}};

constexpr std::array<std::pair<DecisionReduce, std::string_view>, 4> kReduces{{
    {DecisionReduce::kMax, "max"},
    {DecisionReduce::kMin, "min"},
    {DecisionReduce::kSum, "sum"},
    {DecisionReduce::kLast, "last"},
}};

template <class Enum, size_t N>
std::string_view spell(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum e) {
  for (const auto& [value, text] : table) {
    if (value == e) return text;
  }
  return "?";
}

template <class Enum, size_t N>
std::optional<Enum> parse(const std::array<std::pair<Enum, std::string_view>, N>& table,
                          std::string_view text) {
  for (const auto& [value, spelling] : table) {
    if (spelling == text) return value;
  }
  return std::nullopt;
}

}  // namespace

std::string_view toString(DecisionRole role) { return spell(kRoles, role); }
std::optional<DecisionRole> parseDecisionRole(std::string_view text) { return parse(kRoles, text); }
std::string_view toString(DecisionReduce reduce) { return spell(kReduces, reduce); }
std::optional<DecisionReduce> parseDecisionReduce(std::string_view text) {
  return parse(kReduces, text);
}

}  // namespace tb::results
