// A camera view a measure can be evaluated under (adaptive levels, culling): the
// view-projection matrix, the viewport and a screen-space target. Plain data with no
// dependency, so the CPU twins of shaders and the harness share it.
//
// Conventions (Vulkan): world positions are multiplied as column vectors, clip = M * p;
// the matrix is stored column-major (m[c][r], as GLSL's mat4 and a std140 block lay it
// out), so it uploads unchanged. Clip space is Vulkan's: x right, y DOWN, depth z in
// [0, w] (not OpenGL's [-w, w]); normalised device coordinates are clip.xyz / clip.w.
// Pixel coordinates: x in [0, width), y in [0, height), origin at the top-left corner.
#pragma once

#include <array>
#include <cstdint>

namespace tb::view {

// A 4x4 matrix, column-major: m[c][r] is row r of column c.
struct Mat4 {
  std::array<std::array<double, 4>, 4> m{};
  static Mat4 identity() {
    Mat4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
  }
  // The product (*this) * other: transforming by it applies `other` first.
  Mat4 operator*(const Mat4& other) const {
    Mat4 r;
    for (int c = 0; c < 4; ++c) {
      for (int row = 0; row < 4; ++row) {
        double sum = 0;
        for (int k = 0; k < 4; ++k) sum += m[k][row] * other.m[c][k];
        r.m[c][row] = sum;
      }
    }
    return r;
  }
  // M * (x, y, z, w) as a column vector.
  std::array<double, 4> transform(const std::array<double, 4>& p) const {
    std::array<double, 4> r{};
    for (int row = 0; row < 4; ++row) {
      r[row] = m[0][row] * p[0] + m[1][row] * p[1] + m[2][row] * p[2] + m[3][row] * p[3];
    }
    return r;
  }
  bool operator==(const Mat4&) const = default;
};

struct View {
  // World (asset units) to Vulkan clip space: projection * view, column-major (above).
  Mat4 view_projection = Mat4::identity();
  uint32_t viewport_width_px = 1;   // pixels; > 0
  uint32_t viewport_height_px = 1;  // pixels; > 0
  // The screen-space edge length an adaptive factor policy aims for, in pixels per
  // tessellated edge (smaller: finer tessellation). 8 is a common real-time choice.
  double target_pixels_per_edge = 8;
  // The camera position in world units (distance-based factor policies).
  std::array<double, 3> eye{0, 0, 0};
  // |P[1][1]| of the projection alone: 1 / tan(vertical field of view / 2). A world
  // length d at clip w spans d * projection_y_scale / w of NDC's height of 2.
  double projection_y_scale = 1;
  // The near plane's distance from the eye, world units (> 0).
  double near_plane = 0.01;
};

// Pixel position of a world point under `view` ({x, y} in pixels, see the conventions
// above), and its clip w (> 0 in front of the camera; the pixel is meaningless otherwise).
struct ProjectedPoint {
  double x_px = 0, y_px = 0, clip_w = 0;
};
inline ProjectedPoint projectToPixels(const View& view, double x, double y, double z) {
  const std::array<double, 4> clip = view.view_projection.transform({x, y, z, 1});
  ProjectedPoint p;
  p.clip_w = clip[3];
  if (clip[3] == 0) return p;
  p.x_px = (clip[0] / clip[3] * 0.5 + 0.5) * view.viewport_width_px;
  p.y_px = (clip[1] / clip[3] * 0.5 + 0.5) * view.viewport_height_px;
  return p;
}

}  // namespace tb::view
