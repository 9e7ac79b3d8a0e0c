// The culling measure's oracle: which patches a real rasterised render on the device shows
// (the technique's own TCS/TES, depth test, fixed-function back-face culling, per-patch ID
// buffer: a culled patch with a pixel is a false cull), and, independently, which patches an
// ideal back-face + frustum culler may remove (every triangle back-facing or outside one
// clip plane). Occlusion is left to neither. Front faces are counter-clockwise seen from the
// eye (gpu::RenderTarget::DrawOptions), as every technique's triangles face out of a closed
// mesh (tests/measures/cull_oracle_test.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/mesh/vec.h"
#include "core/tess/tessellator.h"
#include "core/view/view.h"
#include "techniques/technique.h"

namespace tb::gpu {
class Context;
class RenderTarget;
}  // namespace tb::gpu

namespace tb::measures {

// Every patch's tessellated surface as the technique's own TCS/TES computed it on the device.
struct DeviceSurface {
  size_t patch_count = 0;
  // World positions (controlMesh() units), winding front-facing per the convention above:
  // (v1 - v0) x (v2 - v0) points out of a closed surface.
  std::vector<std::array<mesh::Vec3f, 3>> triangles;
  std::vector<uint32_t> triangle_patch;  // SurfacePatches patch of each triangle
};

// Runs every gpuPrograms() entry of `patches` with `levels` for every patch (capturing every
// TES invocation) and connects the captured positions with the CPU tessellator's triangles
// for those levels (layout(ccw), as every patch program declares), matching by patch and
// exact gl_TessCoord bits. Triangles come patch by patch, each patch's in the tessellator's
// order. Throws gpu::GpuError when there is no GPU program, or when the device's points of
// a patch are not exactly the tessellator's (a point missing or extra).
// Cost: one capture of every TES invocation plus a sort; catmark_torus with acc at level 8
// (32 patches, 4096 triangles) takes ~0.03 s on lavapipe, most of it the pipeline's first use.
DeviceSurface tessellateOnDevice(gpu::Context& context, const techniques::SurfacePatches& patches,
                                 tess::Spacing spacing, const tess::Levels& levels);

struct PatchVisibility {
  // Per patch: pixels of the final image showing it (ID buffer of a render with the depth
  // test and fixed-function back-face culling). Best case for a culler: every patch with 0
  // here culled; a culled patch with > 0 is a false cull.
  std::vector<uint64_t> visible_pixels;
  // Per patch: 1 when an ideal back-face + frustum culler could remove it, decided
  // geometrically on the clip positions sent to the device: each of its triangles is
  // back-facing (det[x y w] >= 0 over its clip vertices; zero-area ones count as back) or
  // has all three clip vertices outside one of the planes x < -w, x > w, y < -w, y > w,
  // z < 0, z > w. Occlusion never makes a patch cullable. A patch with no triangles is 1.
  std::vector<uint8_t> ideally_cullable;
  // The two causes apart, per patch: 1 when every triangle is back-facing (an ideal back-face
  // culler removes it), and when every triangle has its clip vertices outside one plane (an
  // ideal frustum culler removes it). A cullable patch may be neither (some triangles back,
  // the others outside) or both.
  std::vector<uint8_t> back_facing, outside_frustum;
  double render_s = 0;  // host seconds, submit to fence, of the render and ID readback
};

// Renders a DeviceSurface under a View at the view's viewport size, patch index as the ID,
// clip = view_projection * p computed on the host in double and sent as float. The render
// target is kept and reused while the viewport size stays the same. Not thread-safe.
// Cost per call: the device render (clears, rasterisation, one 4-byte-per-pixel ID copy),
// one host pass over the triangles (transform + tests) and one over the ID pixels. On
// lavapipe (2 cores), catmark_torus with acc at level 8: ~5 ms at 1920 x 1080 (4 ms of it
// the render), ~0.8 ms at 480 x 270; the first call at a size also makes the target.
class VisibilityOracle {
 public:
  // Copies the surface's triangles; `context` must outlive the oracle.
  VisibilityOracle(gpu::Context& context, const DeviceSurface& surface);
  ~VisibilityOracle();
  VisibilityOracle(const VisibilityOracle&) = delete;
  VisibilityOracle& operator=(const VisibilityOracle&) = delete;

  PatchVisibility visibility(const view::View& view);

 private:
  // Fills clip_ and the result's ideally_cullable, back_facing and outside_frustum.
  void transformAndClassify(const view::View& view, PatchVisibility* result);

  gpu::Context& context_;
  size_t patch_count_;
  std::vector<std::array<mesh::Vec3f, 3>> triangles_;
  std::vector<uint32_t> triangle_patch_;
  std::vector<std::array<float, 4>> clip_;  // 3 per triangle, reused between calls
  std::unique_ptr<gpu::RenderTarget> target_;
};

}  // namespace tb::measures
