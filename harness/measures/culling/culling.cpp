#include "harness/measures/culling/culling.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "core/gpu/compute_levels.h"
#include "core/gpu/gpu_error.h"
#include "core/gpu/patch_program.h"
#include "core/mesh/bounds.h"
#include "core/tess/tessellator.h"
#include "harness/lod/factor_policy.h"
#include "harness/measures/culling/cull_oracle.h"

namespace tb::measures {
namespace {

// Patches per draw: lavapipe's tessellator slows down with many patches in one draw; at the
// culling run's low levels 64 keeps the draws few.
constexpr uint32_t kPatchesPerDraw = 64;

tess::Levels uniformLevels(uint32_t level) {
  const float l = float(level);
  return {{l, l, l, l}, {l, l}};
}

view::View scaledView(const view::View& view, double scale) {
  view::View scaled = view;
  scaled.viewport_width_px =
      std::max<uint32_t>(1, uint32_t(std::lround(view.viewport_width_px * scale)));
  scaled.viewport_height_px =
      std::max<uint32_t>(1, uint32_t(std::lround(view.viewport_height_px * scale)));
  return scaled;
}

}  // namespace

CullingSummary summarise(std::span<const CullingFrame> frames) {
  CullingSummary s;
  s.frames = uint32_t(frames.size());
  s.oracle_measured = !frames.empty();
  s.gpu_measured = !frames.empty();
  for (const CullingFrame& f : frames) {
    if (f.patches > 0) {
      s.mean_culled_fraction += double(f.culled_patches) / double(f.patches);
    }
    if (f.tes_invocations_unculled > 0) {
      s.mean_tes_saving += 1 - double(f.tes_invocations) / double(f.tes_invocations_unculled);
    }
    if (f.oracle_measured && f.patches > 0) {
      s.mean_cullable_fraction += double(f.cullable_patches) / double(f.patches);
    }
    s.false_culls += f.false_culls;
    s.false_cull_pixels += f.false_cull_pixels;
    s.missed_culls += f.missed_culls;
    s.twin_mismatches += f.twin_mismatches;
    s.cullable_patches += f.cullable_patches;
    s.culled_cullable_patches += f.culled_cullable_patches;
    s.back_facing_patches += f.back_facing_patches;
    s.culled_back_facing_patches += f.culled_back_facing_patches;
    s.outside_frustum_patches += f.outside_frustum_patches;
    s.culled_outside_frustum_patches += f.culled_outside_frustum_patches;
    s.oracle_measured = s.oracle_measured && f.oracle_measured;
    s.gpu_measured = s.gpu_measured && f.gpu_measured;
  }
  if (!frames.empty()) {
    s.mean_culled_fraction /= double(frames.size());
    s.mean_tes_saving /= double(frames.size());
    s.mean_cullable_fraction /= double(frames.size());
  }
  return s;
}

CullingRun::CullingRun(const techniques::SurfacePatches& patches, gpu::Context* context,
                       std::string gpu_unavailable, const CullingOptions& options)
    : patches_(patches), programs_(patches.gpuPrograms()), context_(context), options_(options) {
  bounds_ = lod::cullBounds(patches, lod::factorCorners(patches),
                            mesh::diagonalOf(mesh::boundsOf(patches.controlMesh())),
                            float(options.level));
  if (options.flip_tangent_plane) {
    for (lod::CullPatchBounds& patch : bounds_.patches) {
      for (std::array<float, 4>& c : patch.tangent_plane) {
        for (float& v : c) v = -v;
      }
    }
  }
  const tess::Levels levels = uniformLevels(options.level);
  const tess::Tessellation quad =
      tess::tessellate(tess::Domain::kQuad, tess::Spacing::kInteger, levels);
  const tess::Tessellation triangle =
      tess::tessellate(tess::Domain::kTriangle, tess::Spacing::kInteger, levels);
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const tess::Tessellation& t =
        patches.patchDomain(p) == techniques::PatchDomain::kQuad ? quad : triangle;
    patch_points_.push_back(t.points.size());
    patch_triangles_.push_back(t.triangles.size());
  }
  for (const gpu::GpuPatchProgram& program : programs_) {
    device_policies_.push_back(lod::cullPatchData(bounds_, program));
  }
  if (programs_.empty()) {
    gpu_skip_reason_ = "the technique has no GPU program";
  } else if (context_ == nullptr) {
    gpu_skip_reason_ = "no Vulkan device (" + gpu_unavailable + ")";
  }
}

