// The culling measure's machinery: each culling policy (cull_policy.h) decided by every
// technique's own TCS on the device and by its CPU twin, the TES work it saves (lavapipe's
// pipeline statistics), and the patches it wrongly removes, counted against a rasterised
// render of the unculled surface (cull_oracle.h: the technique's own shaders, a depth
// buffer, fixed-function back-face culling and a per-patch ID target).
//
// Every patch is tessellated at one uniform integer level, so the TES saving is the share of
// domain points the culled patches would have had.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/gpu/context.h"
#include "core/view/view.h"
#include "harness/lod/cull_policy.h"
#include "techniques/technique.h"

namespace tb::measures {

class VisibilityOracle;
struct DeviceSurface;
struct PatchVisibility;

// One policy on one frame.
struct CullingFrame {
  uint32_t frame = 0;
  uint64_t patches = 0;
  // Patches the CPU twin culls. Best case: every patch that shows no pixel; worst: 0.
  uint64_t culled_patches = 0;
  // CPU tessellator counts at the run's level: the patches kept, and every patch.
  uint64_t tes_invocations = 0, tes_invocations_unculled = 0;
  uint64_t triangles = 0, triangles_unculled = 0;

  // lavapipe: the TCS's own decisions and pipeline statistics, with and without culling.
  bool gpu_measured = false;
  uint64_t gpu_culled_patches = 0;
  uint64_t gpu_tes_invocations = 0, gpu_tes_invocations_unculled = 0;
  bool gpu_primitives_counted = false;
  uint64_t gpu_primitives = 0, gpu_primitives_unculled = 0;
  // Patches whose culling decision differs between the TCS and the twin. Best 0; any is a bug.
  uint64_t twin_mismatches = 0;
  // The compute path (CullingOptions::compute): the same policy in compute
  // (core/gpu/compute_levels.h); patches whose decision differs from the TCS's. Best 0.
  bool compute_measured = false;
  uint64_t compute_mismatches = 0;

  // The ID-buffer oracle (a render of the unculled surface at the run's render size).
  bool oracle_measured = false;
  uint32_t render_width_px = 0, render_height_px = 0;
  uint64_t visible_patches = 0;   // patches with at least one pixel in the image
  uint64_t cullable_patches = 0;  // every triangle back-facing or outside the frustum
  // Culled patches that show pixels in the image (holes). Best 0; each is a visible hole.
  uint64_t false_culls = 0;
  uint64_t false_cull_pixels = 0;  // the pixels those patches cover
  // Cullable patches the policy kept (TES work an ideal culler would save). Best 0.
  uint64_t missed_culls = 0;
  // The efficiency against the oracle, and by cause (cull_policy.h CullPolicyHalves): the
  // cullable patches the policy culls; the back-facing ones (every triangle back-facing) its
  // back-facing half culls; the ones outside the frustum its frustum half culls. Each at most
  // the oracle's count beside it (best: equal; worst: 0).
  uint64_t culled_cullable_patches = 0;
  uint64_t back_facing_patches = 0, culled_back_facing_patches = 0;
  uint64_t outside_frustum_patches = 0, culled_outside_frustum_patches = 0;
};

// A policy over a whole path.
struct CullingSummary {
  uint32_t frames = 0;
  double mean_culled_fraction = 0;    // culled patches / patches, mean over frames
  double mean_tes_saving = 0;         // 1 - TES invocations / unculled, mean over frames
  double mean_cullable_fraction = 0;  // the ideal culler's share, for comparison
  uint64_t false_culls = 0, false_cull_pixels = 0, missed_culls = 0;
  uint64_t twin_mismatches = 0;
  // Sums over the frames of CullingFrame's efficiency counts: efficiency over the path is
  // culled / cullable of these sums (frames with more cullable patches weigh more).
  uint64_t cullable_patches = 0, culled_cullable_patches = 0;
  uint64_t back_facing_patches = 0, culled_back_facing_patches = 0;
  uint64_t outside_frustum_patches = 0, culled_outside_frustum_patches = 0;
  bool oracle_measured = false;  // every frame had the oracle
  bool gpu_measured = false;     // every frame ran on the device
  // Bytes of per-patch cull data the policy reads (lod::cullBytesPerPatch); set by the
  // caller, which knows the policy and the bounds.
  double cull_bytes_per_patch = 0;
  // The policy's TCS cost (culling_cost.h), set by the caller; absent when not measured.
  std::optional<double> tcs_instructions, cull_instructions;
};
CullingSummary summarise(std::span<const CullingFrame> frames);

struct CullingOptions {
  uint32_t level = 8;  // uniform integer tessellation level of every patch
  // The oracle's render size as a fraction of each view's viewport (1: the path's own).
  double render_scale = 1;
  // Control, for tests (made to fail): every tangent-plane coefficient negated, a wrong sign
  // convention under which tangent_plane culls the patches that face the eye.
  bool flip_tangent_plane = false;
  // Also decide on the compute path (CullingFrame::compute_*), with a device.
  bool compute = false;
};

class CullingRun {
 public:
  // `context` null: CPU twin and counts only; gpu_unavailable says why.
  CullingRun(const techniques::SurfacePatches& patches, gpu::Context* context,
             std::string gpu_unavailable, const CullingOptions& options);
  ~CullingRun();

  // Per policy (in `policies` order), one CullingFrame per view.
  std::vector<std::vector<CullingFrame>> frames(std::span<const lod::CullPolicy> policies,
                                                std::span<const view::View> views);

  const lod::CullBounds& bounds() const { return bounds_; }
  // Why the device figures (gpu_*, oracle) are missing; empty when they were measured.
  const std::string& gpuSkipReason() const { return gpu_skip_reason_; }

 private:
  struct DeviceCounts {
    std::vector<uint8_t> culled;  // per SurfacePatches patch, from the TCS's levels
    uint64_t tes_invocations = 0;
    bool primitives_counted = false;
    uint64_t primitives = 0;
    // With CullingOptions::compute: patches whose compute-path levels differ from the TCS's.
    uint64_t compute_mismatches = 0;
  };
  DeviceCounts runOnDevice(const lod::CullParams* params);
  // Per patch, 1 when the policy's back-facing half, or its frustum half, culls it (CPU twin).
  struct HalfDecisions {
    std::vector<uint8_t> back_facing, outside_frustum;
  };
  HalfDecisions halfDecisions(lod::CullPolicy policy, const view::View& view) const;
  static void countAgainstOracle(std::span<const uint8_t> culled, const PatchVisibility& visibility,
                                 const HalfDecisions& halves, CullingFrame* frame);
  void prepareDevice();

  const techniques::SurfacePatches& patches_;
  std::vector<gpu::GpuPatchProgram> programs_;
  // Per program, the packed bounds (patch_words, once) and the frame's view (param_words).
  std::vector<gpu::TcsCullPolicy> device_policies_;
  gpu::Context* context_;
  std::string gpu_skip_reason_;
  CullingOptions options_;
  lod::CullBounds bounds_;
  std::vector<uint64_t> patch_points_, patch_triangles_;
  bool device_ready_ = false;
  std::optional<DeviceCounts> unculled_;
  std::unique_ptr<DeviceSurface> surface_;
  std::unique_ptr<VisibilityOracle> oracle_;
};

}  // namespace tb::measures
