// A camera path as measures see it: a name and its views in path order. Plain data, so
// harness/measures can take a whole path (MeasureNeed::kCameraPath) without knowing how
// paths are made (harness/suite/camera_path.h reads them from JSON files).
#pragma once

#include <string>
#include <vector>

#include "core/view/view.h"

namespace tb::view {

struct CameraPath {
  std::string name;         // the rows' "camera_path" key, e.g. "orbit" or "test_orbit"
  std::vector<View> views;  // in path order (frame i is views[i]); never empty from a file
};

}  // namespace tb::view