CullingRun::~CullingRun() = default;

void CullingRun::prepareDevice() {
  if (device_ready_ || !gpu_skip_reason_.empty()) return;
  device_ready_ = true;
  try {
    unculled_ = runOnDevice(nullptr);
    surface_ = std::make_unique<DeviceSurface>(tessellateOnDevice(
        *context_, patches_, tess::Spacing::kInteger, uniformLevels(options_.level)));
    oracle_ = std::make_unique<VisibilityOracle>(*context_, *surface_);
  } catch (const gpu::GpuError& error) {
    gpu_skip_reason_ = std::string("device run failed: ") + error.what();
  }
}

CullingRun::DeviceCounts CullingRun::runOnDevice(const lod::CullParams* params) {
  DeviceCounts counts;
  counts.culled.assign(patches_.patchCount(), 0);
  counts.primitives_counted = true;
  const tess::Levels levels = uniformLevels(options_.level);
  for (size_t k = 0; k < programs_.size(); ++k) {
    const gpu::GpuPatchProgram& program = programs_[k];
    gpu::PatchProgramOptions run_options;
    run_options.spacing = tess::Spacing::kInteger;
    run_options.capture = false;
    run_options.statistics = true;
    run_options.patches_per_draw = kPatchesPerDraw;
    if (params != nullptr) {
      device_policies_[k].param_words = lod::cullParamWords(*params);
      run_options.cull_policy = &device_policies_[k];
    }
    const gpu::PatchProgramCapture run =
        gpu::runPatchProgram(*context_, program, levels, run_options);
    counts.tes_invocations += run.stats.tes_invocations;
    counts.primitives += run.stats.primitives_generated;
    counts.primitives_counted = counts.primitives_counted && run.stats.primitives_counted;
    if (params == nullptr) continue;
    std::vector<tess::LevelsBits> compute;
    if (options_.compute) {
      compute =
          gpu::computePolicyLevels(*context_, program.domain, tess::Spacing::kInteger,
                                   program.patch_count, nullptr, &device_policies_[k], levels);
    }
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      const uint32_t patch = program.patch_ids.empty() ? i : program.patch_ids[i];
      counts.culled[patch] = std::bit_cast<float>(run.tcs_levels[i][0]) <= 0.0f ? 1 : 0;
      if (!compute.empty() && compute[i] != run.tcs_levels[i]) ++counts.compute_mismatches;
    }
  }
  return counts;
}

CullingRun::HalfDecisions CullingRun::halfDecisions(lod::CullPolicy policy,
                                                    const view::View& view) const {
  const lod::CullPolicyHalves halves = lod::cullPolicyHalves(policy);
  auto decide = [&](lod::CullPolicy half) {
    return lod::cullDecisions(lod::cullParams(half, view, bounds_), bounds_);  // none: all 0
  };
  return {decide(halves.back_facing), decide(halves.outside_frustum)};
}

