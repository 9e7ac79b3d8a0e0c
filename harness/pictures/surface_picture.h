// The two pictures of one surface (docs/REPORTS.md, "Pictures"): rendered on the
// Vulkan device into gpu::RenderTarget's triangle-ID buffer from a fixed 3/4 view, then
// composed on the CPU:
//  - error: each pixel the heat-map colour (heat_map.h) of its triangle's error
//    (SurfaceErrorMesh::triangle_error, the largest of its 3 vertices) over [0, scale_max],
//    times Lambert shading from the triangle's normal; a colour bar with the scale below;
//  - wireframe: light grey shaded faces, dark lines where a pixel's triangle differs from
//    its right or lower neighbour's (and along the silhouette).
// The background is white. Equal meshes give equal pictures, byte for byte.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/view/view.h"
#include "harness/pictures/heat_map.h"
#include "harness/pictures/rgb_image.h"
#include "harness/pictures/surface_error_mesh.h"
#include "harness/pictures/up_axis.h"

namespace tb::gpu {
class Context;
class RenderTarget;
}  // namespace tb::gpu

namespace tb::pictures {

struct PictureSettings {
  int level = 8;           // uniform integer tessellation level of every patch (1..64)
  uint32_t size_px = 208;  // the render is size_px x size_px; at least kMinimumPictureSizePx (208:
                           // report.html embeds every error picture and stays under 2 MB)
};

// Smaller renders leave no room for the colour bar's labels.
inline constexpr uint32_t kMinimumPictureSizePx = 64;

// The colour bar below the render: a gap, the bar, its labels (heat_map.h) and a margin.
inline constexpr uint32_t kColourBarGapPx = 4;
inline constexpr uint32_t kColourBarHeightPx = 12;
// Pixels below the render holding the colour bar and its labels (in both pictures, so
// they have one size: size_px x (size_px + kColourBarStripPx)).
inline constexpr uint32_t kColourBarStripPx =
    kColourBarGapPx + kColourBarHeightPx + kColourBarLabelPx + kColourBarGapPx;

// The smallest top of the colour scale, a fraction of the bounding-box diagonal: a surface
// whose error stays below it (exact up to double round-off, ~1e-16) is drawn all in the
// ramp's first colour instead of its round-off being stretched over the whole ramp.
inline constexpr double kMinimumScaleMax = 1e-6;

// The fixed camera: looking at the box's centre from the direction (1, 0.7, 1.4) (a 3/4 view
// from above, y up), 30 degree vertical field of view, far enough that the box's bounding
// sphere fits the square image. The box must have a positive diagonal. For a z-up asset
// (up_axis.h) the camera turns with the world: from (1, -1.4, 0.7) with z up, the view a
// y-up camera has of the asset rotated to y-up, so it stands upright.
view::View threeQuarterView(const mesh::Aabb& bounds, uint32_t size_px, UpAxis up = UpAxis::kY);

struct SurfacePictures {
  RgbImage error;
  RgbImage wireframe;
  double error_max = 0;  // SurfaceErrorMesh::error_max, fraction of the diagonal
  double scale_max = 0;  // the colour bar's top: max(error_max, kMinimumScaleMax)
  // Per render pixel (row-major, size_px^2), the triangle covering it, or
  // gpu::RenderTarget::kNoId.
  std::vector<uint32_t> triangle_ids;
  uint64_t covered_pixels = 0;  // pixels of the render showing the surface
  uint64_t edge_pixels = 0;     // dark line pixels of the wireframe (best 0 .. covered_pixels)
};

// Draws the mesh's triangles (no culling, depth test) under `view` into `target` (of the
// view's size) and returns the ID buffer. Thread-unsafe on `target`; the device queue is
// shared safely through gpu::Context.
std::vector<uint32_t> renderTriangleIds(gpu::RenderTarget& target, const SurfaceErrorMesh& mesh,
                                        const view::View& view);

// Composes both pictures from an ID buffer of renderTriangleIds (size_px^2 entries, size_px
// >= kMinimumPictureSizePx; std::invalid_argument otherwise). The colour scale's top is
// `scale_max` when given (one scale shared by several surfaces: at least this one's
// error_max), else max(mesh.error_max, kMinimumScaleMax). `up`: the view's up axis (the
// light comes from a little above, along it).
SurfacePictures composeSurfacePictures(const SurfaceErrorMesh& mesh, const view::View& view,
                                       uint32_t size_px, std::vector<uint32_t> triangle_ids,
                                       std::optional<double> scale_max = std::nullopt,
                                       UpAxis up = UpAxis::kY);

// The surface alone, size_px x size_px: light grey faces shaded as the wireframe's, a dark
// silhouette, no triangle lines (the base of the crack pictures, crack_picture.h).
RgbImage shadedPicture(const SurfaceErrorMesh& mesh, const view::View& view, uint32_t size_px,
                       std::span<const uint32_t> triangle_ids, UpAxis up = UpAxis::kY);

// All of it for one surface: the limit of patches.controlMesh() under the scheme it
// approximates (as the error measure builds it), tessellateWithError at settings.level,
// the up axis of the control mesh (detectUpAxis),
// a render target of settings.size_px, the render and the composition. Throws InputError
// when the reference cannot represent the mesh, gpu::GpuError for a device failure.
SurfacePictures renderSurfacePictures(gpu::Context& context,
                                      const techniques::SurfacePatches& patches,
                                      const PictureSettings& settings);

}  // namespace tb::pictures
