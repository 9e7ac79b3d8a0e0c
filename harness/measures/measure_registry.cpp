#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "harness/measures/measure.h"

namespace tb::measures {

results::MeasureDeclaration declarationOf(const MeasureInfo& info) {
  return {info.id,    info.title,         info.description, info.metrics,      info.headline,
          info.notes, info.summary_scope, info.plots,       info.control_rows, info.comparisons};
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