void CullingRun::countAgainstOracle(std::span<const uint8_t> culled,
                                    const PatchVisibility& visibility, const HalfDecisions& halves,
                                    CullingFrame* frame) {
  frame->oracle_measured = true;
  for (size_t p = 0; p < culled.size(); ++p) {
    const uint64_t pixels = visibility.visible_pixels[p];
    const bool cullable = visibility.ideally_cullable[p] != 0;
    if (pixels > 0) ++frame->visible_patches;
    if (cullable) ++frame->cullable_patches;
    if (culled[p] && pixels > 0) {
      ++frame->false_culls;
      frame->false_cull_pixels += pixels;
    }
    if (!culled[p] && cullable) ++frame->missed_culls;
    if (culled[p] && cullable) ++frame->culled_cullable_patches;
    if (visibility.back_facing[p] != 0) {
      ++frame->back_facing_patches;
      frame->culled_back_facing_patches += halves.back_facing[p];
    }
    if (visibility.outside_frustum[p] != 0) {
      ++frame->outside_frustum_patches;
      frame->culled_outside_frustum_patches += halves.outside_frustum[p];
    }
  }
}

std::vector<std::vector<CullingFrame>> CullingRun::frames(std::span<const lod::CullPolicy> policies,
                                                          std::span<const view::View> views) {
  prepareDevice();
  std::vector<std::vector<CullingFrame>> result(policies.size());
  uint64_t all_points = 0, all_triangles = 0;
  for (size_t p = 0; p < patch_points_.size(); ++p) {
    all_points += patch_points_[p];
    all_triangles += patch_triangles_[p];
  }
  for (size_t f = 0; f < views.size(); ++f) {
    std::optional<PatchVisibility> visibility;
    const view::View render_view = scaledView(views[f], options_.render_scale);
    if (oracle_ != nullptr) {
      try {
        visibility = oracle_->visibility(render_view);
      } catch (const gpu::GpuError& error) {
        gpu_skip_reason_ = std::string("oracle render failed: ") + error.what();
        oracle_.reset();
      }
    }
    for (size_t k = 0; k < policies.size(); ++k) {
      CullingFrame frame;
      frame.frame = uint32_t(f);
      frame.patches = patches_.patchCount();
      frame.tes_invocations_unculled = all_points;
      frame.triangles_unculled = all_triangles;
      const lod::CullParams params = lod::cullParams(policies[k], views[f], bounds_);
      const std::vector<uint8_t> culled = lod::cullDecisions(params, bounds_);
      for (size_t p = 0; p < culled.size(); ++p) {
        if (culled[p]) {
          ++frame.culled_patches;
        } else {
          frame.tes_invocations += patch_points_[p];
          frame.triangles += patch_triangles_[p];
        }
      }
      if (unculled_ && gpu_skip_reason_.empty()) {
        try {
          const DeviceCounts device =
              policies[k] == lod::CullPolicy::kNone
                  ? DeviceCounts{std::vector<uint8_t>(culled.size(), 0), unculled_->tes_invocations,
                                 unculled_->primitives_counted, unculled_->primitives}
                  : runOnDevice(&params);
          frame.gpu_measured = true;
          frame.gpu_tes_invocations = device.tes_invocations;
          frame.gpu_tes_invocations_unculled = unculled_->tes_invocations;
          frame.gpu_primitives_counted = device.primitives_counted;
          frame.gpu_primitives = device.primitives;
          frame.gpu_primitives_unculled = unculled_->primitives;
          frame.compute_measured = options_.compute;
          frame.compute_mismatches = device.compute_mismatches;
          for (size_t p = 0; p < culled.size(); ++p) {
            frame.gpu_culled_patches += device.culled[p];
            if (device.culled[p] != culled[p]) ++frame.twin_mismatches;
          }
        } catch (const gpu::GpuError& error) {
          gpu_skip_reason_ = std::string("device run failed: ") + error.what();
        }
      }
      if (visibility) {
        frame.render_width_px = render_view.viewport_width_px;
        frame.render_height_px = render_view.viewport_height_px;
        countAgainstOracle(culled, *visibility, halfDecisions(policies[k], views[f]), &frame);
      }
      result[k].push_back(frame);
    }
  }
  return result;
}

}  // namespace tb::measures
