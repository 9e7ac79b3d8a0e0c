#include "harness/measures/culling/cull_oracle.h"

#include <algorithm>
#include <bit>
#include <span>
#include <stdexcept>
#include <string>

#include "core/gpu/context.h"
#include "core/gpu/gpu_error.h"
#include "core/gpu/patch_program.h"
#include "core/gpu/render_target.h"

namespace tb::measures {
namespace {

// TES invocations a draw aims for (lavapipe's tessellator slows down with many patches
// per draw), as the other measures batch their captures.
constexpr uint64_t kInvocationsPerDraw = 4096;
constexpr uint32_t kMaxPatchesPerDraw = 64;

using CoordKey = std::array<uint32_t, 3>;
CoordKey coordKey(const tess::DomainPoint& p) {
  return {std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
          std::bit_cast<uint32_t>(p[2])};
}

std::string describe(const tess::DomainPoint& p) {
  return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
         ")";
}

// The device positions of one patch's tessellation points: `captured` is that patch's
// vertices sorted by coordinate bits, exactly one per point of `tessellation`.
std::vector<mesh::Vec3f> positionsAtPoints(uint32_t patch, const tess::Tessellation& tessellation,
                                           std::span<const gpu::CapturedVertex> captured) {
  if (captured.size() != tessellation.points.size()) {
    throw gpu::GpuError("tessellateOnDevice: patch " + std::to_string(patch) + " has " +
                        std::to_string(captured.size()) + " device points, the tessellator " +
                        std::to_string(tessellation.points.size()));
  }
  std::vector<mesh::Vec3f> positions(tessellation.points.size());
  for (size_t k = 0; k < tessellation.points.size(); ++k) {
    const CoordKey key = coordKey(tessellation.points[k]);
    const auto found = std::lower_bound(captured.begin(), captured.end(), key,
                                        [](const gpu::CapturedVertex& v, const CoordKey& wanted) {
                                          return coordKey(v.coord) < wanted;
                                        });
    if (found == captured.end() || coordKey(found->coord) != key) {
      throw gpu::GpuError("tessellateOnDevice: patch " + std::to_string(patch) +
                          " has no device point at gl_TessCoord " +
                          describe(tessellation.points[k]));
    }
    positions[k] = found->position;
  }
  return positions;
}

// Outcode bit i: the clip vertex is outside frustum plane i (x<-w, x>w, y<-w, y>w, z<0, z>w).
uint32_t outsidePlanes(const std::array<float, 4>& c) {
  const float w = c[3];
  return uint32_t(c[0] < -w) | uint32_t(c[0] > w) << 1 | uint32_t(c[1] < -w) << 2 |
         uint32_t(c[1] > w) << 3 | uint32_t(c[2] < 0) << 4 | uint32_t(c[2] > w) << 5;
}

// det[x y w] of the three clip vertices (rows), in double from the floats the device gets.
// < 0: front-facing (counter-clockwise on the upright image); >= 0: back-facing or zero
// area. Homogeneous, so it holds for vertices behind the eye too (w <= 0).
double clipDeterminant(const std::array<float, 4>& a, const std::array<float, 4>& b,
                       const std::array<float, 4>& c) {
  const double ax = a[0], ay = a[1], aw = a[3];
  const double bx = b[0], by = b[1], bw = b[3];
  const double cx = c[0], cy = c[1], cw = c[3];
  return ax * (by * cw - bw * cy) - ay * (bx * cw - bw * cx) + aw * (bx * cy - by * cx);
}

}  // namespace

DeviceSurface tessellateOnDevice(gpu::Context& context, const techniques::SurfacePatches& patches,
                                 tess::Spacing spacing, const tess::Levels& levels) {
  const std::vector<gpu::GpuPatchProgram> programs = patches.gpuPrograms();
  if (programs.empty()) {
    throw gpu::GpuError("tessellateOnDevice: the technique has no GPU program");
  }
  // Per patch, its triangles; emitted in patch order at the end.
  std::vector<std::vector<std::array<mesh::Vec3f, 3>>> per_patch(patches.patchCount());
  for (const gpu::GpuPatchProgram& program : programs) {
    const tess::Tessellation tessellation = tess::tessellate(program.domain, spacing, levels);
    gpu::PatchProgramOptions options;
    options.spacing = spacing;
    options.statistics = false;
    const uint64_t points = std::max<size_t>(tessellation.points.size(), 1);
    options.patches_per_draw =
        uint32_t(std::clamp<uint64_t>(kInvocationsPerDraw / points, 1, kMaxPatchesPerDraw));
    const gpu::PatchProgramCapture capture =
        gpu::runPatchProgram(context, program, levels, options);
    // Sorted by (patch, coord bits): each patch's vertices are one run.
    const std::span<const gpu::CapturedVertex> all(capture.vertices);
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      const uint32_t patch = program.patch_ids.empty() ? i : program.patch_ids[i];
      const auto by_patch = [](const gpu::CapturedVertex& v, uint32_t p) { return v.patch < p; };
      const auto begin = std::lower_bound(all.begin(), all.end(), patch, by_patch);
      const auto end = std::lower_bound(begin, all.end(), patch + 1, by_patch);
      const std::vector<mesh::Vec3f> positions =
          positionsAtPoints(patch, tessellation, {begin, end});
      auto& out = per_patch.at(patch);
      out.reserve(tessellation.triangles.size());
      for (const std::array<uint32_t, 3>& t : tessellation.triangles) {
        out.push_back({positions[t[0]], positions[t[1]], positions[t[2]]});
      }
    }
  }
  DeviceSurface surface;
  surface.patch_count = patches.patchCount();
  for (uint32_t patch = 0; patch < per_patch.size(); ++patch) {
    surface.triangles.insert(surface.triangles.end(), per_patch[patch].begin(),
                             per_patch[patch].end());
    surface.triangle_patch.insert(surface.triangle_patch.end(), per_patch[patch].size(), patch);
  }
  return surface;
}

