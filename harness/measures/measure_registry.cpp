#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "harness/measures/measure.h"

namespace tb::measures {

results::MeasureDeclaration declarationOf(const MeasureInfo& info) {
  return {.measure = info.id,
          .title = info.title,
          .description = info.description,
          .metrics = info.metrics,
          .headline = info.headline,
          .notes = info.notes,
          .summary_scope = info.summary_scope,
          .plots = info.plots,
          .control_rows = info.control_rows,
          .comparisons = info.comparisons,
          .decision_inputs = info.decision_inputs,
          .shader_db = info.shader_db};
}

const view::CameraPath& requireCameraPath(const MeasureInput& input) {
  if (input.camera_path == nullptr || input.camera_path->views.empty()) {
    throw std::invalid_argument(
        "measure input: no camera path (MeasureInput::camera_path is "
        "null or has no views)");
  }
  return *input.camera_path;
}

MeasureRegistry& MeasureRegistry::instance() {
  static MeasureRegistry registry;
  return registry;
}

bool runsComputePath(const MeasureInput& input) {
  if (input.displacement != nullptr) return false;
  if (input.suite == SuiteMode::kFull) return true;
  return std::any_of(std::begin(kDefaultComputeAssets), std::end(kDefaultComputeAssets),
                     [&](const char* asset) { return input.asset_name == asset; });
}

}  // namespace tb::measures
