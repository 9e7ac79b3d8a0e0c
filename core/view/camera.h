// Camera matrices in the conventions of core/view/view.h (column-major, Vulkan clip space:
// y down, depth in [0, 1]), for building View::view_projection.
#pragma once

#include <cmath>

#include "core/mesh/vec.h"
#include "core/view/view.h"

namespace tb::view {

// World to eye space, right-handed: the camera at `eye` looks at `target`; eye space has
// x right, y up, and looks down -z. `up` must not be parallel to target - eye.
inline Mat4 lookAt(const mesh::Vec3d& eye, const mesh::Vec3d& target, const mesh::Vec3d& up) {
  const mesh::Vec3d f = normalize(target - eye);
  const mesh::Vec3d s = normalize(cross(f, up));
  const mesh::Vec3d u = cross(s, f);
  Mat4 r = Mat4::identity();
  for (int i = 0; i < 3; ++i) {
    r.m[i][0] = s[i];
    r.m[i][1] = u[i];
    r.m[i][2] = -f[i];
  }
  r.m[3][0] = -dot(s, eye);
  r.m[3][1] = -dot(u, eye);
  r.m[3][2] = dot(f, eye);
  return r;
}

// Eye space to Vulkan clip space: vertical field of view in radians, aspect = width /
// height, near and far planes in world units (0 < near < far). Depth maps near -> 0,
// far -> 1; eye-space y up becomes clip y down (Vulkan's framebuffer y).
inline Mat4 perspective(double fov_y_rad, double aspect, double near_plane, double far_plane) {
  const double f = 1.0 / std::tan(fov_y_rad / 2);
  Mat4 r;
  r.m[0][0] = f / aspect;
  r.m[1][1] = -f;
  r.m[2][2] = far_plane / (near_plane - far_plane);
  r.m[2][3] = -1;
  r.m[3][2] = near_plane * far_plane / (near_plane - far_plane);
  return r;
}

// A perspective camera as plain parameters (the conventions above).
struct PerspectiveCamera {
  mesh::Vec3d eye{0, 0, 1};
  mesh::Vec3d target{0, 0, 0};
  mesh::Vec3d up{0, 1, 0};
  double fov_y_rad = 0.7853981633974483;  // 45 degrees
  uint32_t width_px = 1, height_px = 1;
  double near_plane = 0.01, far_plane = 100;  // world units
  double target_pixels_per_edge = 8;
};

// The View of `camera`: perspective * lookAt, its viewport, eye, |P[1][1]| and near plane.
inline View perspectiveView(const PerspectiveCamera& camera) {
  View view;
  view.view_projection = perspective(camera.fov_y_rad, double(camera.width_px) / camera.height_px,
                                     camera.near_plane, camera.far_plane) *
                         lookAt(camera.eye, camera.target, camera.up);
  view.viewport_width_px = camera.width_px;
  view.viewport_height_px = camera.height_px;
  view.target_pixels_per_edge = camera.target_pixels_per_edge;
  view.eye = {camera.eye.x, camera.eye.y, camera.eye.z};
  view.projection_y_scale = 1 / std::tan(camera.fov_y_rad / 2);
  view.near_plane = camera.near_plane;
  return view;
}

}  // namespace tb::view
