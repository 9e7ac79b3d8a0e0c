// Sampling a camera path file (CameraPathSpec) to views, and the geometric rules a path
// must keep for every sample to have a camera: the field-level rules are the reader's
// (camera_path_file.cpp).
#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

#include "core/mesh/input_error.h"
#include "core/view/camera.h"
#include "harness/suite/camera_path.h"

namespace tb::suite {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
// The smallest sine of the angle between up and the view direction that a camera may
// have: below it lookAt's right axis (view direction × up) is mostly rounding.
constexpr double kMinUpSine = 1e-6;
// Consecutive keyframes whose view directions (eye - target) are this close to opposite
// (radians short of 180 degrees) have no well-defined turn between them (slerp).
constexpr double kMinOppositeGapRad = 1e-6;
// Directions closer than this (radians) are interpolated linearly: the slerp weights'
// quotient of sines loses its accuracy there.
constexpr double kSlerpLinearBelowRad = 1e-9;

std::string keyframeField(size_t k, const char* field) {
  return "keyframes[" + std::to_string(k) + "]." + field;
}

double angleBetween(const mesh::Vec3d& a, const mesh::Vec3d& b) {  // radians, unit vectors
  return std::atan2(length(cross(a, b)), dot(a, b));
}

// Eye, target and up of each keyframe make a camera, and consecutive view directions are
// not opposite. Positions in the path's own space; the rules hold in world space too
// (a bounds-space path is scaled and moved, never turned).
void checkKeyframes(const CameraPathSpec& spec) {
  if (spec.keyframes.empty()) throw mesh::InputError(spec.shown_path, "keyframes", "no keyframes");
  for (size_t k = 0; k < spec.keyframes.size(); ++k) {
    const CameraKeyframe& key = spec.keyframes[k];
    const mesh::Vec3d offset = key.eye - key.target;
    if (!(length(offset) > 0)) {
      throw mesh::InputError(spec.shown_path, keyframeField(k, "eye"),
                             "equals the target (no view direction)");
    }
    if (!std::isfinite(length(offset))) {
      throw mesh::InputError(spec.shown_path, keyframeField(k, "eye"),
                             "too far from the target (the distance overflows)");
    }
    if (!(length(key.up) > 0)) {
      throw mesh::InputError(spec.shown_path, keyframeField(k, "up"), "zero-length vector");
    }
    if (length(cross(normalize(key.up), normalize(offset))) < kMinUpSine) {
      throw mesh::InputError(spec.shown_path, keyframeField(k, "up"),
                             "parallel to the view direction (eye - target)");
    }
    if (k == 0) continue;
    const CameraKeyframe& previous = spec.keyframes[k - 1];
    if (angleBetween(normalize(previous.eye - previous.target), normalize(offset)) >
        std::numbers::pi - kMinOppositeGapRad) {
      throw mesh::InputError(spec.shown_path, keyframeField(k, "eye"),
                             "seen from the target, opposite to keyframes[" +
                                 std::to_string(k - 1) +
                                 "] (the turn between them is undefined; add a keyframe between)");
    }
  }
}

// Spherical linear interpolation of unit vectors a and b (not opposite), t in [0, 1].
mesh::Vec3d slerp(const mesh::Vec3d& a, const mesh::Vec3d& b, double t) {
  const double omega = angleBetween(a, b);
  if (omega < kSlerpLinearBelowRad) return normalize((1 - t) * a + t * b);
  const double sin_omega = std::sin(omega);
  return normalize((std::sin((1 - t) * omega) / sin_omega) * a +
                   (std::sin(t * omega) / sin_omega) * b);
}

// Where path parameter s in [0, 1] falls: between keyframes k and k + 1, at t in [0, 1]
// (keyframe k sits at s = k / (K - 1)); k = 0, t = 0 on a path of one keyframe.
struct PathPoint {
  size_t k = 0;
  double t = 0;
};
PathPoint pathPoint(size_t keyframe_count, double s) {
  if (keyframe_count == 1) return {};
  const double x = s * double(keyframe_count - 1);
  const size_t k = std::min(size_t(std::floor(x)), keyframe_count - 2);
  return {k, x - double(k)};
}

// A camera in the path's space; up is interpolated, not yet normalised (it may be zero).
struct Pose {
  mesh::Vec3d eye, target, up;
};

Pose poseAt(const CameraPathSpec& spec, const PathPoint& at) {
  const std::vector<CameraKeyframe>& keys = spec.keyframes;
  if (keys.size() == 1) return {keys[0].eye, keys[0].target, keys[0].up};
  const CameraKeyframe &a = keys[at.k], &b = keys[at.k + 1];
  const double t = at.t;
  Pose pose;
  pose.target = (1 - t) * a.target + t * b.target;
  const mesh::Vec3d from_a = a.eye - a.target, from_b = b.eye - b.target;
  const double distance_a = length(from_a), distance_b = length(from_b);
  // Geometric in the distance: equal ratios per equal step (a logarithmic dolly).
  const double distance = distance_a * std::pow(distance_b / distance_a, t);
  pose.eye = pose.target + distance * slerp(normalize(from_a), normalize(from_b), t);
  pose.up = (1 - t) * a.up + t * b.up;
  return pose;
}

}  // namespace