VisibilityOracle::VisibilityOracle(gpu::Context& context, const DeviceSurface& surface)
    : context_(context),
      patch_count_(surface.patch_count),
      triangles_(surface.triangles),
      triangle_patch_(surface.triangle_patch) {
  if (triangle_patch_.size() != triangles_.size()) {
    throw std::invalid_argument("VisibilityOracle: one patch per triangle needed");
  }
  for (uint32_t patch : triangle_patch_) {
    if (patch >= patch_count_) {
      throw std::invalid_argument("VisibilityOracle: triangle of patch " + std::to_string(patch) +
                                  " of " + std::to_string(patch_count_));
    }
  }
}

VisibilityOracle::~VisibilityOracle() = default;

void VisibilityOracle::transformAndClassify(const view::View& view, PatchVisibility* result) {
  const view::Mat4& m = view.view_projection;
  auto toClip = [&](const mesh::Vec3f& p) {
    const std::array<double, 4> c = m.transform({double(p.x), double(p.y), double(p.z), 1.0});
    return std::array<float, 4>{float(c[0]), float(c[1]), float(c[2]), float(c[3])};
  };
  clip_.resize(triangles_.size() * 3);
  result->ideally_cullable.assign(patch_count_, 1);
  result->back_facing.assign(patch_count_, 1);
  result->outside_frustum.assign(patch_count_, 1);
  for (size_t t = 0; t < triangles_.size(); ++t) {
    std::array<float, 4>* c = &clip_[t * 3];
    for (int k = 0; k < 3; ++k) c[k] = toClip(triangles_[t][k]);
    const bool back_facing = !(clipDeterminant(c[0], c[1], c[2]) < 0);
    const bool outside = (outsidePlanes(c[0]) & outsidePlanes(c[1]) & outsidePlanes(c[2])) != 0;
    const uint32_t patch = triangle_patch_[t];
    if (!back_facing) result->back_facing[patch] = 0;
    if (!outside) result->outside_frustum[patch] = 0;
    if (!back_facing && !outside) result->ideally_cullable[patch] = 0;
  }
}

PatchVisibility VisibilityOracle::visibility(const view::View& view) {
  PatchVisibility result;
  transformAndClassify(view, &result);
  if (!target_ || target_->width() != view.viewport_width_px ||
      target_->height() != view.viewport_height_px) {
    target_.reset();  // free the old attachments first
    target_ = std::make_unique<gpu::RenderTarget>(context_, view.viewport_width_px,
                                                  view.viewport_height_px);
  }
  gpu::RenderTarget::DrawOptions options;
  options.cull_back_faces = true;
  options.readback = gpu::RenderTarget::Readback::kIdsOnly;
  result.render_s = target_->drawTriangles(clip_, triangle_patch_, options);

  result.visible_pixels.assign(patch_count_, 0);
  for (const uint32_t id : target_->mappedIds()) {
    if (id != gpu::RenderTarget::kNoId) ++result.visible_pixels[id];
  }
  return result;
}

}  // namespace tb::measures
