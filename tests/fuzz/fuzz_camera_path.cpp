// libFuzzer target: the camera path reader (harness/suite/camera_path.h, loadCameraPath) on
// arbitrary file contents, then one sampling around an asset's box as the suite does
// (sampleCameraPath). InputError is the one expected exception; anything else, a sanitizer
// report or a broken property of the spec or its views is a finding.
#include <cmath>
#include <cstdint>
#include <string>

#include "core/mesh/bounds.h"
#include "core/mesh/input_error.h"
#include "harness/suite/camera_path.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using tb::fuzz::require;

// What loadCameraPath promises of a spec it returns (camera_path.h: every field validated).
void checkSpec(const tb::suite::CameraPathSpec& spec) {
  require(!spec.name.empty(), "a path has a name");
  require(spec.width_px >= 1 && spec.height_px >= 1, "the viewport is at least 1 x 1 pixel");
  require(spec.fov_y_deg > 0 && spec.fov_y_deg < 180, "the field of view is in (0, 180)");
  require(spec.frames >= 1, "a path has at least one frame");
  require(spec.near_plane > 0 && spec.far_plane > spec.near_plane && std::isfinite(spec.far_plane),
          "0 < near < far, finite");
  require(spec.target_pixels_per_edge > 0 && std::isfinite(spec.target_pixels_per_edge),
          "pixels per edge is finite and > 0");
  require(!spec.keyframes.empty(), "a path has at least one keyframe");
}

// The views of a path the suite runs measures under: one per frame, each with a finite
// matrix, the spec's viewport, and a positive near plane.
void checkPath(const tb::suite::CameraPathSpec& spec, const tb::view::CameraPath& path) {
  require(path.name == spec.name, "the sampled path keeps the spec's name");
  require(path.views.size() == spec.frames, "one view per frame");
  for (const tb::view::View& view : path.views) {
    for (const auto& column : view.view_projection.m) {
      for (double value : column) require(!std::isnan(value), "view-projection has no NaN");
    }
    require(view.viewport_width_px == spec.width_px && view.viewport_height_px == spec.height_px,
            "each view has the spec's viewport");
    require(view.near_plane > 0, "each view's near plane is > 0");
    require(std::isfinite(view.projection_y_scale) && view.projection_y_scale > 0,
            "projection y scale is finite and > 0");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static tb::fuzz::ScratchFile file(".json");
  const std::string& path = file.write(data, size);
  try {
    const tb::suite::CameraPathSpec spec = tb::suite::loadCameraPath(path, "fuzz_path.json");
    checkSpec(spec);
    // An asset's box, off-centre and not a cube, as the suite passes (boundsOf(mesh)).
    const tb::mesh::Aabb bounds{{-1.5, 0.25, -4}, {2.5, 3, 1}};
    checkPath(spec, tb::suite::sampleCameraPath(spec, bounds));
  } catch (const tb::mesh::InputError& error) {
    const std::string message = error.what();
    require(message.find('\n') == std::string::npos, "an InputError's message is one line");
  }
  return 0;
}
