#include "harness/pictures/surface_picture.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/gpu/render_target.h"
#include "core/view/camera.h"
#include "harness/measures/error/error.h"
#include "harness/pictures/heat_map.h"

namespace tb::pictures {
namespace {

constexpr double kFieldOfViewRad = 30.0 * std::numbers::pi / 180.0;
constexpr Rgb kLine{30, 30, 30};
constexpr double kFaceGrey = 235;     // wireframe face, lit head-on
constexpr double kNoLimitGrey = 170;  // error picture, a patch without limit surface
// Lambert shading kept within [kAmbient, 1] so that faces seen edge-on keep their colour.
constexpr double kAmbient = 0.45;

// Light from the eye's side, a little above and to the left, in world units.
mesh::Vec3d lightDirection(const view::View& view, const mesh::Aabb& bounds, UpAxis up_axis) {
  const mesh::Vec3d centre = 0.5 * (bounds.min + bounds.max);
  const mesh::Vec3d eye{view.eye[0], view.eye[1], view.eye[2]};
  const mesh::Vec3d to_eye = normalize(eye - centre);
  const mesh::Vec3d up = upVector(up_axis);
  const mesh::Vec3d right = normalize(cross(-1.0 * to_eye, up));
  return normalize(to_eye + 0.5 * up - 0.3 * right);
}

// Per triangle, kAmbient + (1 - kAmbient) |n . light|: two-sided, since open meshes show
// their back faces. A degenerate triangle is lit fully.
std::vector<double> triangleShading(const SurfaceErrorMesh& mesh, const mesh::Vec3d& light) {
  std::vector<double> shade(mesh.triangles.size(), 1.0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const mesh::Vec3d& a = mesh.positions[tri[0]];
    const mesh::Vec3d n = cross(mesh.positions[tri[1]] - a, mesh.positions[tri[2]] - a);
    const double len = length(n);
    if (len > 0) shade[t] = kAmbient + (1 - kAmbient) * std::abs(dot(n, light)) / len;
  }
  return shade;
}

uint8_t scaled(double channel, double factor) {
  return uint8_t(std::clamp(std::lround(channel * factor), 0L, 255L));
}

Rgb shaded(Rgb colour, double factor) {
  return {scaled(colour.r, factor), scaled(colour.g, factor), scaled(colour.b, factor)};
}

// The triangle IDs of a render, size_px x size_px, row-major.
struct IdBuffer {
  std::span<const uint32_t> ids;
  uint32_t size_px;
  uint32_t at(uint32_t x, uint32_t y) const { return ids[size_t(y) * size_px + x]; }
  // A line pixel: the left or upper neighbour shows no surface, or the right or lower one
  // shows another triangle (only_silhouette: no surface).
  bool edge(uint32_t x, uint32_t y, uint32_t id, bool only_silhouette) const {
    constexpr uint32_t kNone = gpu::RenderTarget::kNoId;
    auto differs = [&](uint32_t other) { return only_silhouette ? other == kNone : other != id; };
    return (x + 1 < size_px && differs(at(x + 1, y))) ||
           (y + 1 < size_px && differs(at(x, y + 1))) || (x > 0 && at(x - 1, y) == kNone) ||
           (y > 0 && at(x, y - 1) == kNone);
  }
  // fn(x, y, id) for every pixel showing a triangle of `mesh`, row by row; throws
  // std::logic_error for an ID out of range.
  template <class Fn>
  void forEachCovered(const SurfaceErrorMesh& mesh, Fn fn) const {
    for (uint32_t y = 0; y < size_px; ++y) {
      for (uint32_t x = 0; x < size_px; ++x) {
        const uint32_t id = at(x, y);
        if (id == gpu::RenderTarget::kNoId) continue;
        if (id >= mesh.triangles.size())
          throw std::logic_error("pictures: triangle ID out of range");
        fn(x, y, id);
      }
    }
  }
};

}  // namespace

view::View threeQuarterView(const mesh::Aabb& bounds, uint32_t size_px, UpAxis up) {
  const double diagonal = mesh::diagonalOf(bounds);
  if (!(diagonal > 0) || !std::isfinite(diagonal)) {
    throw std::invalid_argument("threeQuarterView: the bounding box has no positive diagonal");
  }
  const double radius = diagonal / 2;
  const double distance = 1.02 * radius / std::sin(kFieldOfViewRad / 2);
  view::PerspectiveCamera camera;
  camera.target = 0.5 * (bounds.min + bounds.max);
  // z-up: the y-up direction seen with the world turned (x, y, z) -> (x, z, -y).
  const mesh::Vec3d from = up == UpAxis::kZ ? mesh::Vec3d{1, -1.4, 0.7} : mesh::Vec3d{1, 0.7, 1.4};
  camera.eye = camera.target + distance * normalize(from);
  camera.up = upVector(up);
  camera.fov_y_rad = kFieldOfViewRad;
  camera.width_px = camera.height_px = size_px;
  camera.near_plane = std::max(distance - 1.05 * radius, 1e-3 * radius);
  camera.far_plane = distance + 1.05 * radius;
  return view::perspectiveView(camera);
}

std::vector<uint32_t> renderTriangleIds(gpu::RenderTarget& target, const SurfaceErrorMesh& mesh,
                                        const view::View& view) {
  std::vector<std::array<float, 4>> clip;
  clip.reserve(mesh.triangles.size() * 3);
  for (const auto& tri : mesh.triangles) {
    for (uint32_t v : tri) {
      const mesh::Vec3d& p = mesh.positions[v];
      const std::array<double, 4> c = view.view_projection.transform({p.x, p.y, p.z, 1.0});
      clip.push_back({float(c[0]), float(c[1]), float(c[2]), float(c[3])});
    }
  }
  std::vector<uint32_t> ids(mesh.triangles.size());
  for (size_t t = 0; t < ids.size(); ++t) ids[t] = uint32_t(t);
  gpu::RenderTarget::DrawOptions options;
  options.readback = gpu::RenderTarget::Readback::kIdsOnly;
  target.drawTriangles(clip, ids, options);
  const std::span<const uint32_t> rendered = target.mappedIds();
  return {rendered.begin(), rendered.end()};
}

SurfacePictures composeSurfacePictures(const SurfaceErrorMesh& mesh, const view::View& view,
                                       uint32_t size_px, std::vector<uint32_t> triangle_ids,
                                       std::optional<double> scale_max, UpAxis up) {
  if (size_px < kMinimumPictureSizePx || triangle_ids.size() != size_t(size_px) * size_px) {
    throw std::invalid_argument(
        "composeSurfacePictures: the picture is under 64 px or the ID buffer is not size_px^2");
  }
  SurfacePictures pictures;
  pictures.error_max = mesh.error_max;
  pictures.scale_max = std::max({mesh.error_max, kMinimumScaleMax, scale_max.value_or(0)});
  pictures.error = RgbImage(size_px, size_px + kColourBarStripPx);
  pictures.wireframe = RgbImage(size_px, size_px + kColourBarStripPx);
  const std::vector<double> shade = triangleShading(mesh, lightDirection(view, mesh.bounds, up));
  const IdBuffer buffer{triangle_ids, size_px};
  buffer.forEachCovered(mesh, [&](uint32_t x, uint32_t y, uint32_t id) {
    ++pictures.covered_pixels;
    const double error = mesh.triangle_error[id];
    const Rgb base = std::isnan(error)
                         ? Rgb{uint8_t(kNoLimitGrey), uint8_t(kNoLimitGrey), uint8_t(kNoLimitGrey)}
                         : heatColour(error / pictures.scale_max);
    pictures.error.set(x, y, shaded(base, shade[id]));
    // A line where the triangle changes towards the right or lower neighbour, and on the
    // silhouette seen from the left or upper neighbour: one pixel wide.
    const bool edge = buffer.edge(x, y, id, false);
    pictures.edge_pixels += edge;
    const uint8_t grey = scaled(kFaceGrey, shade[id]);
    pictures.wireframe.set(x, y, edge ? kLine : Rgb{grey, grey, grey});
  });
  const uint32_t margin_px = std::min<uint32_t>(12, size_px / 8);  // left and right of the bar
  drawColourBar(&pictures.error, margin_px, size_px + kColourBarGapPx, size_px - 2 * margin_px,
                kColourBarHeightPx, pictures.scale_max);
  pictures.triangle_ids = std::move(triangle_ids);
  return pictures;
}

RgbImage shadedPicture(const SurfaceErrorMesh& mesh, const view::View& view, uint32_t size_px,
                       std::span<const uint32_t> triangle_ids, UpAxis up) {
  if (triangle_ids.size() != size_t(size_px) * size_px) {
    throw std::invalid_argument("shadedPicture: the ID buffer is not size_px^2");
  }
  RgbImage image(size_px, size_px);
  const std::vector<double> shade = triangleShading(mesh, lightDirection(view, mesh.bounds, up));
  const IdBuffer buffer{triangle_ids, size_px};
  buffer.forEachCovered(mesh, [&](uint32_t x, uint32_t y, uint32_t id) {
    const uint8_t grey = scaled(kFaceGrey, shade[id]);
    image.set(x, y, buffer.edge(x, y, id, true) ? kLine : Rgb{grey, grey, grey});
  });
  return image;
}

SurfacePictures renderSurfacePictures(gpu::Context& context,
                                      const techniques::SurfacePatches& patches,
                                      const PictureSettings& settings) {
  const ref::LimitSurface limit(patches.controlMesh(),
                                lod::referenceScheme(patches.approximates()));
  const SurfaceErrorMesh mesh = tessellateWithError(patches, limit, settings.level);
  const UpAxis up = detectUpAxis(patches.controlMesh().positions);
  const view::View view = threeQuarterView(mesh.bounds, settings.size_px, up);
  gpu::RenderTarget target(context, settings.size_px, settings.size_px);
  return composeSurfacePictures(mesh, view, settings.size_px, renderTriangleIds(target, mesh, view),
                                std::nullopt, up);
}

}  // namespace tb::pictures
