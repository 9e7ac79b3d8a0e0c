// Camera paths: the views view-dependent measures run under. A measure that needs a view
// (MeasureNeed::kView) runs once per view of each path, its rows keyed by the path's name
// and the view's index; one that needs a whole path (MeasureNeed::kCameraPath) runs once
// per path. Paths are data: small JSON files (assets/cameras/*.json, or any file given to
// `run --camera`), read here and sampled around each asset's bounding box. The JSON format
// and the sampling rule are in docs/FORMATS.md, "Camera path files".
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/mesh/bounds.h"
#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"
#include "core/view/camera_path_views.h"
#include "core/view/view.h"

namespace tb::suite {

// Makes a path for the scene inside `bounds`.
using CameraPathFn = std::function<view::CameraPath(const mesh::Aabb& bounds)>;

// "test_orbit": 3 views at 0, 120 and 240 degrees around the box's vertical (y) axis,
// 20 degrees above its centre, at 2.5 box radii, 60 degree vertical field of view,
// 640 x 480 pixels, 8 pixels per edge. Fixed, for tests and plumbing.
view::CameraPath testOrbitPath(const mesh::Aabb& bounds);

// One keyframe of a path file. Positions in the path's space (CameraPathSpec::bounds_space);
// `up` is a direction (any length > 0), never parallel to eye - target.
struct CameraKeyframe {
  mesh::Vec3d eye, target, up;
};

// A camera path file as read (loadCameraPath): every field validated.
struct CameraPathSpec {
  std::string name;  // the "name" field, else the file's stem
  // How messages and results name the file: "assets/cameras/orbit.json" for a bundled path.
  std::string shown_path;
  uint32_t width_px = 1920, height_px = 1080;  // the viewport, pixels ("resolution")
  double fov_y_deg = 45;                       // vertical field of view, degrees, in (0, 180)
  uint32_t frames = 1;                         // views the path is sampled to (> 0)
  // true ("space": "bounds"): positions in bounding-box diagonals relative to the box's
  // centre, near and far planes in diagonals; false ("world"): world units.
  bool bounds_space = true;
  double near_plane = 0.01, far_plane = 100;  // 0 < near < far, in the path's space
  double target_pixels_per_edge = 8;          // pixels per tessellated edge (> 0)
  std::vector<CameraKeyframe> keyframes;      // at least 1, spaced uniformly along the path
};

// Reads and validates one camera path file. `shown_path` names the file in messages.
// Throws InputError ("<shown_path>: <field>: <rule>") on a missing file, malformed JSON, a
// missing, mistyped, unknown or non-finite field, or a path that cannot be sampled (eye ==
// target, a zero-length up, up parallel to the view direction at a keyframe or at a frame
// sampled at `frames`, opposite view directions on consecutive keyframes).
CameraPathSpec loadCameraPath(const std::string& file, const std::string& shown_path);

// The bundled paths' names (the stems of assetsDirectory()/cameras/*.json), sorted:
// "dolly", "flyby", "orbit".
std::vector<std::string> bundledCameraPaths();

// A bundled name ("orbit") or a path to a .json file, loaded. Throws InputError naming the
// argument when it is neither, or naming the file and field when the file is bad.
CameraPathSpec resolveCameraPath(const std::string& name_or_path);

// The path's views around the box: `frames_override` views when > 0, else spec.frames.
// Frame i of N sits at path parameter s = i / (N - 1) (0 when N = 1), keyframe k at
// k / (K - 1). Between two keyframes the target moves linearly; the eye, seen from the
// target, turns by spherical linear interpolation of its direction and moves by geometric
// interpolation of its distance (d0^(1-t) d1^t); up is interpolated linearly, then
// normalised. Each view: perspective(fov, W/H, near, far) * lookAt(eye, target, up).
// Throws InputError when a sampled frame's up is parallel to its view direction.
view::CameraPath sampleCameraPath(const CameraPathSpec& spec, const mesh::Aabb& bounds,
                                  uint32_t frames_override = 0);

// sampleCameraPath as a CameraPathFn (the suite's form of a path).
CameraPathFn cameraPathFn(CameraPathSpec spec, uint32_t frames_override = 0);

}  // namespace tb::suite