view::CameraPath sampleCameraPath(const CameraPathSpec& spec, const mesh::Aabb& bounds,
                                  uint32_t frames_override) {
  checkKeyframes(spec);
  const uint32_t frames = frames_override > 0 ? frames_override : spec.frames;
  assert(frames > 0 && spec.width_px > 0 && spec.height_px > 0);
  // Path space to world: x -> centre + scale x (bounds) or x (world). A box of no extent
  // (a single point) counts as 1 unit across, so it still gets cameras.
  mesh::Vec3d centre{0, 0, 0};
  double scale = 1;
  if (spec.bounds_space) {
    centre = 0.5 * (bounds.min + bounds.max);
    const double diagonal = length(bounds.max - bounds.min);
    scale = diagonal > 0 ? diagonal : 1;
  }
  const double fov_y_rad = spec.fov_y_deg * kDegree;
  const double near_world = scale * spec.near_plane, far_world = scale * spec.far_plane;
  const view::Mat4 projection = view::perspective(
      fov_y_rad, double(spec.width_px) / double(spec.height_px), near_world, far_world);
  view::CameraPath path{spec.name, {}};
  path.views.reserve(frames);
  for (uint32_t i = 0; i < frames; ++i) {
    const double s = frames == 1 ? 0 : double(i) / double(frames - 1);
    const PathPoint at = pathPoint(spec.keyframes.size(), s);
    const Pose pose = poseAt(spec, at);
    const mesh::Vec3d up = normalize(pose.up);
    const bool up_zero = !(length(pose.up) > 0);
    if (up_zero || length(cross(up, normalize(pose.eye - pose.target))) < kMinUpSine) {
      throw mesh::InputError(spec.shown_path,
                             "frame " + std::to_string(i) + " of " + std::to_string(frames) +
                                 " (after keyframes[" + std::to_string(at.k) + "]).up",
                             up_zero ? "interpolates to a zero-length vector"
                                     : "parallel to the view direction (eye - target)");
    }
    const mesh::Vec3d eye = centre + scale * pose.eye, target = centre + scale * pose.target;
    view::View view;
    view.view_projection = projection * view::lookAt(eye, target, up);
    view.viewport_width_px = spec.width_px;
    view.viewport_height_px = spec.height_px;
    view.target_pixels_per_edge = spec.target_pixels_per_edge;
    view.eye = {eye.x, eye.y, eye.z};
    view.projection_y_scale = 1 / std::tan(fov_y_rad / 2);
    view.near_plane = near_world;
    path.views.push_back(view);
  }
  return path;
}

CameraPathFn cameraPathFn(CameraPathSpec spec, uint32_t frames_override) {
  return [spec = std::move(spec), frames_override](const mesh::Aabb& bounds) {
    return sampleCameraPath(spec, bounds, frames_override);
  };
}

}  // namespace tb::suite
